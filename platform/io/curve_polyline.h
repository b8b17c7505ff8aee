// The polyline a tool traces a curve as, within a tolerance the user gave (a scene's "tolerance",
// revolve-render's and revolve-trace's --tolerance): Profile::fromCurve, which always makes a valid
// profile, refused only when the tolerance would lose the shape, by one rule for every place.
#pragma once

#include <revolve/core.h>

namespace revolve::io {

// Profile::fromCurve(curve, tolerance), or std::invalid_argument (stating the tolerance, the
// curve's largest radius and the rule) when every point of the polyline lies on the axis while the
// curve does not: a tolerance at or beyond the curve's largest radius may collapse it onto the axis,
// a surface of no area that nothing hits, where the curve had a shape. Also fromCurve's own
// std::invalid_argument for a tolerance it cannot take.
Profile curvePolyline(const Spline& curve, double tolerance);

// Whether `polyline` lies wholly on the axis (r = 0 at every point).
bool onTheAxis(const Profile& polyline);

}  // namespace revolve::io
