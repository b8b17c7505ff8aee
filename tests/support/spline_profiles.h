// Spline profiles the tests share: analytic shapes as cubic Bezier arcs with a known error, and
// closed everyday shapes of every spline kind with the awkward features (apexes, horizontal and
// vertical straight pieces, a pinch on the axis, curves not monotone in z, periodic loops).
#pragma once

#include <revolve/revolve.h>

#include <span>
#include <string>
#include <vector>

namespace revolve::testing {

// Cubic Bezier control points of the circular arc of `radius` about `centre` from angle a0 to a1
// (radians) in `pieces` equal pieces, each with the standard tangent length 4/3 tan(theta / 4)
// radius, without the first point (so arcs can be chained): 3 points a piece.
std::vector<Point2> arcControls(Point2 centre, double radius, double a0, double a1, int pieces);
// The largest radial distance of such a piece from its circle, a closed form (Goldapp 1991):
// radius * 2 sin^6(theta / 4) / (27 cos^2(theta / 4)); the piece lies outside the circle, within it.
double arcError(double radius, double theta);

// A sphere of `radius` about the origin: a half circle from the south pole to the north pole.
std::vector<Point2> bezierSphere(double radius, int pieces);
// A torus: the full circle of `minor` radius about (major, 0), a closed loop.
std::vector<Point2> bezierTorus(double major, double minor, int pieces);

struct NamedSpline {
  std::string name;
  SplineKind kind;
  std::vector<Point2> points;
};

// Closed splines of every kind (see above); each is a valid Spline.
std::vector<NamedSpline> closedSplines();

// The curve's points at `perPiece` equal parameter steps of each Bezier piece: a polyline close to
// it (for inside tests and interior points), written apart from the library's conversions.
std::vector<Point2> densePolyline(std::span<const Point2> bezier, int perPiece);

}  // namespace revolve::testing
