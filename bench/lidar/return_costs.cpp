#include "lidar/return_costs.h"

#include "robot/lidar.h"
#include "robot/sensor_rig.h"
#include "threads/thread_arenas.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>

namespace revolve::bench {

namespace {

// Seconds per call of `pass`, timed over whole calls for at least a quarter of a second.
double secondsPerPass(const std::function<void()>& pass) {
  const auto start = std::chrono::steady_clock::now();
  int passes = 0;
  double elapsed = 0;
  do {
    pass();
    ++passes;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < 0.25);
  return elapsed / passes;
}

// Every beam ray of every pose, in the Lidar's order, from the sensor at rest.
std::vector<Ray> beamRays(const io::SensorDescription& sensor, const std::vector<io::RobotPose>& poses) {
  const io::ScanLayout layout = io::scanLayout(sensor, poses.size());
  std::vector<Ray> rays;
  rays.reserve(std::size_t(layout.pointCount()));
  for (const io::RobotPose& pose : poses) {
    const robot::SensorFrame frame = robot::sensorFrame(sensor.pose, pose);
    for (std::size_t ring = 0; ring < layout.rings(); ++ring) {
      for (std::size_t column = 0; column < layout.columns(); ++column) {
        const app::Vec3d d =
            frame.rotate(robot::beamDirection(layout.azimuths[column], layout.elevation(ring, column)));
        Ray ray;
        ray.origin = {float(frame.origin[0]), float(frame.origin[1]), float(frame.origin[2])};
        ray.direction = {float(d[0]), float(d[1]), float(d[2])};
        rays.push_back(ray);
      }
    }
  }
  return rays;
}

}  // namespace

nlohmann::ordered_json measureReturnCosts(const scene::EmbreeScene& scene, const io::SensorDescription& sensor,
                                          const std::vector<io::RobotPose>& poses, int repeats) {
  const std::vector<Ray> rays = beamRays(sensor, poses);
  std::vector<float> distances(rays.size());
  constexpr std::size_t kPacket = scene::EmbreeScene::kPacketRays;
  const int threads = tbb::info::default_concurrency();

  io::SensorDescription moving = sensor;
  moving.rotationRate = 10;
  std::vector<io::RobotPose> timed = poses;
  for (std::size_t i = 0; i < timed.size(); ++i) timed[i].time = 0.1 * double(i);
  const auto footprint = [&](int subrays) {
    io::SensorDescription s = sensor;
    s.divergence = 0.003;
    s.subrays = subrays;
    s.returns = io::ReturnMode::all;
    s.maxReturns = 2;
    return s;
  };
  const io::SensorDescription four = footprint(4), sixteen = footprint(16);

  struct Configuration {
    std::string name;
    int subrays;
    std::function<void()> pass;
  };
  std::vector<Configuration> configurations{
      {"rays only", 1,
       [&] {
         app::threadArena(threads).execute([&] {
           tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size() / kPacket + 1, 32),
                             [&](const tbb::blocked_range<std::size_t>& r) {
                               std::array<std::optional<scene::RangeHit>, kPacket> hits;
                               for (std::size_t p = r.begin(); p != r.end(); ++p) {
                                 const std::size_t first = p * kPacket;
                                 if (first >= rays.size()) break;
                                 const std::size_t n = std::min(kPacket, rays.size() - first);
                                 scene.nearest(std::span<const Ray>(rays.data() + first, n), std::span(hits.data(), n));
                                 for (std::size_t k = 0; k < n; ++k) distances[first + k] = hits[k] ? hits[k]->t : -1;
                               }
                             });
         });
       }},
      {"scan at rest", 1, [&] { robot::Lidar(scene, sensor).scan(poses, threads); }},
      {"scan moving", 1, [&] { robot::Lidar(scene, moving).scan(timed, threads); }},
      {"subrays 4", 4, [&] { robot::Lidar(scene, four).scan(poses, threads); }},
      {"subrays 16", 16, [&] { robot::Lidar(scene, sixteen).scan(poses, threads); }},
  };
  std::map<std::string, std::vector<double>> seconds;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    for (const Configuration& c : configurations) seconds[c.name].push_back(secondsPerPass(c.pass));
  }
  const auto median = [&](const std::string& name) {
    std::vector<double> t = seconds[name];
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  };
  const double floor = median("rays only"), rest = median("scan at rest");
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Configuration& c : configurations) {
    const double m = median(c.name);
    const double subrays = double(rays.size()) * c.subrays;
    out.push_back({{"configuration", c.name},
                   {"subrays", c.subrays},
                   {"threads", threads},
                   {"seconds", seconds[c.name]},
                   {"median_seconds", m},
                   {"ratio_to_rays_only", m / floor},
                   {"ratio_to_scan_at_rest", m / rest},
                   {"ns_per_subray", m / subrays * 1e9}});
    std::printf("%-13s %2d sub-ray%s: %.4g s a pass, %.3g x rays only, %.3g x the scan at rest, %.3g ns a sub-ray\n",
                c.name.c_str(), c.subrays, c.subrays == 1 ? " " : "s", m, m / floor, m / rest, m / subrays * 1e9);
  }
  return out;
}

}  // namespace revolve::bench
