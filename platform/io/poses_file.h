// The poses file (POSES.csv): where the robot stands, one pose a line, for revolve-lidar and
// revolve-clearance. The header names the columns and is required: `x,y,z,yaw` or `x,y,yaw`
// (z is optional: an empty z field, or no z column, means 0, i.e. the sensor's or robot's own
// heights apply unchanged). Units are the scene's; yaw is in radians, counter-clockwise about +Z.
//
// The reader is strict: a bad line is an InputError naming the file, the line and the problem.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

struct RobotPose {
  double x = 0, y = 0, z = 0, yaw = 0;
};

// Parses POSES.csv `text`; `file` names it in messages. Throws InputError (text_files.h).
std::vector<RobotPose> parsePosesCsv(std::string_view text, std::string_view file);
std::vector<RobotPose> readPosesCsv(const std::string& path);

}  // namespace revolve::io
