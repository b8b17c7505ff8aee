// The range sensors' table (revolve-lidar with a "type": "range" sensor file, docs/robot.md):
// one row a sensor a pose, in pose order, then sensor order,
//
//   pose,sensor,range,x,y,z,object
//
// pose and sensor numbered from 0 (sensor: its place in the sensor file), range in metres, x y z the
// reading's point in the world frame, object the scene's object index (quads after the objects).
// No reading: range `inf` and the other fields empty, as the lidar's table writes a beam without a
// return. Numbers are written to double's round-trip precision (17 significant digits).
#pragma once

#include "io/output_set.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace revolve::io {

// One sensor's reading at one pose (robot/range_sensors.h computes them).
struct RangeReading {
  double range = INFINITY;  // metres; inf: no reading
  // The nearest point as the reading places it: the apex plus range times the unit direction to the
  // nearest surface point (the nearest point itself without noise); NaN without a reading.
  std::array<double, 3> point{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                              std::numeric_limits<double>::quiet_NaN()};
  std::int64_t object = -1;  // the scene's object index (quads after the objects); -1: none
};

inline constexpr const char* kRangeTableHeader = "pose,sensor,range,x,y,z,object";

class RangeTableWriter {
 public:
  // Writes the header.
  explicit RangeTableWriter(OutputStream& out);
  // The rows of poses firstPose, firstPose + 1, ...: rows[p x sensors + s] is sensor s at pose
  // firstPose + p.
  void write(std::uint64_t firstPose, std::size_t sensors, std::span<const RangeReading> rows);

 private:
  OutputStream& out_;
};

}  // namespace revolve::io
