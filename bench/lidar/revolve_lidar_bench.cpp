// revolve-lidar-bench: the figures of README.md, "Robot range-finding", from one reproducible run.
//
//   build/bin/revolve-lidar-bench scenes/robot_world.json --poses examples/robot/path.csv
//       --out bench/results/robot/lidar_bench.json
//
// Two sensors, noise and resolution off (geometry only): a 2-D scanner of 1,080 beams over 270
// degrees (a Hokuyo UTM-30LX's layout) and a 3-D one of 16 x 1,800 beams (a Velodyne VLP-16's).
//  1. Range error: every beam of every pose traced with exact surfaces (revolve) and with meshes
//     of each --slices count, against ReferenceRanges (a double-precision brute force written
//     apart from revolve and Embree) along the same float rays. Per class of object (names
//     starting "pole", and names containing "barrel"): over the beams whose reference hit is such
//     an object and whose traced hit is the same object, the mean and largest |range - reference|
//     and how many are over 1 cm off; and how many of those beams hit something else or nothing.
//  2. Throughput: scans per second over all poses, on one thread and on all, for revolve and for
//     the mesh of equal mean range accuracy (the fewest slices whose mean error on both classes and
//     both scans is at most revolve's; the most accurate mesh tried when none is), and the 64-slice
//     mesh, each configuration timed --repeats
//     times (whole passes over the poses for at least 0.25 s each), the configurations interleaved
//     within each repeat; the median is reported.
//  3. The cost of the returns' fields and of beam footprints on the 3-D sensor with exact
//     surfaces: the scan (ranges, intensity, time) at rest and moving, and with 4 and 16 sub-rays
//     a beam, against tracing its rays alone (lidar/return_costs.h).
#include "cli/command_line.h"
#include "io/output_set.h"
#include "io/poses_file.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "io/text_files.h"
#include "lidar/reference_ranges.h"
#include "lidar/return_costs.h"
#include "robot/lidar.h"
#include "robot/sensor_rig.h"
#include "run_info.h"
#include "scene/embree_scene.h"

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>

namespace {

using namespace revolve;
using Json = nlohmann::ordered_json;

io::SensorDescription planarScanner() {
  io::SensorDescription s;
  s.file = "2-D: 1,080 beams over 270 degrees";
  s.pose.position = {0.2, 0, 0.3};
  s.horizontal = {1080, -0.75 * std::numbers::pi, 0.75 * std::numbers::pi};
  s.elevations = {0.0};
  s.rangeMin = 0.1;
  s.rangeMax = 30;
  return s;
}

io::SensorDescription spinningScanner() {
  io::SensorDescription s;
  s.file = "3-D: 16 x 1,800 beams, +-15 degrees";
  s.pose.position = {0, 0, 0.7};
  s.horizontal = {1800, -std::numbers::pi, std::numbers::pi * (1 - 2.0 / 1800)};
  s.elevations = io::fanAngles({16, -15 * std::numbers::pi / 180, 15 * std::numbers::pi / 180});
  s.planar = false;
  s.rangeMin = 0.4;
  s.rangeMax = 100;
  return s;
}

enum class ObjectClass { pole, barrel, other };

ObjectClass classOf(const io::SceneDescription& scene, std::int64_t object) {
  if (object < 0 || std::size_t(object) >= scene.objects.size()) return ObjectClass::other;
  const std::string& name = scene.objects[std::size_t(object)].name;
  if (name.rfind("pole", 0) == 0) return ObjectClass::pole;
  if (name.find("barrel") != std::string::npos) return ObjectClass::barrel;
  return ObjectClass::other;
}

// The reference answer of every beam of every pose, in the scan's order, along the very ray the
// lidar traces (origin and direction rounded to float as it rounds them): what is measured is then
// the geometry's error, not the rounding of the beam, which moves a grazing return a long way.
std::vector<std::optional<bench::ReferenceHit>> referenceScan(const bench::ReferenceRanges& reference,
                                                              const io::SensorDescription& s,
                                                              const std::vector<io::RobotPose>& poses) {
  const std::vector<double> azimuths = io::fanAngles(s.horizontal);
  const std::size_t perPose = azimuths.size() * s.elevations.size();
  std::vector<std::optional<bench::ReferenceHit>> hits(poses.size() * perPose);
  tbb::parallel_for(std::size_t{0}, hits.size(), [&](std::size_t index) {
    const std::size_t pose = index / perPose, ring = (index % perPose) / azimuths.size(),
                      column = index % azimuths.size();
    const robot::SensorFrame frame = robot::sensorFrame(s.pose, poses[pose]);
    const robot::Vec3d direction = frame.rotate(robot::beamDirection(azimuths[column], s.elevations[ring]));
    bench::Vec3d o, d;
    for (int k = 0; k < 3; ++k) o[k] = double(float(frame.origin[k])), d[k] = double(float(direction[k]));
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& c : d) c /= length;
    hits[index] = reference.trace(o, d);
  });
  return hits;
}

