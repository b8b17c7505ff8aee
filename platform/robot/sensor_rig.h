// Where a range-finder's beams start and point in the world: the sensor's mounting on the robot
// (io::SensorPose, ROS conventions) composed with a robot pose (io::RobotPose), and the beam
// directions of its fans. Double precision; rays are rounded to float once, at the end.
#pragma once

#include "geometry/placement.h"
#include "geometry/vec3d.h"
#include "io/poses_file.h"
#include "io/sensor_file.h"

#include <array>
#include <cmath>

namespace revolve::robot {

using app::Vec3d;

// A rotation (world from sensor) and the sensor's origin in the world.
struct SensorFrame {
  Vec3d origin{};
  app::Matrix3d rotation{};

  Vec3d rotate(const Vec3d& v) const { return rotation.apply(v); }
};

// The unit direction of the beam at `azimuth` (counter-clockwise about the sensor's +Z from its +X)
// and `elevation` (up from its XY plane), in the sensor's frame.
inline Vec3d beamDirection(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

// World from sensor: the robot at (x, y, z) turned by yaw about +Z, carrying the sensor at its
// mounting position turned by Rz(yaw) Ry(pitch) Rx(roll) (ROS's fixed-axis roll, pitch, yaw).
inline SensorFrame sensorFrame(const io::SensorPose& mount, const io::RobotPose& pose) {
  const app::Matrix3d robot = app::rotationAboutZ(pose.yaw);
  SensorFrame frame;
  frame.rotation =
      robot * (app::rotationAboutZ(mount.yaw) * (app::rotationAboutY(mount.pitch) * app::rotationAboutX(mount.roll)));
  const SensorFrame robotOnly{{}, robot};
  const Vec3d mounted = robotOnly.rotate(mount.position);
  frame.origin = {pose.x + mounted[0], pose.y + mounted[1], pose.z + mounted[2]};
  return frame;
}

}  // namespace revolve::robot
