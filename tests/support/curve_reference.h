// Independent test oracle for spline profiles: ray / surface-of-revolution intersections of a curve
// made of cubic Bezier pieces, by brute force in long double.
//
// Nothing here includes the library's kernel: each piece is cut where z turns (roots of z'(u) in
// long double), F(u) = rho^2(ray at height z(u)) - r(u)^2 is sampled on a fine grid of every
// z-monotone range, and each sign change is bisected to long double precision. A tangent (double)
// root between samples is missed: callers treat answers within rounding of such rays as fragile.
#pragma once

#include "support/reference.h"

#include <revolve/revolve.h>

#include <optional>
#include <span>
#include <vector>

namespace revolve::reference {

// Every hit of the ray with the surface swept by the curve (control points 3i .. 3i + 3 make piece
// i), tnear <= t <= tfar, sorted by t; `segment` is the piece's index.
std::vector<RefHit> allCurveHits(std::span<const Point2> bezier, const RefRay& ray);
std::optional<RefHit> intersectCurve(std::span<const Point2> bezier, const RefRay& ray);

// Distance from (x, y, z) to the surface: the 2-D distance from (sqrt(x^2 + y^2), z) to the curve,
// by dense sampling refined by golden-section search about the best samples.
long double curveMeridianDistance(std::span<const Point2> bezier, long double x, long double y, long double z);

// As verdictIsFragile: whether nudging the ray's origin by `nudge` along any axis changes the
// oracle's verdict or moves its hit by more than 1e-6 * size, or the ray lies in a horizontal plane
// of a piece's end or z extremum.
bool curveVerdictIsFragile(std::span<const Point2> bezier, const RefRay& ray, long double nudge, long double size);

}  // namespace revolve::reference
