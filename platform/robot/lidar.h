// A simulated laser range-finder (the GLBot simulator's laser): every beam of a sensor (io::SensorDescription)
// traced from every robot pose into a scene built in Embree, with ROS LaserScan semantics: a beam
// with no hit, or whose measured range lies outside [min, max], is no return (+inf), never clamped;
// Gaussian noise (from the seed, per beam and return) is added to returns only; ranges are then
// rounded to the resolution. A beam is its axis, or a cone sampled by sub-rays
// (beam_footprint.h) whose hits make one or more returns (beam_returns.h). A spinning sensor's
// beams carry their firing time, and with timed poses are traced from where the moving sensor is
// then (sensor_motion.h).
#pragma once

#include "io/poses_file.h"
#include "io/scan_files.h"
#include "io/sensor_file.h"
#include "robot/beam_footprint.h"
#include "scene/embree_scene.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace revolve::robot {

class Lidar {
 public:
  // Keeps references to both: they must outlive the Lidar.
  Lidar(const scene::EmbreeScene& scene, const io::SensorDescription& sensor);

  // Receives a scan's points in point order (io::ScanLayout), a block of consecutive points at a
  // time: `first` is the number of the block's first point. A sensor reporting several returns a
  // beam (layers) hands over whole poses.
  using Sink = std::function<void(std::uint64_t first, std::span<const io::BeamReturn> points)>;
  // Points traced at a time: enough work for every thread, little memory (two blocks in flight); a
  // sensor of several layers traces whole poses, as many as fit, at least one.
  static constexpr std::size_t kBlockBeams = std::size_t{1} << 16;

  // The scan's layout for `poses` poses.
  io::ScanLayout layout(std::size_t poses) const;

  // Traces every beam of every pose on `threads` threads (0: all) and hands the returns to `sink`
  // block by block, tracing the next block while `sink` takes one: memory does not depend on the
  // number of poses. The result does not depend on the thread count: each beam's noise comes from
  // its own counter-based stream. An exception from `sink` stops the scan and is rethrown.
  // `tracingSeconds`, when given, receives the wall time spent tracing (the blocks' own time,
  // which overlaps the sink's). `firstPose` numbers poses[0] in a larger scan traced in parts (the
  // Python package's shards): the noise of pose i is that of pose firstPose + i, point numbers
  // handed to `sink` still count from 0. `sweeps`: the sweeps of poses[0], ..., poses[sweeps - 1]
  // only, the poses after them the rest of the path a moving sensor follows (sensor_motion.h; a
  // shard's poses reach to the first after its last sweep's end, so that its beams are traced from
  // where the whole scan traces them).
  static constexpr std::size_t kEveryPose = std::size_t(-1);
  void scan(std::span<const io::RobotPose> poses, const Sink& sink, int threads = 0, double* tracingSeconds = nullptr,
            std::uint64_t firstPose = 0, std::size_t sweeps = kEveryPose) const;
  // The whole scan in memory (tests and the benchmark; the tool streams).
  io::ScanTable scan(std::span<const io::RobotPose> poses, int threads = 0) const;

  std::size_t beamsPerPose() const { return layout_.beamsPerPose(); }

 private:
  struct Angle {
    double cosine, sine;
  };
  const scene::EmbreeScene& scene_;
  const io::SensorDescription& sensor_;
  io::ScanLayout layout_;                // of one pose
  std::vector<Angle> azimuths_;          // one per column
  std::vector<Angle> elevations_;        // one per ring; a pattern's one per column
  std::vector<SubrayOffset> footprint_;  // the sub-rays of every beam
};

}  // namespace revolve::robot
