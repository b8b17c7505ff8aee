#include "robot/lidar.h"
#include "threads/thread_arenas.h"

#include "random/counter_hash.h"
#include "robot/beam_noise.h"
#include "robot/beam_returns.h"
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

Lidar::Lidar(const scene::EmbreeScene& scene, const io::SensorDescription& sensor)
    : scene_(scene), sensor_(sensor), layout_(io::scanLayout(sensor, 1)) {
  for (const double a : layout_.azimuths) azimuths_.push_back({std::cos(a), std::sin(a)});
  for (const double e : layout_.elevations) elevations_.push_back({std::cos(e), std::sin(e)});
  footprint_ = footprintOffsets(sensor.divergence, sensor.subrays);
}

io::ScanLayout Lidar::layout(std::size_t poses) const {
  io::ScanLayout layout = layout_;
  layout.poses = poses;
  return layout;
}

namespace {

// The noise stream of a beam's `echo`-th return (in range order among all its echoes): the
// sensor's seed for the first, so that a beam of one return has the noise it always had; a seed
// of its own for each further one.
std::uint64_t echoSeed(std::uint64_t seed, std::size_t echo) noexcept {
  return echo == 0 ? seed : app::mix64(seed ^ app::mix64(0x9e3779b97f4a7c15ULL + echo));
}

// The intensity noise's seed: a stream apart from the range noise's even where the two seeds are
// equal (both default to 0), so that a return's range and intensity errors are independent.
std::uint64_t intensitySeed(std::uint64_t seed) noexcept { return app::mix64(seed ^ 0x696e74656e736974ULL); }

}  // namespace

