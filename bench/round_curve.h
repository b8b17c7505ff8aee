// Embree's round Bézier curve (RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE) along the z axis, fitted to a
// smooth profile: the other primitive an Embree user would reach for.
//
// What Embree 3.13's kernel renders (kernels/geometry/curve_intersector_sweep.h): the sweep of a
// circle of radius r(u) centred on the curve P(u), in the plane perpendicular to the tangent P'(u)
// (Newton's method on dot(Q - P(u), T(u)) = 0 and |Q - P(u)|_perp = r(u), in single precision; not
// the envelope of spheres). With P(u) on the z axis that is exactly the surface of revolution of the
// planar Bézier curve (r(u), z(u)), as long as z'(u) != 0: a segment must rise or fall all along. Its
// ends are open (no caps). So each line of the profile becomes one segment (exactly), each arc is cut
// at its highest and lowest points and each piece approximated by cubic Béziers with the usual
// tangent handles (4/3 tan(theta / 4) R: error ~ R theta^6); a horizontal first or last line
// starting or ending on the axis becomes one of Embree's oriented discs
// (RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT), and any other horizontal piece (a ring, a step) cannot be
// expressed.
#pragma once

#include "smooth_profile.h"

#include <revolve/embree_api.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace revolve::bench {

struct RoundCurveFit {
  std::vector<float> controlPoints;         // x, y, z, radius per control point; x = y = 0
  std::vector<std::uint32_t> firstControl;  // per Bézier segment: the first of its four control points
  struct Disc {
    double z, radius;
    double normalZ;  // +1 or -1: the profile's normal (right of travel) there
  };
  std::vector<Disc> discs;
};

// At least one segment per piece of the profile; the rest go, one at a time, to the arc piece whose
// segments span the widest angle times its radius^(1/6) (the largest error).
// Returns the fit, or why the profile or this number of segments cannot be one.
std::variant<RoundCurveFit, std::string> fitRoundCurve(const SmoothProfile& profile, int segments);

// The curve and, if the fit has any, its discs: geometries committed and attached to `scene`.
void attachRoundCurve(RTCDevice device, RTCScene scene, const RoundCurveFit& fit);

}  // namespace revolve::bench
