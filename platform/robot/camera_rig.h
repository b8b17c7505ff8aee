// A robot-mounted camera at a pose of its path: its mounting composed with the robot's pose as a
// lidar's is (sensor_rig.h), as the scene camera the renderer takes (from, to, up, vertical field
// of view), and the camera's intrinsics and pose as ROS describes them (sensor_msgs/CameraInfo,
// the optical frame of REP 103: x right, y down, z forward).
#pragma once

#include "io/poses_file.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "robot/sensor_rig.h"

#include <array>
#include <cmath>
#include <numbers>

namespace revolve::robot {

// The scene camera of `camera` on the robot at `pose`: from its origin, looking along its +X, its
// +Z up.
inline io::SceneCamera cameraAt(const io::CameraDescription& camera, const io::RobotPose& pose) {
  const SensorFrame frame = sensorFrame(camera.pose, pose);
  const Vec3d forward = frame.rotate({1, 0, 0}), up = frame.rotate({0, 0, 1});
  io::SceneCamera scene;
  scene.from = frame.origin;
  scene.to = {frame.origin[0] + forward[0], frame.origin[1] + forward[1], frame.origin[2] + forward[2]};
  scene.up = up;
  scene.fovDegrees = camera.fovDegrees;
  scene.width = camera.width;
  scene.height = camera.height;
  return scene;
}

// The pinhole's intrinsic matrix K (row-major) in ROS's pixel coordinates, whose integers are pixel
// centres: the renderer's ray through image position (u + 1/2, v + 1/2) from the top left corner
// is pixel (u, v)'s. Square pixels: fx = fy = (height / 2) / tan(fov / 2); the principal point is
// the image's centre, ((width - 1) / 2, (height - 1) / 2).
inline std::array<double, 9> intrinsics(const io::CameraDescription& camera) {
  const double f = 0.5 * camera.height / std::tan(camera.fovDegrees * std::numbers::pi / 360.0);
  return {f, 0, 0.5 * (camera.width - 1), 0, f, 0.5 * (camera.height - 1), 0, 0, 1};
}

// World from the camera's optical frame (x right, y down, z forward), row-major: the columns are
// the optical axes in the world, -Y, -Z and +X of the camera's own frame.
inline std::array<double, 9> opticalRotation(const io::CameraDescription& camera, const io::RobotPose& pose) {
  const SensorFrame frame = sensorFrame(camera.pose, pose);
  const Vec3d right = frame.rotate({0, -1, 0}), down = frame.rotate({0, 0, -1}), forward = frame.rotate({1, 0, 0});
  return {right[0], down[0], forward[0], right[1], down[1], forward[1], right[2], down[2], forward[2]};
}

}  // namespace revolve::robot
