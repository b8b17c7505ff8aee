// Every spline kind as cubic Bezier pieces: control points 3i to 3i + 3 make piece i, neighbours
// sharing their end point. Inputs are validated first (spline.cpp): finite, counts right, and for
// the interpolating kinds no two equal consecutive points.
#pragma once

#include <revolve/core.h>

#include <span>
#include <vector>

namespace revolve::detail {

// Segments, with their inner control points at the thirds.
std::vector<Point2> bezierOfPolyline(std::span<const Point2> points);
// 2n + 1 points: each quadratic piece raised to degree 3 (its inner points at 2/3 of the way to the middle one).
std::vector<Point2> bezierOfQuadratic(std::span<const Point2> points);
// The centripetal Catmull-Rom curve through the points (see SplineKind::catmullRom).
std::vector<Point2> bezierOfCatmullRom(std::span<const Point2> points);
// The natural (or, when the first and last points are equal, periodic) cubic spline through the
// points, parametrised by chord length (see SplineKind::natural).
std::vector<Point2> bezierOfNatural(std::span<const Point2> points);

}  // namespace revolve::detail
