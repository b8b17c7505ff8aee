// The clearance between the robot (robot_body.h) and a triangle (a scene's quads are two).
//
// The triangle is cut by the planes of the robot's ends into the part beside the robot (heights
// within its own) and the parts above and below. Beside it the clearance is exact: the horizontal
// distance from the robot's axis to that part, minus the radius (or, overlapping, minus the deepest
// point, bounded by min(R - h, the depth in height) and checked against the points realising it).
// Above (below) it a lower bound is taken, the larger of two: the horizontal and vertical gaps
// combined, sqrt(dh^2 + dz^2) with each at its own minimum, and the distance to the end disc's
// centre minus the radius. The first is exact when one point has both minima, which covers
// horizontal triangles (floors, ceilings, table tops) and vertical ones whose lowest (highest)
// edge is horizontal (walls, box faces); `exact` reports, per query, whether a surface point was
// found whose signed distance equals the bound.
#pragma once

#include "robot/robot_body.h"

#include <array>

namespace revolve::robot {

ObstacleClearance triangleClearance(const RobotBody& robot, const std::array<Vec3d, 3>& triangle);

}  // namespace revolve::robot
