// A surface of revolution placed in the world by its scene transform (translate . rotate . scale,
// app::Transform, in double precision), and the robot's clearance to it.
//
// Upright (its axis vertical: turned only about z, or upside down, with equal x and y scales), the
// clearance is exact: revolve::cylinderClearance in the meridian plane. Tilted, it is a lower
// bound, the larger of two: the robot's axis segment's distance to the surface minus the radius
// (the capsule around the robot holds it), found by branch and bound along the segment with exact
// point distances (revolve::closestMeridianPoint in object space; the smallest scale factor keeps
// it a lower bound under unequal scales) to within 2^-24 of the robot's size; and the signed
// distance to the surface's world box.
#pragma once

#include "geometry/placement.h"
#include "io/scene_file.h"
#include "robot/robot_body.h"

#include <revolve/revolve.h>

#include <optional>

namespace revolve::robot {

// The meridian scale of an upright placement (the axis stays vertical: turned only about z, by no
// angle, or half a turn about a horizontal axis, with equal x and y scales); nullopt when tilted.
// Decided from the description, not from rounded sines.
std::optional<MeridianScale> uprightScale(const app::Transform& transform);

class PlacedShape {
 public:
  // Keeps a reference to `shape`, which must outlive it.
  PlacedShape(const Shape& shape, const app::Transform& transform);

  bool upright() const { return upright_; }
  // A world box holding the surface.
  const Box& worldBox() const { return box_; }
  ObstacleClearance clearance(const RobotBody& robot) const;

 private:
  ObstacleClearance uprightClearance(const RobotBody& robot) const;
  ObstacleClearance tiltedClearance(const RobotBody& robot) const;
  // The world distance from p to the surface (a lower bound under unequal scales), and the surface
  // point nearest p in object space, carried to the world.
  std::pair<double, Vec3d> distanceFrom(const Vec3d& p) const;

  const Shape* shape_;
  app::Placement placement_;  // its inverse is the transform's own (inverseLinearPart), not a cofactor one
  double smallestScale_ = 1;
  bool upright_ = false;
  MeridianScale meridianScale_;  // upright only
  Box box_;
};

}  // namespace revolve::robot
