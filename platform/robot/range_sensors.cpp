#include "robot/range_sensors.h"

#include "robot/beam_noise.h"
#include "robot/sensor_rig.h"
#include "threads/thread_arenas.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace revolve::robot {
namespace {

// Balls holding a surface are padded by 2^-20 of their radius: far above the rounding of the few
// operations placing them, so that no surface reaching into a cone is passed over.
constexpr double kBallPadding = 1 + 0x1p-20;

double norm(const Vec3d& a) { return std::sqrt(app::dot(a, a)); }

// The ball about the mean of `points` through the farthest of them.
std::pair<Vec3d, double> ballAround(std::span<const Vec3d> points) {
  Vec3d centre{0, 0, 0};
  for (const Vec3d& p : points) centre = app::plus(centre, p);
  for (double& c : centre) c /= double(points.size());
  double radius = 0;
  for (const Vec3d& p : points) radius = std::max(radius, norm(app::minus(p, centre)));
  return {centre, radius * kBallPadding};
}

// The profile swept into `slices` steps about the axis, vertices on its circles (as
// revolve-lidar --geometry mesh tessellates it), placed in the world.
std::vector<std::array<Vec3d, 3>> tessellated(std::span<const Point2> profile, const app::Placement& placement,
                                              std::uint32_t slices) {
  std::vector<std::array<Vec3d, 3>> triangles;
  const auto vertex = [&](std::size_t i, std::uint32_t k) {
    const double phi = 2 * std::numbers::pi * double(k % slices) / double(slices);
    return placement.toWorld({profile[i].r * std::cos(phi), profile[i].r * std::sin(phi), profile[i].z});
  };
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    for (std::uint32_t k = 0; k < slices; ++k) {
      const Vec3d a = vertex(i, k), b = vertex(i, k + 1), c = vertex(i + 1, k + 1), d = vertex(i + 1, k);
      if (profile[i].r > 0) triangles.push_back({a, b, c});
      if (profile[i + 1].r > 0) triangles.push_back({a, c, d});
    }
  }
  return triangles;
}

}  // namespace

RangeSensors::RangeSensors(const io::SceneDescription& scene, io::RangeSensorsDescription sensors, Settings settings)
    : sensors_(std::move(sensors)) {
  io::drawPolylines(scene);
  for (const io::SceneProfile& profile : scene.profiles) {
    const auto points = profile.polyline().points();
    profiles_.emplace_back(points.begin(), points.end());
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const io::SceneObject& object = scene.objects[i];
    const app::Placement placement(object.transform);
    const std::vector<Point2>& profile = profiles_[object.profile];
    if (settings.mesh) {
      Triangles mesh{tessellated(profile, placement, settings.slices), {}, 0, std::int64_t(i)};
      std::vector<Vec3d> corners;
      for (const auto& triangle : mesh.triangles) corners.insert(corners.end(), triangle.begin(), triangle.end());
      std::tie(mesh.centre, mesh.radius) = ballAround(corners);
      meshes_.push_back(std::move(mesh));
      continue;
    }
    if (placement.similarity() == 0) {
      const auto& s = object.transform.scale;
      throw std::invalid_argument(
          scene.file + ": objects[" + std::to_string(i) + "]" + (object.name.empty() ? "" : " (" + object.name + ")") +
          " is scaled by [" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ", " + std::to_string(s[2]) +
          "]: a range sensor's exact reading needs an object scaled equally along its three axes (angles kept); "
          "the tessellated geometry takes any scale");
    }
    double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
    for (const Point2 p : profile) rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
    const double scale = placement.similarity();
    revolutions_.push_back({object.profile, placement, scale, placement.toWorld({0, 0, 0.5 * (zLow + zHigh)}),
                            std::hypot(rMax, 0.5 * (zHigh - zLow)) * scale * kBallPadding, std::int64_t(i)});
  }
  for (std::size_t q = 0; q < scene.quads.size(); ++q) {
    const auto& c = scene.quads[q].corners;
    Triangles quad{{{c[0], c[1], c[2]}, {c[0], c[2], c[3]}}, {}, 0, std::int64_t(scene.objects.size() + q)};
    std::tie(quad.centre, quad.radius) = ballAround(c);
    meshes_.push_back(std::move(quad));
  }
}

