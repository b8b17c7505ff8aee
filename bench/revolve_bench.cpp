// revolve-bench: speed against error, side by side, on the same rays.
//
//   revolve-bench [speed-error | scaling | paper-table | pov | pov-scaling] [--quick] [--json FILE] [--csv FILE] [options]
//
// speed-error traces five smooth test shapes with MIBIT (each shell kind) at increasing profile
// resolution, with Embree triangle meshes over a grid of profile points x slices, with the linear
// scan and Kajiya's strip tree, and with one analytic user primitive (the floor of any user
// geometry's cost); it measures every method's error against the smooth surface and its speed
// (Mrays/s, medians of interleaved repetitions), build time and memory, and matches MIBIT against
// the best mesh at each error level. scaling measures throughput against the number of profile
// points, 16 to 32,768. With no subcommand both run. paper-table reproduces Baciu, Jia & Lam 2001's
// Tables 2 and 4 on the patio (paper_table.h); pov and pov-scaling measure revolve beside POV-Ray
// 3.7 (pov_compare.h).
#include "paper_table.h"
#include "pov_compare.h"
#include "povray.h"
#include "report.h"
#include "run_info.h"
#include "suites.h"

#include "io/text_files.h"

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

  PaperTableSettings paper;
  CLI::App* paperTable = app.add_subcommand(
      "paper-table", "Baciu, Jia & Lam 2001's Tables 2 and 4 on the patio: KJ and MIBIT's shells, monotone split and range search");
  paperTable->add_option("--scene", paper.scene, "the scene")->capture_default_str();
  paperTable->add_option("--size", paper.size, "image width and height")->check(CLI::Range(1, 16384))->capture_default_str();
  paperTable->add_option("--threads", paper.threads, "render threads")->check(CLI::Range(1, 1024))->capture_default_str();

  PovCompareSettings pov;
  CLI::App* povCompare = app.add_subcommand("pov", "a scene rendered by revolve (whitted) and POV-Ray 3.7: trace times, image difference");
  povCompare->add_option("--scene", pov.scene, "the scene (point lights, uniform environment, no metal)")->capture_default_str();
  povCompare->add_option("--width", pov.width, "image width (default: the scene's camera.width, else 640)")->check(CLI::Range(1, 16384));
  povCompare->add_option("--height", pov.height, "image height (default: camera.height, else 480)")->check(CLI::Range(1, 16384));
  povCompare->add_option("--depth", pov.depth, "ray levels (POV-Ray's max_trace_level)")->check(CLI::Range(1, 64))->capture_default_str();
  bool povNoShadows = false;
  povCompare->add_flag("--no-shadows", povNoShadows, "no shadow rays");
  povCompare->add_option("--threads", pov.threads, "the all-threads count (default: the machine's); one thread is always run too")
      ->check(CLI::Range(1, 1024));
  povCompare->add_option("--out", pov.outDirectory, "folder for the SDL and both images")->capture_default_str();
  povCompare->add_option("--figure", pov.figure, "the side-by-side PNG (default: OUT/<scene>_side_by_side.png)");

  PovScalingSettings povScaling;
  CLI::App* povScale = app.add_subcommand("pov-scaling", "one lathe at 16 to 32,767 points: revolve's and POV-Ray's trace times");
  povScale->add_option("--points", povScaling.points, "profile point counts (16 to 32767)")->delimiter(',');
  povScale->add_option("--size", povScaling.size, "image width and height")->check(CLI::Range(1, 16384))->capture_default_str();
  povScale->add_option("--threads", povScaling.threads, "threads of both (default: the machine's)")->check(CLI::Range(1, 1024));
  povScale->add_option("--out", povScaling.outDirectory, "folder for the SDL and images")->capture_default_str();
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

  // The new subcommands' own repetition defaults, unless --repetitions or --quick says otherwise.
  const auto repetitionsFor = [&](int fallback) {
    return app.count("--repetitions") > 0 ? settings.repetitions : settings.quick ? 1 : fallback;
  };
  const bool newSuite = paperTable->parsed() || povCompare->parsed() || povScale->parsed();
  if (newSuite && (!csvPath.empty() || app.count("--rays") > 0 || !camera.empty() || app.count("--min-time") > 0)) {
    std::fprintf(stderr, "revolve-bench: --csv, --rays, --camera and --min-time belong to speed-error and scaling\n");
    return 2;
  }
  try {
    if (newSuite && !jsonPath.empty()) revolve::io::checkWritable(jsonPath);  // before minutes of work
    if (paperTable->parsed()) {
      paper.repetitions = repetitionsFor(paper.repetitions);
      if (settings.quick && paperTable->count("--size") == 0) paper.size = 24;
      nlohmann::ordered_json document = runInfo(commandLine);
      const std::vector<PaperExample> examples = runPaperTable(paper);
      finishRunInfo(document);
      printPaperTable(stdout, paper, examples);
      if (!jsonPath.empty()) {
        document["quick"] = settings.quick;
        document.update(paperTableJson(paper, examples));
        writeJsonFile(jsonPath, document);
      }
      return 0;
    }
    if (povCompare->parsed() || povScale->parsed()) {
      // Documented commands, not CI steps: without POV-Ray there is nothing to compare.
      const std::optional<std::string> povray = findPovray();
      if (!povray) {
        std::fprintf(stderr, "revolve-bench: skipped: povray is not installed (Debian: apt-get install povray, "
                             "or scripts/install-deps.sh --test)\n");
        return 0;
      }
      nlohmann::ordered_json document = runInfo(commandLine);
      if (povCompare->parsed()) {
        pov.shadows = !povNoShadows;
        pov.repetitions = repetitionsFor(pov.repetitions);
        const PovComparison comparison = runPovComparison(*povray, pov);
        printPovComparison(stdout, pov, comparison);
        document.update(povComparisonJson(pov, comparison));
      } else {
        povScaling.repetitions = repetitionsFor(povScaling.repetitions);
        const std::vector<PovScalingPoint> points = runPovScaling(*povray, povScaling);
        printPovScaling(stdout, povScaling, points);
        document.update(povScalingJson(povScaling, points));
      }
      finishRunInfo(document);
      if (!jsonPath.empty()) writeJsonFile(jsonPath, document);
      return 0;
    }
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
