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

// The sensor's rotation on the robot: Rz(yaw) Ry(pitch) Rx(roll) (ROS's fixed-axis roll, pitch, yaw).
inline app::Matrix3d mountRotation(const io::SensorPose& mount) {
  return app::rotationAboutZ(mount.yaw) * (app::rotationAboutY(mount.pitch) * app::rotationAboutX(mount.roll));
}

// The robot's rotation: Rz(yaw) Ry(pitch) Rx(roll), the yaw alone on level ground.
inline app::Matrix3d robotRotation(const io::RobotPose& pose) {
  if (pose.level()) return app::rotationAboutZ(pose.yaw);
  return app::rotationAboutZ(pose.yaw) * (app::rotationAboutY(pose.pitch) * app::rotationAboutX(pose.roll));
}

// World from sensor: the robot at (x, y, z) turned by robotRotation, carrying the sensor at its
// mounting position turned by `mounted` (mountRotation(mount), made once by callers that place
// many beams).
inline SensorFrame sensorFrame(const io::SensorPose& mount, const app::Matrix3d& mounted, const io::RobotPose& pose) {
  const app::Matrix3d robot = robotRotation(pose);
  SensorFrame frame;
  frame.rotation = robot * mounted;
  const Vec3d position = robot.apply(Vec3d{mount.position[0], mount.position[1], mount.position[2]});
  frame.origin = {pose.x + position[0], pose.y + position[1], pose.z + position[2]};
  return frame;
}

inline SensorFrame sensorFrame(const io::SensorPose& mount, const io::RobotPose& pose) {
  return sensorFrame(mount, mountRotation(mount), pose);
}

}  // namespace revolve::robot
