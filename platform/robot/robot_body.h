// The robot of the GLBot simulator's collision test: a solid vertical cylinder with flat ends, placed in the
// world, and its signed distance function, in terms of which every clearance here is defined:
// the clearance to an obstacle is the least signed distance over the obstacle's surface points
// (positive: the gap; zero or negative: the surface touches or enters the robot, and minus the
// clearance is the deepest a surface point lies inside it, measured to its nearest side or end).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include "geometry/vec3d.h"
#include "io/poses_file.h"

namespace revolve::robot {

using app::Vec3d;

// The cylinder stands upright: a pose that tilts the robot (roll or pitch, which a lidar's poses
// may carry) has no clearance here. Throws std::invalid_argument naming the first such pose of
// `poses` (numbered from 0, as `where` calls them: "POSES.csv: pose" or "poses[").
inline void requireLevelPoses(std::span<const io::RobotPose> poses, const std::string& where) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (poses[i].level()) continue;
    char angles[64];
    std::snprintf(angles, sizeof angles, "roll = %.9g, pitch = %.9g", poses[i].roll, poses[i].pitch);
    throw std::invalid_argument(where + " " + std::to_string(i) + " (counting from 0) has " + angles +
                                ": the clearance robot is an upright cylinder on level ground (roll and pitch 0)");
  }
}

struct RobotBody {
  double x = 0, y = 0;        // the axis
  double zMin = 0, zMax = 0;  // world heights of its ends, zMin < zMax
  double radius = 0;          // > 0

  // Half the diagonal of its meridian section: every point of the robot lies within this of its centre.
  double reach() const { return std::hypot(radius, 0.5 * (zMax - zMin)); }
  Vec3d centre() const { return {x, y, 0.5 * (zMin + zMax)}; }
};

// The cylinder's signed distance at q: Euclidean outside, minus the distance to the boundary inside.
inline double signedDistance(const RobotBody& robot, const Vec3d& q) {
  const double dr = std::hypot(q[0] - robot.x, q[1] - robot.y) - robot.radius;
  const double dz = std::max(robot.zMin - q[2], q[2] - robot.zMax);
  if (dr <= 0 && dz <= 0) return std::max(dr, dz);
  return std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
}

// An axis-aligned box.
struct Box {
  Vec3d lower{}, upper{};
};

// The least signed distance over a box (a lower bound for anything inside it). Both sets are a
// horizontal set times a height interval, so apart the distance splits into a horizontal and a
// vertical gap; overlapping, the depth min(R - h, tent in z) is greatest at the box point nearest
// the axis and at the height nearest the robot's middle (its maxima separate).
inline double signedDistance(const RobotBody& robot, const Box& box) {
  const double nx = std::clamp(robot.x, box.lower[0], box.upper[0]),
               ny = std::clamp(robot.y, box.lower[1], box.upper[1]);
  const double h = std::hypot(nx - robot.x, ny - robot.y);
  const double gapZ = std::max({robot.zMin - box.upper[2], box.lower[2] - robot.zMax, 0.0});
  if (h > robot.radius || gapZ > 0) return std::hypot(std::max(h - robot.radius, 0.0), gapZ);
  const double middle = std::clamp(0.5 * (robot.zMin + robot.zMax), std::max(box.lower[2], robot.zMin),
                                   std::min(box.upper[2], robot.zMax));
  return -std::min(robot.radius - h, std::min(middle - robot.zMin, robot.zMax - middle));
}

// One obstacle's clearance. `value` is exact or, where said, a lower bound (never more clearance
// than there is); `point` is a point of the obstacle's surface whose own signed distance is
// `achieved` >= value; the two agree (to rounding) when the clearance is exact.
struct ObstacleClearance {
  double value = std::numeric_limits<double>::infinity();
  Vec3d point{};
  double achieved = std::numeric_limits<double>::infinity();
  bool exact = true;
};

}  // namespace revolve::robot
