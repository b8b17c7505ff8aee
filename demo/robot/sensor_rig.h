// Where a range-finder's beams start and point in the world: the sensor's mounting on the robot
// (io::SensorPose, ROS conventions) composed with a robot pose (io::RobotPose), and the beam
// directions of its fans. Double precision; rays are rounded to float once, at the end.
#pragma once

#include "io/poses_file.h"
#include "io/sensor_file.h"

#include <array>
#include <cmath>

namespace revolve::robot {

using Vec3d = std::array<double, 3>;

// A rotation (world from sensor) and the sensor's origin in the world.
struct SensorFrame {
  Vec3d origin{};
  std::array<Vec3d, 3> rows{};  // the rotation matrix, row by row

  Vec3d rotate(const Vec3d& v) const {
    return {rows[0][0] * v[0] + rows[0][1] * v[1] + rows[0][2] * v[2],
            rows[1][0] * v[0] + rows[1][1] * v[1] + rows[1][2] * v[2],
            rows[2][0] * v[0] + rows[2][1] * v[1] + rows[2][2] * v[2]};
  }
};

// The unit direction of the beam at `azimuth` (counter-clockwise about the sensor's +Z from its +X)
// and `elevation` (up from its XY plane), in the sensor's frame.
inline Vec3d beamDirection(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

// World from sensor: the robot at (x, y, z) turned by yaw about +Z, carrying the sensor at its
// mounting position turned by Rz(yaw) Ry(pitch) Rx(roll) (ROS's fixed-axis roll, pitch, yaw).
inline SensorFrame sensorFrame(const io::SensorPose& mount, const io::RobotPose& pose) {
  const auto rz = [](double a) {
    return std::array<Vec3d, 3>{Vec3d{std::cos(a), -std::sin(a), 0}, Vec3d{std::sin(a), std::cos(a), 0},
                                Vec3d{0, 0, 1}};
  };
  const auto ry = [](double a) {
    return std::array<Vec3d, 3>{Vec3d{std::cos(a), 0, std::sin(a)}, Vec3d{0, 1, 0},
                                Vec3d{-std::sin(a), 0, std::cos(a)}};
  };
  const auto rx = [](double a) {
    return std::array<Vec3d, 3>{Vec3d{1, 0, 0}, Vec3d{0, std::cos(a), -std::sin(a)},
                                Vec3d{0, std::sin(a), std::cos(a)}};
  };
  const auto multiply = [](const std::array<Vec3d, 3>& a, const std::array<Vec3d, 3>& b) {
    std::array<Vec3d, 3> c{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    }
    return c;
  };
  const std::array<Vec3d, 3> robot = rz(pose.yaw);
  SensorFrame frame;
  frame.rows = multiply(robot, multiply(rz(mount.yaw), multiply(ry(mount.pitch), rx(mount.roll))));
  const SensorFrame robotOnly{{}, robot};
  const Vec3d mounted = robotOnly.rotate(mount.position);
  frame.origin = {pose.x + mounted[0], pose.y + mounted[1], pose.z + mounted[2]};
  return frame;
}

}  // namespace revolve::robot
