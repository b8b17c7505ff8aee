// revolve-lidar: simulated laser range-finder scans of a scene file (the renderer's format), every
// surface of revolution traced exactly by revolve (or tessellated, for comparison). The sensor, the
// poses and the outputs are described in README.md, "Robot range-finding".
#include "cli/command_line.h"
#include "cli/counted.h"
#include "io/output_set.h"
#include "io/poses_file.h"
#include "io/range_readings.h"
#include "io/scan_files.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "robot/lidar.h"
#include "robot/range_sensors.h"
#include "robot/scan_plot.h"
#include "scene/degenerate_objects.h"
#include "scene/embree_scene.h"
#include "threads/thread_arenas.h"

#include <tbb/info.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace {

using namespace revolve;

struct Options {
  std::string scene, sensor, poses, output, plot, geometry = "mibit", pcdData = "ascii";
  std::uint32_t slices = 64;
  int threads = 0;
  std::optional<std::size_t> plotRing;
};

void warnAboutScene(const io::SceneDescription& description) {
  for (const io::SceneProfile& profile : description.profiles) {
    for (const std::string& warning : profile.warnings)
      std::fprintf(stderr, "revolve-lidar: warning: %s\n", warning.c_str());
  }
  for (const std::string& warning : scene::degenerateObjectWarnings(description, false)) {
    std::fprintf(stderr, "revolve-lidar: warning: %s\n", warning.c_str());
  }
}

// The run's inputs, which no output may overwrite.
void addInputs(io::OutputSet& outputs, const Options& options, const io::SceneDescription& description) {
  outputs.addInput("the scene file", options.scene);
  for (const io::SceneProfile& profile : description.profiles)
    outputs.addInput("a profile CSV of the scene", profile.csvFile);
  outputs.addInput("the sensor file (--sensor)", options.sensor);
  outputs.addInput("the poses file (--poses)", options.poses);
}

// Range sensors (sonar, infrared): their readings at every pose as a CSV table.
void runRange(const Options& options, bool pcdDataGiven) {
  const std::string& out = options.output;
  if (out.size() < 4 || out.compare(out.size() - 4, 4, ".csv") != 0) {
    throw std::runtime_error(out + ": " + options.sensor +
                             " describes range sensors, whose readings are a CSV table (" + io::kRangeTableHeader +
                             "): name the output .csv");
  }
  if (pcdDataGiven) throw std::runtime_error("--pcd-data applies to a lidar's .pcd scans, not to range sensors");
  if (!options.plot.empty() || options.plotRing)
    throw std::runtime_error(
        "--plot draws a lidar's scan; range sensors' readings are a table (bench/python/plot_sonar_ring.py shows how "
        "to "
        "draw them)");
  const io::SceneDescription description = io::readScene(options.scene);
  warnAboutScene(description);
  io::RangeSensorsDescription sensors = io::readRangeSensors(options.sensor);
  const std::vector<io::RobotPose> poses =
      options.poses.empty() ? std::vector<io::RobotPose>{io::RobotPose{}} : io::readPosesCsv(options.poses);
  io::OutputSet outputs;
  addInputs(outputs, options, description);
  outputs.add("-o", out);

  robot::RangeSensors::Settings settings;
  settings.mesh = options.geometry == "mesh";
  settings.slices = options.slices;
  const std::size_t count = sensors.sensors.size();
  const robot::RangeSensors ranging(description, std::move(sensors), settings);
  io::RangeTableWriter writer(outputs.stream(out));
  std::size_t readings = 0;
  const auto start = std::chrono::steady_clock::now();
  ranging.readAll(poses, options.threads, [&](std::uint64_t first, std::span<const io::RangeReading> block) {
    writer.write(first, count, block);
    for (const io::RangeReading& r : block) readings += std::isinf(r.range) ? 0 : 1;
  });
  outputs.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  std::printf("revolve-lidar: %s x %s: %s in %.3g s (%s, %s geometry)\n", app::counted(poses.size(), "pose").c_str(),
              app::counted(count, "range sensor").c_str(), app::counted(readings, "reading").c_str(), seconds,
              app::counted(std::size_t(threads), "thread").c_str(),
              settings.mesh ? ("mesh, " + std::to_string(settings.slices) + " slices").c_str() : "exact");
}

