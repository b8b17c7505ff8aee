#include "io/curve_polyline.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <string>

namespace revolve::io {
namespace {

std::string shortest(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

}  // namespace

bool onTheAxis(const Profile& polyline) {
  const std::span<const Point2> points = polyline.points();
  return std::all_of(points.begin(), points.end(), [](const Point2& p) { return p.r == 0.0; });
}

Profile curvePolyline(const Spline& curve, double tolerance) {
  Profile polyline = Profile::fromCurve(curve, tolerance);
  if (!onTheAxis(polyline)) return polyline;
  // The curve's largest radius lies at an end of one of its parts monotone in r: the points of a
  // shape's profile. Built only here, to say how far the tolerance must come down.
  const Shape shape(curve);  // named: the points belong to it
  double largest = 0;
  for (const Point2& p : shape.profile().points()) largest = std::max(largest, p.r);
  if (largest == 0) return polyline;  // the curve lies on the axis itself: its own (warned-of) business
  throw std::invalid_argument("polyline tolerance " + shortest(tolerance) + " collapses the " +
                              splineKindName(curve.kind()) +
                              " spline onto the axis: every point of its polyline has r = 0, a surface of no area that "
                              "nothing hits, where the curve reaches r = " +
                              shortest(largest) + "; a tolerance below that keeps the polyline off the axis");
}

}  // namespace revolve::io
