// The poses file (POSES.csv): where the robot stands, one pose a line, for revolve-lidar and
// revolve-clearance. The header names the columns and is required: x, y and yaw, with z, roll,
// pitch and time optional, each once, in any order (`x,y,yaw`, `x,y,z,yaw`, `time,x,y,z,yaw`,
// `x,y,z,roll,pitch,yaw`, ...). z: an empty z field, or no z column, means 0, i.e. the sensor's or
// robot's own heights apply unchanged. Units are the scene's; angles are in radians: the robot
// turned as ROS's fixed-axis roll (about X), pitch (about Y), yaw (about Z) turn it, R = Rz(yaw)
// Ry(pitch) Rx(roll); no roll or pitch column means 0 (a robot on level ground). time: seconds,
// strictly increasing down the file, within +-1e12 (a moving sensor's sweeps start at the poses'
// times and the robot moves between them, robot/sensor_motion.h; revolve-clearance does not use it).
//
// The reader is strict: a bad line is an InputError naming the file, the line and the problem.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

struct RobotPose {
  double x = 0, y = 0, z = 0, yaw = 0;
  double time = std::numeric_limits<double>::quiet_NaN();  // seconds; NaN: the poses carry no time
  double roll = 0, pitch = 0;

  bool timed() const { return !std::isnan(time); }
  bool level() const { return roll == 0 && pitch == 0; }
};

// The largest |time| a pose may carry, in seconds (about 32,000 years: any clock's epoch).
inline constexpr double kMaxPoseTime = 1e12;

// Why a pose's `time` cannot follow the previous pose's (NaN for the first pose), or nullptr.
inline const char* poseTimeProblem(double time, double previous) {
  if (!(std::abs(time) <= kMaxPoseTime)) return "is out of range: a pose's time is a number of seconds within +-1e12";
  if (!std::isnan(previous) && !(time > previous)) return "does not increase: times are strictly increasing";
  return nullptr;
}

// Parses POSES.csv `text`; `file` names it in messages. Throws InputError (text_files.h).
std::vector<RobotPose> parsePosesCsv(std::string_view text, std::string_view file);
std::vector<RobotPose> readPosesCsv(const std::string& path);

}  // namespace revolve::io