void run(const Options& options, bool pcdDataGiven) {
  if (io::readSensorType(options.sensor) == io::SensorType::range) return runRange(options, pcdDataGiven);
  // Everything that can be checked before tracing is, so that a mistake costs nothing and leaves
  // no output behind.
  const io::ScanFormat format = io::scanFormatFor(options.output);
  if (pcdDataGiven && format != io::ScanFormat::pcd) {
    throw std::runtime_error(options.output + ": --pcd-data applies to .pcd outputs, and this one is a CSV table");
  }
  if (!options.plot.empty()) robot::checkPlotPath(options.plot);
  const io::SceneDescription description = io::readScene(options.scene);
  warnAboutScene(description);
  const io::SensorDescription sensor = io::readSensor(options.sensor);
  const io::ScanLayout sweep = io::scanLayout(sensor, 1);
  if (options.plotRing && *options.plotRing >= sweep.rings()) {
    throw std::runtime_error("--plot-ring " + std::to_string(*options.plotRing) + ": " + options.sensor + " has " +
                             app::counted(sweep.rings(), "ring") + ", numbered from 0" +
                             (sweep.pattern ? " (a beam pattern is one ring)" : ""));
  }
  if (options.plotRing && options.plot.empty()) throw std::runtime_error("--plot-ring needs --plot");
  // Without poses, one: the robot at the origin, so the sensor's pose is its world pose.
  const std::vector<io::RobotPose> poses =
      options.poses.empty() ? std::vector<io::RobotPose>{io::RobotPose{}} : io::readPosesCsv(options.poses);
  const std::uint64_t perPose = sweep.pointsPerPose();
  if (std::uint64_t(poses.size()) * perPose > io::kMaxScanPoints) {
    throw std::runtime_error(
        (options.poses.empty() ? options.sensor : options.poses) + ": " + std::to_string(poses.size()) + " poses x " +
        std::to_string(perPose) + " points (" + options.sensor + ") = " + std::to_string(poses.size() * perPose) +
        " points; a scan holds at most 2^31 - 1 (PCD's point count, as PCL indexes it): split the poses");
  }
  io::OutputSet outputs;
  addInputs(outputs, options, description);
  outputs.add("-o", options.output);
  if (!options.plot.empty()) outputs.add("--plot", options.plot);

  scene::BuildSettings build;
  build.mesh = options.geometry == "mesh";
  build.slices = options.slices;
  const scene::EmbreeScene built(description, build);
  const robot::Lidar lidar(built, sensor);
  const io::ScanLayout layout = lidar.layout(poses.size());
  io::ScanWriter writer(outputs.stream(options.output), format,
                        options.pcdData == "binary" ? io::PcdData::binary : io::PcdData::ascii, layout);
  std::optional<robot::ScanPlot> plot;
  if (!options.plot.empty()) plot.emplace(description, sensor, poses, layout, options.plotRing);

  std::size_t returns = 0;
  double tracing = 0;
  const auto start = std::chrono::steady_clock::now();
  lidar.scan(
      poses,
      [&](std::uint64_t first, std::span<const io::BeamReturn> beams) {
        writer.write(first, beams);
        if (plot) plot->add(first, beams);
        for (const io::BeamReturn& beam : beams) returns += std::isinf(beam.range) ? 0 : 1;
      },
      options.threads, &tracing);
  if (plot) plot->finish(outputs.stream(options.plot), options.plot);
  outputs.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (built.refusedRays() > 0) {
    std::fprintf(stderr,
                 "revolve-lidar: warning: %s: %llu rays (beams, or their sub-rays) fell outside Embree's range and "
                 "were not traced\n",
                 options.scene.c_str(), static_cast<unsigned long long>(built.refusedRays()));
  }

  const std::string geometry = build.mesh ? "mesh, " + std::to_string(build.slices) + " slices" : "exact";
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  const std::string shape =
      layout.pattern ? "a beam pattern"
                     : app::counted(layout.rings(), "ring") + " x " + app::counted(layout.columns(), "azimuth");
  std::printf(
      "revolve-lidar: %s x %s (%s%s): %s; traced in %.3g s (%.4g scans/s, %s, %s geometry); %.3g s with writing\n",
      app::counted(poses.size(), "pose").c_str(), app::counted(lidar.beamsPerPose(), "beam").c_str(), shape.c_str(),
      layout.layers > 1 ? (", up to " + app::counted(layout.layers, "return") + " a beam").c_str() : "",
      app::counted(returns, "return").c_str(), tracing, tracing > 0 ? double(poses.size()) / tracing : 0.0,
      app::counted(std::size_t(threads), "thread").c_str(), geometry.c_str(), seconds);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Simulated laser range-finder scans (ROS LaserScan semantics) of a scene of surfaces of revolution, "
      "traced exactly by revolve inside Embree; or, for a sensor file of \"type\": \"range\", the readings of "
      "sonar and infrared cones (ROS Range: the nearest surface inside each cone, exact)."};
  app.add_option("scene", options.scene, "scene file (JSON, revolve-render's format)")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("--sensor", options.sensor,
                 "sensor file (JSON): a lidar (pose, horizontal/vertical beams, range, noise) or range sensors "
                 "(\"type\": \"range\": pose, field_of_view, min_range, max_range, radiation_type, noise)")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("--poses", options.poses,
                 "robot poses (CSV, header x,y,z,yaw or x,y,yaw); default: one, at the origin")
      ->check(app::kNonEmpty);
  app.add_option("-o,--output", options.output,
                 "scan to write: .csv (LaserScan-shaped table) or .pcd (PCD v0.7); range sensors: .csv (pose,sensor,"
                 "range,x,y,z,object)")
      ->required()
      ->check(app::kNonEmpty);
  CLI::Option* pcdData = app.add_option("--pcd-data", options.pcdData,
                                        "a .pcd output's DATA: ascii (text) or binary (PCL's packed layout)")
                             ->check(CLI::IsMember({"ascii", "binary"}))
                             ->capture_default_str();
  app.add_option("--plot", options.plot, "also write a top-down PNG of the scan over the scene's footprint")
      ->check(app::kNonEmpty);
  app.add_option("--plot-ring", options.plotRing, "plot only this ring (0 = the lowest) of a 3-D scan")
      ->check(app::wholeNumberIn<std::size_t>(0, 1u << 16));
  app.add_option("--geometry", options.geometry,
                 "surfaces of revolution traced exactly (mibit) or as triangle meshes (mesh)")
      ->check(CLI::IsMember({"mibit", "mesh"}))
      ->capture_default_str();
  app.add_option("--slices", options.slices, "azimuthal steps of --geometry mesh")
      ->check(app::wholeNumberIn<std::uint32_t>(3, 1u << 16))
      ->capture_default_str();
  app.add_option("--threads", options.threads, "worker threads (default: all); the scan does not depend on it")
      ->check(app::wholeNumberIn(1, app::kMaxThreads));
  if (const std::optional<int> status = app::parseCommandLine(app, argc, argv, "revolve-lidar")) return *status;
  return app::runTool("revolve-lidar", options.scene, [&] { run(options, pcdData->count() > 0); });
}