struct ClassError {
  std::size_t beams = 0,
              otherHit = 0;        // beams whose reference hit is the class; of them, traced to another object or none
  std::size_t overCentimetre = 0;  // same object, but more than 1 cm off (a mesh's ray leaking through an edge)
  double sum = 0, max = 0;
  double mean() const { return beams > otherHit ? sum / double(beams - otherHit) : 0.0; }
};

std::map<ObjectClass, ClassError> rangeErrors(const io::SceneDescription& scene, const io::ScanTable& scan,
                                              const std::vector<std::optional<bench::ReferenceHit>>& reference) {
  std::map<ObjectClass, ClassError> errors;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (!reference[i]) continue;
    const ObjectClass kind = classOf(scene, reference[i]->object);
    if (kind == ObjectClass::other) continue;
    ClassError& e = errors[kind];
    ++e.beams;
    const io::BeamReturn& beam = scan.points[i];
    if (std::isinf(beam.range) || beam.object != reference[i]->object) {
      ++e.otherHit;
      continue;
    }
    const double error = std::abs(double(beam.range) - reference[i]->distance);
    e.sum += error;
    e.max = std::max(e.max, error);
    e.overCentimetre += error > 0.01 ? 1 : 0;
  }
  return errors;
}

Json errorJson(const ClassError& e) {
  return {{"beams", e.beams},
          {"other_hit", e.otherHit},
          {"mean_m", e.mean()},
          {"max_m", e.max},
          {"over_1cm", e.overCentimetre}};
}

struct Options {
  std::string scene, poses, output;
  std::vector<std::uint32_t> slices{8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192};
  int repeats = 5;
};