void Lidar::scan(std::span<const io::RobotPose> poses, const Sink& sink, int threads, double* tracingSeconds,
                 std::uint64_t firstPose, std::size_t sweeps) const {
  sweeps = std::min(sweeps, poses.size());
  const std::size_t columns = layout_.columns(), rings = layout_.rings(), perPose = columns * rings;
  const std::size_t layers = layout_.layers;
  const std::uint64_t total = std::uint64_t(sweeps) * perPose;
  const float noReturn = std::numeric_limits<float>::infinity();
  const SensorMotion motion(sensor_.pose, poses);
  // A beam's own frame only where the sensor moves during a sweep.
  const bool moving = motion.moving() && sensor_.fansOutInTime();
  const int subrays = sensor_.subrays;
  // Returns nearer each other than the sensor can tell apart are one.
  const double separation = std::max(sensor_.returnSeparation, sensor_.resolution);
  // Beams traced by one call of traceBeams: a packet's worth of sub-rays at least, no more than
  // kMaxRays of them (its stack arrays).
  constexpr std::size_t kPacket = scene::EmbreeScene::kPacketRays;
  constexpr std::size_t kMaxRays = std::size_t(io::kMaxSubrays);
  static_assert(kMaxRays >= kPacket);
  const std::size_t beamsPerCall = std::clamp<std::size_t>(kMaxRays / std::size_t(subrays), 1, kPacket);

  // The number of point (beam, layer) in the scan (io::ScanLayout).
  const auto pointOf = [&](std::uint64_t beam, std::size_t layer) noexcept {
    return (beam / perPose * layers + layer) * perPose + beam % perPose;
  };
  // A return measured from its traced echo (the `echo`-th of its beam in range order): noise,
  // rounding to the resolution and the range gate (ROS: outside it, not a return), then the
  // intensity's noise. False: no return.
  const auto measure = [&](Echo& e, std::size_t echo, std::uint64_t pose, std::size_t ring,
                           std::size_t column) noexcept {
    double range = e.range + sensor_.noiseMean;
    if (sensor_.noiseStddev > 0)
      range += sensor_.noiseStddev * standardNormal(echoSeed(sensor_.noiseSeed, echo), firstPose + pose, ring, column);
    if (sensor_.resolution > 0) range = std::round(range / sensor_.resolution) * sensor_.resolution;
    if (!(range >= sensor_.rangeMin && range <= sensor_.rangeMax)) return false;
    if (sensor_.intensityNoiseStddev > 0) {
      const double z =
          standardNormal(echoSeed(intensitySeed(sensor_.intensityNoiseSeed), echo), firstPose + pose, ring, column);
      e.intensity = std::max(0.0, e.intensity * (1 + sensor_.intensityNoiseStddev * z));
    }
    e.range = range;
    return true;
  };
  // A sub-ray's hit as an echo: the range along the unit direction `d` (t is in units of the ray's
  // float direction, whose length differs from 1 by its rounding) and its intensity. A Lambertian
  // surface of reflectivity r returns r |cos theta| of the light (theta between the ray and the
  // surface's normal: the exact surface's, a facet's for a mesh), received over a solid angle
  // falling as 1 / range^2; the traced range, not the noisy one: the range noise models the range
  // measurement only.
  const auto echoOf = [](const Ray& ray, const Vec3d& d, const scene::RangeHit& hit) noexcept -> Echo {
    const double length =
        std::sqrt(double(ray.direction.x) * ray.direction.x + double(ray.direction.y) * ray.direction.y +
                  double(ray.direction.z) * ray.direction.z);
    const double traced = double(hit.t) * length;
    const double cosine =
        std::abs(double(hit.normal.x) * d[0] + double(hit.normal.y) * d[1] + double(hit.normal.z) * d[2]);
    return {traced, double(hit.reflectivity) * cosine / (traced * traced), std::int32_t(hit.object)};
  };

  // Beams [first, first + count) of one ring of one pose, count <= beamsPerCall, their sub-rays
  // traced in packets, from the pose's frame or, while the sensor moves, each from its own:
  // `columnFrames` (the frames of their columns, in order) or, without it, made here. Their
  // points go to out[pointOf(beam, layer) - outFirst]. kSingleRay: beams of one ray each (the
  // common case: no footprint, so no grouping), whose arrays hold a packet.
  const auto traceBeams = [&]<bool kSingleRay>(std::uint64_t first, std::size_t count, const SensorFrame& poseFrame,
                                               const SensorFrame* columnFrames, io::BeamReturn* out,
                                               std::uint64_t outFirst) noexcept {
    constexpr std::size_t kRays = kSingleRay ? kPacket : kMaxRays;
    std::array<Ray, kRays> rays;
    std::array<Vec3d, kSingleRay ? 1 : kRays> directions;  // sub-rays' (a single ray's is its axis)
    std::array<std::optional<scene::RangeHit>, kRays> hits;
    std::array<SensorFrame, kPacket> ownFrames;
    std::array<Vec3d, kPacket> axes;
    // The call's beams share their pose and ring: their columns run on from the first's.
    const std::uint64_t pose = first / perPose;
    const std::size_t within = std::size_t(first % perPose), ring = within / columns, column0 = within % columns;
    const std::uint64_t rowPoint = pose * layers * perPose + ring * columns + column0 - outFirst;
    if (moving && columnFrames == nullptr) {
      for (std::size_t k = 0; k < count; ++k)
        ownFrames[k] = motion.at(std::size_t(pose), sensor_.columnTime(column0 + k));
      columnFrames = ownFrames.data();
    }
    const auto frame = [&](std::size_t k) -> const SensorFrame& { return moving ? columnFrames[k] : poseFrame; };
    const std::size_t rayCount = count * std::size_t(subrays);
    for (std::size_t k = 0; k < count; ++k) {
      const SensorFrame& f = frame(k);
      const Angle& a = azimuths_[column0 + k];
      const Angle& e = elevations_[layout_.pattern ? column0 + k : ring];
      const BeamAxes beam = BeamAxes::at(a.cosine, a.sine, e.cosine, e.sine);
      axes[k] = f.rotate(beam.axis);
      const Vec3 origin{float(f.origin[0]), float(f.origin[1]), float(f.origin[2])};
      for (std::size_t j = 0; j < std::size_t(subrays); ++j) {
        const std::size_t q = k * std::size_t(subrays) + j;
        const Vec3d& d = kSingleRay ? axes[k] : (directions[q] = f.rotate(beam.direction(footprint_[j])));
        rays[q].origin = origin;
        rays[q].direction = {float(d[0]), float(d[1]), float(d[2])};
      }
    }
    for (std::size_t q = 0; q < rayCount; q += kPacket) {
      const std::size_t n = std::min(kPacket, rayCount - q);
      scene_.nearest(std::span<const Ray>(rays.data() + q, n), std::span(hits.data() + q, n));
    }
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t column = column0 + k;
      const float time = float(sensor_.columnTime(column));
      // The beam's returns, measured, nearest first.
      std::array<Echo, kSingleRay ? 1 : kRays> measured;
      std::size_t returned = 0;
      if constexpr (kSingleRay) {
        if (hits[k]) {
          measured[0] = echoOf(rays[k], axes[k], *hits[k]);
          returned = measure(measured[0], 0, pose, ring, column) ? 1 : 0;
        }
      } else {
        std::array<Echo, kRays> echoes;
        std::size_t hitCount = 0;
        for (std::size_t j = 0; j < std::size_t(subrays); ++j) {
          const std::size_t q = k * std::size_t(subrays) + j;
          if (hits[q]) echoes[hitCount++] = echoOf(rays[q], directions[q], *hits[q]);
        }
        const std::size_t groups =
            groupEchoes(std::span(echoes.data(), hitCount), separation, subrays, std::span(measured.data(), hitCount));
        for (std::size_t g = 0; g < groups; ++g) {
          Echo e = measured[g];
          if (measure(e, g, pose, ring, column)) measured[returned++] = e;  // returned <= g: in place
        }
        // Noise larger than the separation can swap neighbouring returns: reported in the order
        // of their measured ranges. Insertion sort: stable (equal ranges keep their traced order),
        // in place (std::stable_sort may allocate), and the returns are few and nearly in order.
        for (std::size_t i = 1; i < returned; ++i) {
          const Echo e = measured[i];
          std::size_t j = i;
          for (; j > 0 && e.range < measured[j - 1].range; --j) measured[j] = measured[j - 1];
          measured[j] = e;
        }
      }
      // The reported returns: the first `layers` (nearest first), or the last or strongest one.
      std::size_t from = 0;
      const std::size_t reported = std::min(returned, layers);
      if (returned > 0 && sensor_.returns == io::ReturnMode::last) from = returned - 1;
      if (returned > 0 && sensor_.returns == io::ReturnMode::strongest) {
        for (std::size_t g = 1; g < returned; ++g)
          if (measured[g].intensity > measured[from].intensity) from = g;
      }
      const SensorFrame& f = frame(k);
      for (std::size_t layer = 0; layer < layers; ++layer) {
        io::BeamReturn& point = out[rowPoint + layer * perPose + k];
        if (layer >= reported) {
          point = {noReturn, 0, 0, 0, -1, 0, time};
          continue;
        }
        // The return where the measured range puts it along the beam's axis, from the
        // double-precision origin.
        const Echo& r = measured[from + layer];
        point = {float(r.range),
                 float(f.origin[0] + r.range * axes[k][0]),
                 float(f.origin[1] + r.range * axes[k][1]),
                 float(f.origin[2] + r.range * axes[k][2]),
                 r.object,
                 float(r.intensity),
                 time};
      }
    }
  };
  // Beams [first, first + count) into `out` (their points, from point pointOf(first, 0)), on the
  // arena's threads.
  double tracing = 0;
  const auto traceBlock = [&](std::uint64_t first, std::size_t count, std::vector<io::BeamReturn>& out) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t firstPose = first / perPose, lastPose = (first + count - 1) / perPose;
    const std::uint64_t outFirst = pointOf(first, 0);
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
    const std::size_t grain = std::max<std::size_t>(1, 256 / std::size_t(subrays));
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, grain), [&](const tbb::blocked_range<std::size_t>& range) {
          // Neighbouring beams of a ring together, a call ending where its ring does.
          for (std::size_t i = range.begin(); i != range.end();) {
            const std::uint64_t beam = first + i;
            const std::size_t ringLeft = columns - std::size_t(beam % columns);
            const std::size_t n = std::min({beamsPerCall, ringLeft, range.end() - i});
            const std::uint64_t pose = beam / perPose;
            const SensorFrame* own = columnFrames.empty()
                                         ? nullptr
                                         : &columnFrames[std::size_t((pose - firstPose) * columns + beam % columns)];
            if (subrays == 1)
              traceBeams.template operator()<true>(beam, n, frames[pose - firstPose], own, out.data(), outFirst);
            else
              traceBeams.template operator()<false>(beam, n, frames[pose - firstPose], own, out.data(), outFirst);
            i += n;
          }
        });
    tracing += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();  // one block at a time
  };
  if (total == 0) return;

  // Beams a block: kBlockBeams points' worth; for one layer any such run, for several whole poses,
  // so that a block's points (a pose's layers one after the other) are consecutive.
  const std::uint64_t blockBeams =
      layers == 1 ? kBlockBeams : std::max<std::uint64_t>(1, kBlockBeams / (perPose * layers)) * perPose;
  tbb::task_arena& arena = app::threadArena(threads > 0 ? threads : 0);
  arena.execute([&] {
    const std::size_t firstCount = std::size_t(std::min<std::uint64_t>(blockBeams, total));
    std::vector<io::BeamReturn> ready(firstCount * layers), next(ready.size());
    std::uint64_t readyFirst = 0;
    std::size_t readyCount = firstCount;
    traceBlock(readyFirst, readyCount, ready);
    for (;;) {
      const std::uint64_t nextFirst = readyFirst + readyCount;
      const std::size_t nextCount = std::size_t(std::min<std::uint64_t>(blockBeams, total - nextFirst));
      tbb::task_group tracing;
      if (nextCount > 0) tracing.run([&] { traceBlock(nextFirst, nextCount, next); });
      try {
        sink(pointOf(readyFirst, 0), std::span<const io::BeamReturn>(ready.data(), readyCount * layers));
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
  table.points.resize(table.pointCount());
  scan(
      poses,
      [&](std::uint64_t first, std::span<const io::BeamReturn> beams) {
        std::copy(beams.begin(), beams.end(), table.points.begin() + first);
      },
      threads);
  return table;
}

}  // namespace revolve::robot
