// revolve-bench: speed against error, side by side, on the same rays.
//
//   revolve-bench [speed-error | scaling | paper-table | pov | pov-scaling | scale] [--quick] [--json FILE] [--csv
//   FILE] [options]
//
// speed-error traces five smooth test shapes with MIBIT (each shell kind) at increasing profile
// resolution, with Embree triangle meshes over a grid of profile points x slices, with the linear
// scan and Kajiya's strip tree, with Embree's own linear cone curves and round Bézier curves along
// the axis (or the reason they cannot trace a shape), and with one analytic user primitive (the
// floor of any user geometry's cost); it measures every method's error against the smooth surface
// and its speed (Mrays/s, medians of interleaved repetitions), build time and memory, and matches
// MIBIT against the best mesh and Embree's curves at each error level. scaling measures throughput
// against the number of profile points, 16 to 32,768. With no subcommand both run. paper-table
// reproduces Baciu, Jia & Lam 2001's Tables 2 and 4 on the patio (paper_table.h); pov and
// pov-scaling measure revolve beside POV-Ray 3.7 (pov_compare.h). scale builds N distinct objects
// as exact surfaces or meshes: build time, memory, time to the first ray, throughput (scale/scale_suite.h).
#include "paper_table.h"
#include "pov_compare.h"
#include "povray.h"
#include "report.h"
#include "run_info.h"
#include "scale/scale_scene_file.h"
#include "scale/scale_suite.h"
#include "suites.h"

#include "cli/command_line.h"
#include "embree/embree_handles.h"
#include "embree/memory_check.h"
#include "shape/query_kernels.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <exception>
#include <sstream>