RangeReading RangeSensors::read(std::size_t index, const io::RobotPose& pose, std::uint64_t poseNumber) const {
  const io::RangeSensorDescription& sensor = sensors_.sensors[index];
  const SensorFrame frame = sensorFrame(sensor.pose, pose);
  const Vec3d axis = frame.rotate({1, 0, 0});  // ROS: a range sensor looks along its +X
  const app::SensorCone cone(frame.origin, axis, 0.5 * sensor.fieldOfView);

  app::ConeNearest best;
  std::int64_t object = -1;
  // In index order, replacing only when strictly nearer: ties go to the lowest object index.
  for (const Revolution& revolution : revolutions_) {
    if (!cone.mayReach(revolution.centre, revolution.radius, best.distance)) continue;
    const app::SensorCone local(revolution.placement.toObject(frame.origin), revolution.placement.inverse().apply(axis),
                                cone.halfAngle());
    // Searched within the best so far, in object units; only a point the search found counts (the
    // limit scaled back need not equal the best: rounding).
    const double limit = best.distance / revolution.scale;
    app::ConeNearest nearest;
    nearest.distance = limit;
    app::nearestOnRevolution(profiles_[revolution.profile], local, nearest);
    if (!(nearest.distance < limit)) continue;
    const double distance = nearest.distance * revolution.scale;
    if (distance < best.distance) {
      best.distance = distance;
      best.point = revolution.placement.toWorld(nearest.point);
      object = revolution.object;
    }
  }
  for (const Triangles& mesh : meshes_) {
    if (!cone.mayReach(mesh.centre, mesh.radius, best.distance)) continue;
    const double before = best.distance;
    for (const auto& triangle : mesh.triangles) app::nearestOnTriangle(triangle, cone, best);
    if (best.distance < before) object = mesh.object;
  }

  RangeReading reading;
  if (!std::isfinite(best.distance)) return reading;
  double range = best.distance + sensor.noiseMean;
  if (sensor.noiseStddev > 0) range += sensor.noiseStddev * standardNormal(sensor.noiseSeed, poseNumber, index, 0);
  if (!(range >= sensor.minRange && range <= sensor.maxRange)) return reading;
  const Vec3d toPoint = app::minus(best.point, frame.origin);
  const double length = norm(toPoint);
  // The apex on the surface: the direction is the axis.
  const Vec3d direction =
      length > 0 ? Vec3d{toPoint[0] / length, toPoint[1] / length, toPoint[2] / length} : cone.axis();
  reading.range = range;
  reading.point = {frame.origin[0] + range * direction[0], frame.origin[1] + range * direction[1],
                   frame.origin[2] + range * direction[2]};
  reading.object = object;
  return reading;
}

void RangeSensors::readAll(std::span<const io::RobotPose> poses, int threads,
                           const std::function<void(std::uint64_t, std::span<const RangeReading>)>& sink,
                           std::uint64_t firstPose) const {
  const std::size_t count = sensorCount();
  // Blocks of about 4096 readings: enough to keep the threads busy, small whatever the path.
  const std::size_t posesPerBlock = std::max<std::size_t>(1, 4096 / std::max<std::size_t>(count, 1));
  std::vector<RangeReading> block;
  tbb::task_arena& arena = app::threadArena(threads > 0 ? threads : 0);
  for (std::size_t start = 0; start < poses.size(); start += posesPerBlock) {
    const std::size_t end = std::min(poses.size(), start + posesPerBlock);
    block.assign((end - start) * count, RangeReading{});
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, block.size(), [&](std::size_t i) {
        const std::size_t pose = start + i / count, sensor = i % count;
        block[i] = read(sensor, poses[pose], firstPose + pose);
      });
    });
    sink(firstPose + start, block);
  }
}

}  // namespace revolve::robot
