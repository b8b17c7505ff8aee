// revolve-lidar: simulated laser range-finder scans of a scene file (the renderer's format), every
// surface of revolution traced exactly by revolve (or tessellated, for comparison). The sensor, the
// poses and the outputs are described in README.md, "Robot range-finding".
#include "common/counted.h"
#include "io/poses_file.h"
#include "io/scan_files.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "io/text_files.h"
#include "robot/lidar.h"
#include "robot/scan_plot.h"
#include "scene/embree_scene.h"

#include <CLI/CLI.hpp>
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace {

using namespace revolve;

struct Options {
  std::string scene, sensor, poses, output, plot, geometry = "mibit";
  std::uint32_t slices = 64;
  int threads = 0;
  std::optional<std::size_t> plotRing;
};

void run(const Options& options) {
  // Everything that can be checked before tracing is, so that a mistake costs nothing and leaves
  // no output behind.
  io::scanFormatFor(options.output);
  if (!options.plot.empty()) robot::checkPlotPath(options.plot);
  const io::SceneDescription description = io::readScene(options.scene);
  for (const io::SceneProfile& profile : description.profiles) {
    for (const std::string& warning : profile.warnings) std::fprintf(stderr, "revolve-lidar: warning: %s\n", warning.c_str());
  }
  const io::SensorDescription sensor = io::readSensor(options.sensor);
  if (options.plotRing && *options.plotRing >= sensor.elevations.size()) {
    throw std::runtime_error("--plot-ring " + std::to_string(*options.plotRing) + ": " + options.sensor + " has " +
                             app::counted(sensor.elevations.size(), "ring") + ", numbered from 0");
  }
  if (options.plotRing && options.plot.empty()) throw std::runtime_error("--plot-ring needs --plot");
  // Without poses, one: the robot at the origin, so the sensor's pose is its world pose.
  const std::vector<io::RobotPose> poses = options.poses.empty() ? std::vector<io::RobotPose>{io::RobotPose{}}
                                                                 : io::readPosesCsv(options.poses);
  io::checkWritable(options.output);

  scene::BuildSettings build;
  build.mesh = options.geometry == "mesh";
  build.slices = options.slices;
  const scene::EmbreeScene built(description, build);
  const robot::Lidar lidar(built, sensor);
  const auto start = std::chrono::steady_clock::now();
  const io::ScanTable scan = lidar.scan(poses, options.threads);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  io::writeScan(options.output, scan);
  if (!options.plot.empty()) robot::writeScanPlot(options.plot, {description, sensor, poses, scan, options.plotRing});

  const std::string geometry = build.mesh ? "mesh, " + std::to_string(build.slices) + " slices" : "exact";
  std::size_t returns = 0;
  for (const io::BeamReturn& beam : scan.beams) returns += std::isinf(beam.range) ? 0 : 1;
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  std::printf("revolve-lidar: %s x %s (%s x %s): %s; traced in %.3g s (%.4g scans/s, %s, %s geometry)\n",
              app::counted(poses.size(), "pose").c_str(), app::counted(lidar.beamsPerPose(), "beam").c_str(),
              app::counted(scan.rings(), "ring").c_str(), app::counted(scan.azimuths.size(), "azimuth").c_str(),
              app::counted(returns, "return").c_str(), seconds, seconds > 0 ? double(poses.size()) / seconds : 0.0,
              app::counted(std::size_t(threads), "thread").c_str(), geometry.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Simulated laser range-finder scans (ROS LaserScan semantics) of a scene of surfaces of revolution, "
               "traced exactly by revolve inside Embree."};
  app.add_option("scene", options.scene, "scene file (JSON, revolve-render's format)")->required();
  app.add_option("--sensor", options.sensor, "sensor file (JSON): pose, horizontal/vertical beams, range, noise")->required();
  app.add_option("--poses", options.poses, "robot poses (CSV, header x,y,z,yaw or x,y,yaw); default: one, at the origin");
  app.add_option("-o,--output", options.output, "scan to write: .csv (LaserScan-shaped table) or .pcd (ASCII PCD v0.7)")->required();
  app.add_option("--plot", options.plot, "also write a top-down PNG of the scan over the scene's footprint");
  app.add_option("--plot-ring", options.plotRing, "plot only this ring (0 = the lowest) of a 3-D scan");
  app.add_option("--geometry", options.geometry, "surfaces of revolution traced exactly (mibit) or as triangle meshes (mesh)")
      ->check(CLI::IsMember({"mibit", "mesh"}))
      ->capture_default_str();
  app.add_option("--slices", options.slices, "azimuthal steps of --geometry mesh")->check(CLI::Range(3u, 1u << 16))->capture_default_str();
  app.add_option("--threads", options.threads, "worker threads (default: all); the scan does not depend on it")->check(CLI::Range(1, 1024));
  // Argument errors too are one line, like every other error of the tool.
  app.failure_message([](const CLI::App*, const CLI::Error& error) { return std::string("revolve-lidar: ") + error.what() + " (see --help)\n"; });
  CLI11_PARSE(app, argc, argv);
  try {
    run(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "revolve-lidar: %s\n", error.what());
    return 1;
  }
  return 0;
}
