// The nearest surface point inside a cone: what a sonar or an infrared ranger reports (ROS's
// sensor_msgs/Range), computed exactly for the surfaces revolve's scenes hold: a polyline swept
// about the z axis (a stack of truncated cones, discs and cylinders) and a triangle.
//
// The reading of a cone with apex p is the least |x - p| over surface points x inside it. The
// cone is convex (half-angle up to pi/2) and star-shaped from p, so that point is also the first
// hit of the ray from p through it: nothing nearer can hide it. The least of |x - p| over the
// compact set "surface inside the cone" lies at a point of one of these kinds, each found in closed
// form or as a root of a polynomial of degree at most 8 (derivations in cone_nearest.cpp):
//   inside the cone: a point where the sphere about p touches a smooth patch (for a swept
//     segment, the foot of the perpendicular from p in p's meridian plane; for a triangle, the
//     foot in its plane), or touches a patch's edge (a profile vertex's circle: its points in the
//     meridian plane; a triangle's edge: the nearest point of the segment), or a vertex;
//   on the cone's boundary: a point where the distance along the patch's curve of intersection
//     with the cone is stationary, or where that curve meets a patch edge.
// Every candidate is a point of the surface inside the cone (those on its boundary checked to lie on
// it, within the rounding of their computation), so the least of them is the reading, exact to
// double rounding; extra candidates (added where a degenerate case makes a whole circle stationary)
// can only be as far or farther.
#pragma once

#include "geometry/vec3d.h"

#include <revolve/core.h>

#include <array>
#include <cmath>
#include <span>

namespace revolve::app {

// A solid circular cone: the points x with angle(x - apex, axis) <= halfAngle.
class SensorCone {
 public:
  // `axis` need not be unit length (it is normalised); halfAngle in (0, pi/2].
  SensorCone(const Vec3d& apex, const Vec3d& axis, double halfAngle);

  const Vec3d& apex() const { return apex_; }
  const Vec3d& axis() const { return axis_; }  // unit
  double halfAngle() const { return halfAngle_; }
  double cosHalf() const { return cos_; }
  double sinHalf() const { return sin_; }
  // Unit vectors completing the axis to a right-handed orthonormal basis (u, v, axis).
  const Vec3d& u() const { return u_; }
  const Vec3d& v() const { return v_; }
  // Whether x lies inside (or on) the cone, by the exact comparison of rounded values.
  bool contains(const Vec3d& x) const;
  // Whether x, computed as a point where a surface crosses the cone's boundary, lies on it (not on
  // its mirror image) to within the rounding of that computation (cone_nearest.cpp says how much).
  bool onBoundary(const Vec3d& x) const;
  // Whether a ball of `radius` about `centre` may reach into the cone nearer than `within` to the
  // apex (conservative: false only when it cannot).
  bool mayReach(const Vec3d& centre, double radius, double within) const;

 private:
  Vec3d apex_, axis_, u_, v_;
  double halfAngle_, cos_, sin_;
};

// The nearest point found so far.
struct ConeNearest {
  double distance = INFINITY;
  Vec3d point{};
  void offer(double d, const Vec3d& x) {
    if (d < distance) distance = d, point = x;
  }
};

// Lowers `best` to the nearest point inside `cone` of the surface swept by the polyline `profile`
// (points (r, z), r >= 0) about the z axis, when it is nearer. Everything in the profile's frame.
void nearestOnRevolution(std::span<const Point2> profile, const SensorCone& cone, ConeNearest& best);

// The same for a triangle.
void nearestOnTriangle(const std::array<Vec3d, 3>& triangle, const SensorCone& cone, ConeNearest& best);

}  // namespace revolve::app
