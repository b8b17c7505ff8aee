// revolve-bench: speed against error, side by side, on the same rays.
//
//   revolve-bench [speed-error | scaling] [--quick] [--json FILE] [--csv FILE] [options]
//
// speed-error traces five smooth test shapes with MIBIT (each shell kind) at increasing profile
// resolution, with Embree triangle meshes over a grid of profile points x slices, with the linear
// scan and Kajiya's strip tree, with Embree's own linear cone curves and round Bézier curves along
// the axis (or the reason they cannot trace a shape), and with one analytic user primitive (the
// floor of any user geometry's cost); it measures every method's error against the smooth surface
// and its speed (Mrays/s, medians of interleaved repetitions), build time and memory, and matches
// MIBIT against the best mesh and Embree's curves at each error level. scaling measures throughput
// against the number of profile points, 16 to 32,768. With no subcommand both run.
#include "report.h"
#include "suites.h"

#include "../demo/common/embree_handles.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <sstream>

int main(int argc, char** argv) {
  using namespace revolve::bench;
  CLI::App app{"revolve-bench: MIBIT against Embree-tessellated meshes and the paper's baselines, speed against error"};
  app.fallthrough();
  RunSettings settings;
  std::string jsonPath, csvPath, camera;
  std::vector<std::string> shapes;
  app.add_flag("--quick", settings.quick, "small ladders, few rays, one repetition: a smoke test (under a minute)");
  app.add_option("--json", jsonPath, "write every figure as JSON");
  app.add_option("--csv", csvPath, "write every figure as CSV, one row per method, resolution and timing mode");
  app.add_option("--rays", settings.incoherentRays, "incoherent rays per shape")->check(CLI::Range(8, 100000000));
  app.add_option("--camera", camera, "camera rays, WIDTHxHEIGHT (width a multiple of 4, height of 2)");
  app.add_option("--repetitions", settings.repetitions, "timed repetitions of each measurement (median reported)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--min-time", settings.minSeconds, "seconds each repetition runs at least")->check(CLI::Range(0.0001, 100.0));
  app.add_option("--seed", settings.seed, "seed of the incoherent rays");
  CLI::App* speedError = app.add_subcommand("speed-error", "every method on the test shapes: speed, error, memory");
  speedError->add_option("--shapes", shapes, "only these shapes (sphere, torus, vase, goblet, bottle)")
      ->check(CLI::IsMember({"sphere", "torus", "vase", "goblet", "bottle"}));
  CLI::App* scaling = app.add_subcommand("scaling", "throughput against profile points, 16 to 32,768, on the vase");
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);

  if (settings.quick) {
    if (app.count("--rays") == 0) settings.incoherentRays = 4000;
    if (app.count("--repetitions") == 0) settings.repetitions = 1;
    if (app.count("--min-time") == 0) settings.minSeconds = 0.002;
    settings.cameraWidth = settings.cameraHeight = 64;
  }
  if (!camera.empty()) {
    char x = 0;
    std::istringstream text(camera);
    if (!(text >> settings.cameraWidth >> x >> settings.cameraHeight) || x != 'x' || !text.eof() ||
        settings.cameraWidth <= 0 || settings.cameraWidth % 4 != 0 || settings.cameraHeight <= 0 ||
        settings.cameraHeight % 2 != 0) {
      std::fprintf(stderr, "--camera %s: expected WIDTHxHEIGHT, width a positive multiple of 4, height of 2\n",
                   camera.c_str());
      return 2;
    }
  }
  std::string commandLine;
  for (int i = 0; i < argc; ++i) commandLine += (i > 0 ? " " : "") + std::string(argv[i]);

  try {
    const revolve::app::Device device = revolve::app::newDevice();
    RunResults results;
    results.settings = settings;
    const bool all = app.get_subcommands().empty();
    if (all || speedError->parsed()) results.speedError = runSpeedError(device.get(), settings, shapes);
    if (all || scaling->parsed()) results.scaling = runScaling(device.get(), settings);
    printTables(stdout, results);
    if (!jsonPath.empty()) writeJson(jsonPath, results, commandLine);
    if (!csvPath.empty()) writeCsv(csvPath, results);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "revolve-bench: %s\n", error.what());
    return 1;
  }
  return 0;
}