void run(const Options& options, const std::string& commandLine) {
  const io::SceneDescription scene = io::readScene(options.scene);
  const std::vector<io::RobotPose> poses = io::readPosesCsv(options.poses);
  io::OutputSet outputs;
  outputs.addInput("the scene file", options.scene);
  for (const io::SceneProfile& profile : scene.profiles)
    outputs.addInput("a profile CSV of the scene", profile.csvFile);
  outputs.addInput("the poses file (--poses)", options.poses);
  outputs.add("--out", options.output);
  const bench::ReferenceRanges reference(scene);
  const std::vector<io::SensorDescription> sensors{planarScanner(), spinningScanner()};
  std::vector<std::vector<std::optional<bench::ReferenceHit>>> truth;
  for (const io::SensorDescription& s : sensors) truth.push_back(referenceScan(reference, s, poses));

  // 1. Range error of each geometry.
  struct Geometry {
    std::string name;
    std::uint32_t slices;  // 0: exact
    std::unique_ptr<scene::EmbreeScene> built;
  };
  std::vector<Geometry> geometries;
  geometries.push_back({"revolve", 0, std::make_unique<scene::EmbreeScene>(scene, scene::BuildSettings{})});
  for (const std::uint32_t k : options.slices) {
    scene::BuildSettings mesh;
    mesh.mesh = true;
    mesh.slices = k;
    geometries.push_back({"mesh " + std::to_string(k), k, std::make_unique<scene::EmbreeScene>(scene, mesh)});
  }
  Json errors = Json::array();
  std::vector<double> worstMean(geometries.size(), 0);  // over both sensors and both classes
  for (std::size_t g = 0; g < geometries.size(); ++g) {
    Json entry{{"geometry", geometries[g].name},
               {"slices", geometries[g].slices},
               {"embree_bytes", geometries[g].built->embreeBytes()},
               {"build_seconds", geometries[g].built->buildSeconds()}};
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      const io::ScanTable scan = robot::Lidar(*geometries[g].built, sensors[s]).scan(poses);
      const auto byClass = rangeErrors(scene, scan, truth[s]);
      Json perSensor;
      for (const auto& [kind, e] : byClass) {
        perSensor[kind == ObjectClass::pole ? "poles" : "barrels"] = errorJson(e);
        worstMean[g] = std::max(worstMean[g], e.mean());
      }
      entry[s == 0 ? "scan_2d" : "scan_3d"] = perSensor;
    }
    std::printf("%-10s mean error (worst of poles/barrels, 2-D/3-D) %.3g m\n", geometries[g].name.c_str(),
                worstMean[g]);
    errors.push_back(entry);
  }
  // The fewest slices whose worst mean error is at most revolve's; when none is, the most accurate
  // mesh tried.
  std::size_t equal = 1;
  bool matched = false;
  for (std::size_t g = 1; g < geometries.size(); ++g) {
    if (worstMean[g] <= worstMean[0]) {
      equal = g, matched = true;
      break;
    }
    if (worstMean[g] < worstMean[equal]) equal = g;
  }
  const std::string rule = matched ? "the fewest slices with a mean error at most revolve's"
                                   : "no mesh tried is as accurate as revolve: the most accurate mesh tried";
  std::printf("mesh of equal mean accuracy: %s (%s)\n", geometries[equal].name.c_str(), rule.c_str());

  // 2. Throughput, revolve and that mesh (and the 64-slice mesh, a common default), interleaved.
  std::vector<std::size_t> timed{0, equal};
  for (std::size_t g = 1; g < geometries.size(); ++g) {
    if (geometries[g].slices == 64 && g != equal) timed.push_back(g);
  }
  const int all = tbb::info::default_concurrency();
  std::map<std::tuple<std::size_t, std::size_t, int>, std::vector<double>> seconds;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    for (const std::size_t g : timed) {
      for (std::size_t s = 0; s < sensors.size(); ++s) {
        for (const int threads : {1, all}) {
          // Whole passes over the poses until a quarter of a second has gone: seconds per pass.
          const robot::Lidar lidar(*geometries[g].built, sensors[s]);
          const auto start = std::chrono::steady_clock::now();
          int passes = 0;
          double elapsed = 0;
          do {
            const io::ScanTable scan = lidar.scan(poses, threads);
            ++passes;
            elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          } while (elapsed < 0.25);
          seconds[{g, s, threads}].push_back(elapsed / passes);
        }
      }
    }
  }
  Json throughput = Json::array();
  for (const std::size_t g : timed) {
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      for (const int threads : {1, all}) {
        std::vector<double> times = seconds[{g, s, threads}];
        std::sort(times.begin(), times.end());
        const double median = times[times.size() / 2];
        const double scansPerSecond = double(poses.size()) / median;
        const double beams =
            double(poses.size()) * double(sensors[s].horizontal.samples) * double(sensors[s].elevations.size());
        throughput.push_back({{"geometry", geometries[g].name},
                              {"slices", geometries[g].slices},
                              {"sensor", s == 0 ? "2d" : "3d"},
                              {"threads", threads},
                              {"seconds", times},
                              {"median_seconds", median},
                              {"scans_per_second", scansPerSecond},
                              {"mrays_per_second", beams / median * 1e-6}});
        std::printf("%-10s %s %d thread%s: %.4g scans/s (%.3g Mrays/s)\n", geometries[g].name.c_str(),
                    s == 0 ? "2-D" : "3-D", threads, threads == 1 ? "" : "s", scansPerSecond, beams / median * 1e-6);
      }
    }
  }

  // 3. What intensity, time, motion and footprints cost.
  const Json returnCosts = bench::measureReturnCosts(*geometries[0].built, sensors[1], poses, options.repeats);

  Json sensorJson = Json::array();
  for (const io::SensorDescription& s : sensors) {
    sensorJson.push_back({{"name", s.file},
                          {"azimuths", s.horizontal.samples},
                          {"min_angle", s.horizontal.minAngle},
                          {"max_angle", s.horizontal.maxAngle},
                          {"elevations", s.elevations},
                          {"position", s.pose.position}});
  }
  const Json result{{"command", commandLine},
                    {"date", bench::today()},
                    {"machine", {{"cpu", bench::cpuModel()}, {"threads", all}}},
                    {"scene", options.scene},
                    {"poses", poses.size()},
                    {"sensors", sensorJson},
                    {"range_error", errors},
                    {"equal_accuracy_mesh", geometries[equal].name},
                    {"equal_accuracy_rule", rule},
                    {"throughput", throughput},
                    {"return_costs", returnCosts}};
  const std::string text = result.dump(1) + "\n";
  outputs.write(options.output, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
  outputs.commit();
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Range error and scan throughput of revolve's exact surfaces against tessellated meshes (README, Robot "
      "range-finding)."};
  app.add_option("scene", options.scene, "scene file (JSON)")->required()->check(app::kNonEmpty);
  app.add_option("--poses", options.poses, "robot poses (CSV)")->required()->check(app::kNonEmpty);
  app.add_option("--out", options.output, "results (JSON)")->required()->check(app::kNonEmpty);
  app.add_option("--slices", options.slices, "mesh slice counts to measure")
      ->delimiter(',')
      ->check(app::wholeNumberIn<std::uint32_t>(3, 1u << 16))
      ->capture_default_str();
  app.add_option("--repeats", options.repeats, "timing repeats (the median is reported)")
      ->check(app::wholeNumberIn(1, 1000))
      ->capture_default_str();
  if (const std::optional<int> status = app::parseCommandLine(app, argc, argv, "revolve-lidar-bench")) return *status;
  std::string commandLine;
  for (int i = 0; i < argc; ++i) commandLine += (i > 0 ? " " : "") + std::string(argv[i]);
  return app::runTool("revolve-lidar-bench", options.scene, [&] { run(options, commandLine); });
}
