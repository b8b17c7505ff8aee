// The test shapes as splines: every line a straight cubic piece, every arc cubic Bezier arcs of the
// standard tangent length, enough of them that each lies within a given distance of its circle
// (Goldapp 1991: a cubic arc of angle theta and radius R lies outside its circle by at most
// R 2 sin^6(theta / 4) / (27 cos^2(theta / 4))). The benchmark traces this spline exactly and
// measures the hits against the lines and arcs themselves, so the error it reports for the spline
// includes this approximation.
#pragma once

#include "smooth_profile.h"

#include <revolve/revolve.h>

#include <vector>

namespace revolve::bench {

struct SmoothSpline {
  std::vector<Point2> bezier;  // 3n + 1 control points
  double error = 0;            // the largest distance of the spline from the profile (closed form)
};

// Arcs split into the fewest equal cubic arcs within `maxError` of their circle.
SmoothSpline bezierOf(const SmoothProfile& profile, double maxError);

// The closed-form distance above, for one cubic arc.
double cubicArcError(double radius, double theta);

}  // namespace revolve::bench
