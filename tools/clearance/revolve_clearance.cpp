// revolve-clearance: the clearance of a vertical-cylinder robot (the GLBot simulator's collision test) at each
// pose of POSES.csv among a scene file's obstacles: exact for upright surfaces of revolution, a
// lower bound where said (README.md, "Robot range-finding").
#include "cli/command_line.h"
#include "cli/counted.h"
#include "io/clearance_file.h"
#include "io/csv_fields.h"
#include "io/output_set.h"
#include "io/poses_file.h"
#include "io/scene_file.h"
#include "io/text_files.h"
#include "robot/clearance_map.h"
#include "robot/robot_argument.h"
#include "scene/degenerate_objects.h"
#include "scene/picking.h"
#include "threads/thread_arenas.h"

#include <tbb/parallel_for.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace {

using namespace revolve;

struct Options {
  std::string scene, robot, poses, output, ground;
  int threads = 0;
};

void run(const Options& options) {
  std::string extension = std::filesystem::path(options.output).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".csv") {
    throw std::runtime_error(options.output + ": unsupported extension \"" + extension +
                             "\"; the clearance table is a .csv");
  }
  const robot::RobotDimensions shape = robot::parseRobotArgument(options.robot);
  double ground = -INFINITY;  // default: every surface is an obstacle
  if (!options.ground.empty()) {
    const std::optional<double> value = io::csv::parseNumber<double>(options.ground);
    if (!value || !std::isfinite(*value))
      throw std::runtime_error("--ground " + io::csv::quote(options.ground) + " is not a finite number");
    ground = *value;
  }
  const io::SceneDescription description = io::readScene(options.scene);
  for (const io::SceneProfile& profile : description.profiles) {
    for (const std::string& warning : profile.warnings)
      std::fprintf(stderr, "revolve-clearance: warning: %s\n", warning.c_str());
  }
  for (const std::string& warning : scene::degenerateObjectWarnings(description, false)) {
    std::fprintf(stderr, "revolve-clearance: warning: %s\n", warning.c_str());
  }
  const std::vector<io::RobotPose> poses = io::readPosesCsv(options.poses);
  robot::requireLevelPoses(poses, options.poses + ": pose");  // one message, exit 1 (app::runTool)
  io::OutputSet outputs;
  outputs.addInput("the scene file", options.scene);
  for (const io::SceneProfile& profile : description.profiles)
    outputs.addInput("a profile CSV of the scene", profile.csvFile);
  outputs.addInput("the poses file (--poses)", options.poses);
  outputs.add("-o", options.output);

  const robot::ClearanceMap map(description, ground);
  std::vector<robot::SceneClearance> results(poses.size());
  tbb::task_arena& arena = app::threadArena(options.threads > 0 ? options.threads : 0);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, poses.size(), [&](std::size_t i) {
      const io::RobotPose& p = poses[i];
      results[i] = map.query({p.x, p.y, p.z + shape.zMin, p.z + shape.zMax, shape.radius});
    });
  });

  std::vector<io::ClearanceRow> rows;
  std::size_t collisions = 0, bounds = 0, least = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const robot::SceneClearance& r = results[i];
    rows.push_back({r.clearance, r.collides, r.object, r.point[0], r.point[1], r.point[2]});
    collisions += r.collides ? 1 : 0;
    bounds += r.object >= 0 && !r.exact ? 1 : 0;
    if (r.clearance < results[least].clearance) least = i;
  }
  io::writeClearanceCsv(outputs.stream(options.output), rows);
  outputs.commit();
  const robot::SceneClearance& worst = results[least];
  std::printf("revolve-clearance: %s, %zu %s; least clearance %.6g at pose %zu",
              app::counted(poses.size(), "pose").c_str(), collisions, collisions == 1 ? "collides" : "collide",
              worst.clearance, least);
  if (worst.object >= 0) {
    const std::string name = scene::objectName(description, std::size_t(worst.object));
    std::printf(" (object %lld%s%s%s)", static_cast<long long>(worst.object), name.empty() ? "" : " \"", name.c_str(),
                name.empty() ? "" : "\"");
  }
  std::printf("; %s a lower bound (tilted objects or sloping quads nearest)\n",
              bounds == 1 ? "1 pose's clearance is" : (std::to_string(bounds) + " poses' clearances are").c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "The clearance of a vertical-cylinder robot to the obstacles of a scene of surfaces of revolution and quads, "
      "at each pose: signed distance, collision flag, nearest obstacle and its point."};
  app.add_option("scene", options.scene, "scene file (JSON, revolve-render's format)")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("--robot", options.robot,
                 "RADIUS,ZMIN,ZMAX: the robot's radius and the heights of its ends above each pose's z")
      ->required();
  app.add_option("--poses", options.poses, "robot poses (CSV, header x,y,z,yaw or x,y,yaw)")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("-o,--output", options.output, "clearance table to write (.csv)")->required()->check(app::kNonEmpty);
  app.add_option(
         "--ground", options.ground,
         "height of the ground the robot drives on: surfaces wholly at or below it are not obstacles (default: none)")
      ->check(CLI::Validator(
          [](std::string& value) {
            return value.empty() ? std::string("the value is empty; expected a height") : std::string();
          },
          "Z"));
  app.add_option("--threads", options.threads, "worker threads (default: all)")
      ->check(app::wholeNumberIn(1, app::kMaxThreads));
  if (const std::optional<int> status = app::parseCommandLine(app, argc, argv, "revolve-clearance")) return *status;
  return app::runTool("revolve-clearance", options.scene, [&] { run(options); });
}
