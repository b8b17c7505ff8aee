// The robot of revolve-clearance's --robot RADIUS,ZMIN,ZMAX: three finite numbers, RADIUS > 0 and
// ZMIN < ZMAX (heights of the robot's ends above each pose's z). A separate function so that its
// rules are tested in process, not only through the tool.
#pragma once

#include <string_view>

namespace revolve::robot {

struct RobotDimensions {
  double radius = 0, zMin = 0, zMax = 0;
};

// Throws std::runtime_error naming the argument, the value and the rule.
RobotDimensions parseRobotArgument(std::string_view text);

}  // namespace revolve::robot