int main(int argc, char** argv) {
  using namespace revolve::bench;
  namespace app = revolve::app;
  CLI::App cli{"revolve-bench: MIBIT against Embree-tessellated meshes and the paper's baselines, speed against error"};
  cli.fallthrough();
  RunSettings settings;
  std::string jsonPath, csvPath, camera;
  std::vector<std::string> shapes;
  cli.add_flag("--quick", settings.quick, "small ladders, few rays, one repetition: a smoke test (under a minute)");
  cli.add_option("--json", jsonPath, "write every figure as JSON")->check(app::kNonEmpty);
  cli.add_option("--csv", csvPath, "write every figure as CSV, one row per method, resolution and timing mode")
      ->check(app::kNonEmpty);
  cli.add_option("--rays", settings.incoherentRays, "incoherent rays per shape")
      ->check(app::wholeNumberIn<std::size_t>(8, 100000000));
  cli.add_option("--camera", camera, "camera rays, WIDTHxHEIGHT (width a multiple of 4, height of 2)");
  cli.add_option("--repetitions", settings.repetitions, "timed repetitions of each measurement (median reported)")
      ->check(app::wholeNumberIn(1, 1000));
  cli.add_option("--min-time", settings.minSeconds, "seconds each repetition runs at least")
      ->check(CLI::Range(0.0001, 100.0));
  cli.add_option("--seed", settings.seed, "seed of the incoherent rays")
      ->check(app::wholeNumberIn<std::uint64_t>(0, UINT64_MAX));
  std::string isa;
  cli.add_option("--isa", isa,
                 "the instruction set of revolve's per-ray code and of Embree's kernels alike (Embree's "
                 "device config isa=...): sse2, avx2 or avx512 (default: the best this CPU runs, for each)")
      ->check(CLI::IsMember({"sse2", "avx2", "avx512"}));
  CLI::App* speedError = cli.add_subcommand("speed-error", "every method on the test shapes: speed, error, memory");
  speedError->add_option("--shapes", shapes, "only these shapes (sphere, torus, vase, goblet, bottle)")
      ->check(CLI::IsMember({"sphere", "torus", "vase", "goblet", "bottle"}));
  CLI::App* scaling = cli.add_subcommand("scaling", "throughput against profile points, 16 to 32,768, on the vase");

  PaperTableSettings paper;
  CLI::App* paperTable = cli.add_subcommand(
      "paper-table",
      "Baciu, Jia & Lam 2001's Tables 2 and 4 on the patio: KJ and MIBIT's shells, monotone split and range search");
  paperTable->add_option("--scene", paper.scene, "the scene")->check(app::kNonEmpty)->capture_default_str();
  paperTable->add_option("--size", paper.size, "image width and height")
      ->check(app::wholeNumberIn(1, 16384))
      ->capture_default_str();
  paperTable->add_option("--threads", paper.threads, "render threads")
      ->check(app::wholeNumberIn(1, 1024))
      ->capture_default_str();

  PovCompareSettings pov;
  CLI::App* povCompare =
      cli.add_subcommand("pov", "a scene rendered by revolve (whitted) and POV-Ray 3.7: trace times, image difference");
  povCompare->add_option("--scene", pov.scene, "the scene (point lights, uniform environment, no metal)")
      ->check(app::kNonEmpty)
      ->capture_default_str();
  povCompare->add_option("--width", pov.width, "image width (default: the scene's camera.width, else 640)")
      ->check(app::wholeNumberIn(1, 16384));
  povCompare->add_option("--height", pov.height, "image height (default: camera.height, else 480)")
      ->check(app::wholeNumberIn(1, 16384));
  povCompare->add_option("--depth", pov.depth, "ray levels (POV-Ray's max_trace_level)")
      ->check(app::wholeNumberIn(1, 64))
      ->capture_default_str();
  bool povNoShadows = false;
  povCompare->add_flag("--no-shadows", povNoShadows, "no shadow rays");
  povCompare
      ->add_option("--threads", pov.threads,
                   "the all-threads count (default: the machine's); one thread is always run too")
      ->check(app::wholeNumberIn(1, 1024));
  povCompare->add_option("--out", pov.outDirectory, "folder for the SDL and both images")
      ->check(app::kNonEmpty)
      ->capture_default_str();
  povCompare->add_option("--figure", pov.figure, "the side-by-side PNG (default: OUT/<scene>_side_by_side.png)")
      ->check(app::kNonEmpty);

  PovScalingSettings povScaling;
  CLI::App* povScale =
      cli.add_subcommand("pov-scaling", "one lathe at 16 to 32,767 points: revolve's and POV-Ray's trace times");
  povScale->add_option("--points", povScaling.points, "profile point counts (16 to 32767)")
      ->delimiter(',')
      ->check(app::wholeNumberIn(16, 32767));
  povScale->add_option("--size", povScaling.size, "image width and height")
      ->check(app::wholeNumberIn(1, 16384))
      ->capture_default_str();
  povScale->add_option("--threads", povScaling.threads, "threads of both (default: the machine's)")
      ->check(app::wholeNumberIn(1, 1024));
  povScale->add_option("--out", povScaling.outDirectory, "folder for the SDL and images")
      ->check(app::kNonEmpty)
      ->capture_default_str();
  ScaleSettings scale;
  std::string scaleGeometry = "revolve";
  CLI::App* scaleRun = cli.add_subcommand(
      "scale",
      "N distinct 64-point revolutions, exact or meshed at matched error: build, memory, first ray, throughput");
  scaleRun->add_option("--objects", scale.objects, "how many objects")
      ->check(app::wholeNumberIn<std::size_t>(1, 100000000))
      ->capture_default_str();
  scaleRun->add_option("--geometry", scaleGeometry, "revolve (exact) or mesh (Embree triangles)")
      ->check(CLI::IsMember({"revolve", "mesh"}))
      ->capture_default_str();
  std::string scaleBuild = "scene";
  scaleRun
      ->add_option("--build", scaleBuild,
                   "scene: through the tools' scene stack (a scene description, its records); library: each "
                   "object's revolve::Shape and placed revolve::Geometry in an Embree scene, as a C++ program would")
      ->check(CLI::IsMember({"scene", "library"}))
      ->capture_default_str();
  scaleRun->add_option("--lidar", scale.lidarAzimuths, "lidar azimuth steps (32 rings each)")
      ->check(app::wholeNumberIn(1, 1000000))
      ->capture_default_str();
  std::string writeScene;
  scaleRun
      ->add_option("--write-scene", writeScene,
                   "write the N objects as a scene file (DIR/scale-N.json and its two object-table CSVs) and stop")
      ->check(app::kNonEmpty);
  scaleRun->add_option("--scene", scale.sceneFile, "build this scene file's objects (read time reported apart)")
      ->check(app::kNonEmpty);
  cli.require_subcommand(0, 1);
  if (const std::optional<int> status = app::parseCommandLine(cli, argc, argv, "revolve-bench")) return *status;

  if (settings.quick) {
    if (cli.count("--rays") == 0) settings.incoherentRays = 4000;
    if (cli.count("--repetitions") == 0) settings.repetitions = 1;
    if (cli.count("--min-time") == 0) settings.minSeconds = 0.002;
    settings.cameraWidth = settings.cameraHeight = 64;
  }
  std::string commandLine;
  for (int i = 0; i < argc; ++i) commandLine += (i > 0 ? " " : "") + std::string(argv[i]);
  const std::string subject = "the benchmark's " + std::to_string(settings.incoherentRays) + " rays (--rays)" +
                              (camera.empty() ? std::string() : " and --camera " + camera);

  return app::runTool("revolve-bench", subject, [&] {
    if (!camera.empty()) {
      char x = 0;
      std::istringstream text(camera);
      if (!(text >> settings.cameraWidth >> x >> settings.cameraHeight) || x != 'x' || !text.eof() ||
          settings.cameraWidth <= 0 || settings.cameraWidth % 4 != 0 || settings.cameraHeight <= 0 ||
          settings.cameraHeight % 2 != 0) {
        throw std::runtime_error("--camera " + camera +
                                 ": expected WIDTHxHEIGHT, width a positive multiple of 4, height of 2");
      }
    }
    // Each shape holds its incoherent and camera rays with their reference hits, packets and
    // errors: 200 bytes a ray, measured (peak resident memory of `speed-error --shapes sphere
    // --quick` with --camera 1024x1024 less that with 256x256, 196 MB, over the 983,040 rays between).
    constexpr double kBytesPerRay = 200;
    const double rays = double(settings.incoherentRays) + double(settings.cameraWidth) * double(settings.cameraHeight);
    app::requireMemory(rays * kBytesPerRay, subject);
    revolve::io::OutputSet outputs;
    if (!jsonPath.empty()) outputs.add("--json", jsonPath);
    if (!csvPath.empty()) outputs.add("--csv", csvPath);

    // The POV-Ray and paper-table subcommands' own repetition defaults, unless --repetitions or
    // --quick says otherwise.
    const auto repetitionsFor = [&](int fallback) {
      return cli.count("--repetitions") > 0 ? settings.repetitions : settings.quick ? 1 : fallback;
    };
    const bool renderSuite = paperTable->parsed() || povCompare->parsed() || povScale->parsed();
    if (renderSuite &&
        (!csvPath.empty() || cli.count("--rays") > 0 || !camera.empty() || cli.count("--min-time") > 0)) {
      throw std::runtime_error("--csv, --rays, --camera and --min-time belong to speed-error and scaling");
    }
    const auto writeDocument = [&](const nlohmann::ordered_json& document) {
      if (jsonPath.empty()) return;
      outputs.stream(jsonPath).write(document.dump(2) + "\n");
      outputs.commit();
    };
    if (scaleRun->parsed()) {
      if (!csvPath.empty() || cli.count("--rays") > 0 || cli.count("--min-time") > 0)
        throw std::runtime_error("--csv, --rays and --min-time belong to speed-error and scaling");
      scale.mesh = scaleGeometry == "mesh";
      scale.library = scaleBuild == "library";
      scale.seed = settings.seed;
      if (!writeScene.empty()) {
        if (!scale.sceneFile.empty()) throw std::runtime_error("--write-scene and --scene: one at a time");
        if (scale.library)
          throw std::runtime_error("--write-scene writes a file and builds nothing: no --build library");
        const auto start = std::chrono::steady_clock::now();
        const std::string written = writeFamilyScene(ScaleFamily{.seed = scale.seed}, scale.objects, writeScene);
        std::printf("%s: %zu objects written in %.2f s\n", written.c_str(), scale.objects,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        return;
      }
      scale.repetitions = repetitionsFor(settings.repetitions);
      if (!camera.empty()) scale.cameraWidth = settings.cameraWidth, scale.cameraHeight = settings.cameraHeight;
      nlohmann::ordered_json document = runInfo(commandLine);
      document.update(runScale(scale));
      finishRunInfo(document);
      printScale(stdout, document);
      writeDocument(document);
      return;
    }
    if (paperTable->parsed()) {
      paper.repetitions = repetitionsFor(paper.repetitions);
      if (settings.quick && paperTable->count("--size") == 0) paper.size = 24;
      nlohmann::ordered_json document = runInfo(commandLine);
      const std::vector<PaperExample> examples = runPaperTable(paper);
      finishRunInfo(document);
      printPaperTable(stdout, paper, examples);
      document["quick"] = settings.quick;
      document.update(paperTableJson(paper, examples));
      writeDocument(document);
      return;
    }
    if (povCompare->parsed() || povScale->parsed()) {
      // Documented commands, not CI steps: without POV-Ray there is nothing to compare.
      const std::optional<std::string> povray = findPovray();
      if (!povray) {
        std::fprintf(stderr,
                     "revolve-bench: skipped: povray is not installed (Debian: apt-get install povray, "
                     "or scripts/install-deps.sh --test)\n");
        return;
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
      writeDocument(document);
      return;
    }
    std::string deviceConfig;
    if (!isa.empty()) {
      namespace detail = revolve::detail;
      const detail::Isa chosen = isa == "sse2"   ? detail::Isa::sse2
                                 : isa == "avx2" ? detail::Isa::avx2
                                                 : detail::Isa::avx512;
      if (!detail::cpuRuns(chosen)) throw std::runtime_error("--isa " + isa + ": this CPU does not run it");
      detail::limitIsa(chosen);
      deviceConfig = "isa=" + isa;
    }
    std::printf("instruction sets: revolve %s, Embree %s\n", revolve::detail::isaName(revolve::detail::chosenIsa()),
                deviceConfig.empty() ? "its default (the best it was built for)" : deviceConfig.c_str());
    const revolve::app::Device device = revolve::app::newDevice(deviceConfig.empty() ? nullptr : deviceConfig.c_str());
    RunResults results;
    results.settings = settings;
    const bool all = cli.get_subcommands().empty();
    if (all || speedError->parsed()) results.speedError = runSpeedError(device.get(), settings, shapes);
    if (all || scaling->parsed()) results.scaling = runScaling(device.get(), settings);
    printTables(stdout, results);
    if (!jsonPath.empty()) writeJson(outputs, jsonPath, results, commandLine);
    if (!csvPath.empty()) writeCsv(outputs, csvPath, results);
    outputs.commit();
  });
}
