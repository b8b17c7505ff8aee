#include "robot/lidar.h"

#include "robot/beam_noise.h"
#include "robot/sensor_rig.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <limits>

namespace revolve::robot {

Lidar::Lidar(const scene::EmbreeScene& scene, const io::SensorDescription& sensor) : scene_(scene), sensor_(sensor) {
  for (const double a : io::fanAngles(sensor.horizontal)) azimuths_.push_back({a, std::cos(a), std::sin(a)});
  for (const double e : sensor.elevations) elevations_.push_back({e, std::cos(e), std::sin(e)});
}

io::ScanTable Lidar::scan(std::span<const io::RobotPose> poses, int threads) const {
  io::ScanTable table;
  for (const Angle& a : azimuths_) table.azimuths.push_back(a.radians);
  for (const Angle& e : elevations_) table.elevations.push_back(e.radians);
  table.poses = poses.size();
  const std::size_t columns = azimuths_.size(), rings = elevations_.size(), perPose = columns * rings;
  table.beams.resize(poses.size() * perPose);
  std::vector<SensorFrame> frames;
  for (const io::RobotPose& pose : poses) frames.push_back(sensorFrame(sensor_.pose, pose));

  const float noReturn = std::numeric_limits<float>::infinity();
  const auto traceBeam = [&](std::size_t index) noexcept {
    const std::size_t pose = index / perPose, ring = (index % perPose) / columns, column = index % columns;
    const SensorFrame& frame = frames[pose];
    const Angle& a = azimuths_[column];
    const Angle& e = elevations_[ring];
    const Vec3d direction = frame.rotate({e.cosine * a.cosine, e.cosine * a.sine, e.sine});
    Ray ray;
    ray.origin = {float(frame.origin[0]), float(frame.origin[1]), float(frame.origin[2])};
    ray.direction = {float(direction[0]), float(direction[1]), float(direction[2])};
    io::BeamReturn& out = table.beams[index];
    out = {noReturn, 0, 0, 0, -1};
    const std::optional<scene::RangeHit> hit = scene_.nearest(ray);
    if (!hit) return;
    // t is in units of the float direction, whose length differs from 1 by its rounding.
    const double length = std::sqrt(double(ray.direction.x) * ray.direction.x + double(ray.direction.y) * ray.direction.y +
                                    double(ray.direction.z) * ray.direction.z);
    double range = double(hit->t) * length + sensor_.noiseMean;
    if (sensor_.noiseStddev > 0) range += sensor_.noiseStddev * standardNormal(sensor_.noiseSeed, pose, ring, column);
    if (sensor_.resolution > 0) range = std::round(range / sensor_.resolution) * sensor_.resolution;
    if (!(range >= sensor_.rangeMin && range <= sensor_.rangeMax)) return;  // ROS: not a return
    // The return where the measured range puts it along the beam, from the double-precision origin.
    out = {float(range), float(frame.origin[0] + range * direction[0]), float(frame.origin[1] + range * direction[1]),
           float(frame.origin[2] + range * direction[2]), std::int32_t(hit->object)};
  };

  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, table.beams.size(), 256), [&](const tbb::blocked_range<std::size_t>& block) {
      for (std::size_t i = block.begin(); i != block.end(); ++i) traceBeam(i);
    });
  });
  return table;
}

}  // namespace revolve::robot
