#include "robot/lidar.h"
#include "threads/thread_arenas.h"

#include "robot/beam_noise.h"
#include "robot/sensor_motion.h"
#include "robot/sensor_rig.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

namespace revolve::robot {

Lidar::Lidar(const scene::EmbreeScene& scene, const io::SensorDescription& sensor) : scene_(scene), sensor_(sensor) {
  for (const double a : io::fanAngles(sensor.horizontal)) azimuths_.push_back({a, std::cos(a), std::sin(a)});
  for (const double e : sensor.elevations) elevations_.push_back({e, std::cos(e), std::sin(e)});
}

io::ScanLayout Lidar::layout(std::size_t poses) const {
  io::ScanLayout layout;
  for (const Angle& a : azimuths_) layout.azimuths.push_back(a.radians);
  for (const Angle& e : elevations_) layout.elevations.push_back(e.radians);
  layout.poses = poses;
  return layout;
}

void Lidar::scan(std::span<const io::RobotPose> poses, const Sink& sink, int threads, double* tracingSeconds,
                 std::uint64_t firstPose, std::size_t sweeps) const {
  sweeps = std::min(sweeps, poses.size());
  const std::size_t columns = azimuths_.size(), rings = elevations_.size(), perPose = columns * rings;
  const std::uint64_t total = std::uint64_t(sweeps) * perPose;
  const float noReturn = std::numeric_limits<float>::infinity();
  const SensorMotion motion(sensor_.pose, poses);
  // A beam's own frame only where the sensor moves during a sweep.
  const bool moving = motion.moving() && sensor_.rotationRate > 0;

  // Beam `index` (its number in the scan): its ray from the frame of its pose, and its direction
  // in double precision (where the return is placed).
  const auto beamRay = [&](std::uint64_t index, const SensorFrame& frame, Vec3d& direction) noexcept {
    const std::size_t ring = std::size_t(index % perPose) / columns, column = std::size_t(index % columns);
    const Angle& a = azimuths_[column];
    const Angle& e = elevations_[ring];
    direction = frame.rotate({e.cosine * a.cosine, e.cosine * a.sine, e.sine});
    Ray ray;
    ray.origin = {float(frame.origin[0]), float(frame.origin[1]), float(frame.origin[2])};
    ray.direction = {float(direction[0]), float(direction[1]), float(direction[2])};
    return ray;
  };
  // The beam's return from its nearest hit.
  const auto beamReturn = [&](std::uint64_t index, const SensorFrame& frame, const Ray& ray, const Vec3d& direction,
                              const std::optional<scene::RangeHit>& hit) noexcept -> io::BeamReturn {
    const std::uint64_t pose = index / perPose;
    const std::size_t ring = std::size_t(index % perPose) / columns, column = std::size_t(index % columns);
    const float time = float(sensor_.columnTime(column));
    if (!hit) return {noReturn, 0, 0, 0, -1, 0, time};
    // t is in units of the float direction, whose length differs from 1 by its rounding.
    const double length =
        std::sqrt(double(ray.direction.x) * ray.direction.x + double(ray.direction.y) * ray.direction.y +
                  double(ray.direction.z) * ray.direction.z);
    double range = double(hit->t) * length + sensor_.noiseMean;
    if (sensor_.noiseStddev > 0)
      range += sensor_.noiseStddev * standardNormal(sensor_.noiseSeed, firstPose + pose, ring, column);
    if (sensor_.resolution > 0) range = std::round(range / sensor_.resolution) * sensor_.resolution;
    if (!(range >= sensor_.rangeMin && range <= sensor_.rangeMax))
      return {noReturn, 0, 0, 0, -1, 0, time};  // ROS: not a return
    // Intensity: a Lambertian surface of reflectivity r returns r |cos theta| of the beam's light
    // (theta between the beam and the surface's normal: the exact surface's, a facet's for a mesh),
    // received over a solid angle falling as 1 / range^2. The traced range, not the noisy one: the
    // range noise models the range measurement only.
    const double traced = double(hit->t) * length;
    const double cosine = std::abs(double(hit->normal.x) * direction[0] + double(hit->normal.y) * direction[1] +
                                   double(hit->normal.z) * direction[2]);
    double intensity = double(hit->reflectivity) * cosine / (traced * traced);
    if (sensor_.intensityNoiseStddev > 0) {
      const double z = standardNormal(sensor_.intensityNoiseSeed, firstPose + pose, ring, column);
      intensity = std::max(0.0, intensity * (1 + sensor_.intensityNoiseStddev * z));
    }
    // The return where the measured range puts it along the beam, from the double-precision origin.
    return {float(range),
            float(frame.origin[0] + range * direction[0]),
            float(frame.origin[1] + range * direction[1]),
            float(frame.origin[2] + range * direction[2]),
            std::int32_t(hit->object),
            float(intensity),
            time};
  };
  // Beams [first, first + count) of one ring of one pose, count <= kPacketRays, traced as one packet,
  // from the pose's frame or, while the sensor moves, each from its own: `columnFrames` (the
  // frames of their columns, in order) or, without it, made here.
  constexpr std::size_t kPacket = scene::EmbreeScene::kPacketRays;
  const auto tracePacket = [&](std::uint64_t first, std::size_t count, const SensorFrame& poseFrame,
                               const SensorFrame* columnFrames, io::BeamReturn* out) noexcept {
    std::array<Ray, kPacket> rays;
    std::array<Vec3d, kPacket> directions;
    std::array<std::optional<scene::RangeHit>, kPacket> hits;
    std::array<SensorFrame, kPacket> ownFrames;
    if (moving && columnFrames == nullptr) {
      const std::size_t pose = std::size_t(first / perPose);
      for (std::size_t k = 0; k < count; ++k)
        ownFrames[k] = motion.at(pose, sensor_.columnTime(std::size_t((first + k) % columns)));
      columnFrames = ownFrames.data();
    }
    const auto frame = [&](std::size_t k) -> const SensorFrame& { return moving ? columnFrames[k] : poseFrame; };
    for (std::size_t k = 0; k < count; ++k) rays[k] = beamRay(first + k, frame(k), directions[k]);
    scene_.nearest(std::span<const Ray>(rays.data(), count), std::span(hits.data(), count));
    for (std::size_t k = 0; k < count; ++k) out[k] = beamReturn(first + k, frame(k), rays[k], directions[k], hits[k]);
  };
  // Beams [first, first + count) into `out`, on the arena's threads.
  double tracing = 0;
  const auto traceBlock = [&](std::uint64_t first, std::size_t count, std::vector<io::BeamReturn>& out) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t firstPose = first / perPose, lastPose = (first + count - 1) / perPose;
    std::vector<SensorFrame> frames;
    for (std::uint64_t p = firstPose; p <= lastPose; ++p) frames.push_back(motion.atPose(std::size_t(p)));
    // A moving sensor fires every ring of a column from one frame: made once per (pose, column)
    // where that table is no larger than the block (sensors of several rings), else per beam.
    std::vector<SensorFrame> columnFrames;
    const std::uint64_t tableSize = (lastPose - firstPose + 1) * columns;
    if (moving && rings > 1 && tableSize <= count) {
      columnFrames.resize(std::size_t(tableSize));
      tbb::parallel_for(std::size_t{0}, columnFrames.size(), [&](std::size_t i) {
        columnFrames[i] = motion.at(std::size_t(firstPose + i / columns), sensor_.columnTime(i % columns));
      });
    }
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, 256), [&](const tbb::blocked_range<std::size_t>& range) {
          // Neighbouring beams of a ring in packets, a packet ending where its ring does.
          for (std::size_t i = range.begin(); i != range.end();) {
            const std::uint64_t beam = first + i;
            const std::size_t ringLeft = columns - std::size_t(beam % columns);
            const std::size_t count = std::min({kPacket, ringLeft, range.end() - i});
            const std::uint64_t pose = beam / perPose;
            const SensorFrame* own = columnFrames.empty()
                                         ? nullptr
                                         : &columnFrames[std::size_t((pose - firstPose) * columns + beam % columns)];
            tracePacket(beam, count, frames[pose - firstPose], own, out.data() + i);
            i += count;
          }
        });
    tracing += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();  // one block at a time
  };
  if (total == 0) return;

  tbb::task_arena& arena = app::threadArena(threads > 0 ? threads : 0);
  arena.execute([&] {
    std::vector<io::BeamReturn> ready(std::min<std::uint64_t>(kBlockBeams, total)), next(ready.size());
    std::uint64_t readyFirst = 0;
    std::size_t readyCount = ready.size();
    traceBlock(readyFirst, readyCount, ready);
    for (;;) {
      const std::uint64_t nextFirst = readyFirst + readyCount;
      const std::size_t nextCount = std::size_t(std::min<std::uint64_t>(kBlockBeams, total - nextFirst));
      tbb::task_group tracing;
      if (nextCount > 0) tracing.run([&] { traceBlock(nextFirst, nextCount, next); });
      try {
        sink(readyFirst, std::span<const io::BeamReturn>(ready.data(), readyCount));
      } catch (...) {
        tracing.wait();
        throw;
      }
      tracing.wait();
      if (nextCount == 0) break;
      std::swap(ready, next);
      readyFirst = nextFirst;
      readyCount = nextCount;
    }
  });
  if (tracingSeconds != nullptr) *tracingSeconds = tracing;
}

io::ScanTable Lidar::scan(std::span<const io::RobotPose> poses, int threads) const {
  io::ScanTable table;
  static_cast<io::ScanLayout&>(table) = layout(poses.size());
  table.beams.resize(table.beamCount());
  scan(
      poses,
      [&](std::uint64_t first, std::span<const io::BeamReturn> beams) {
        std::copy(beams.begin(), beams.end(), table.beams.begin() + first);
      },
      threads);
  return table;
}

}  // namespace revolve::robot
