#include "support/spline_profiles.h"

#include <cmath>
#include <numbers>

namespace revolve::testing {

std::vector<Point2> arcControls(Point2 centre, double radius, double a0, double a1, int pieces) {
  std::vector<Point2> out;
  const double theta = (a1 - a0) / pieces, k = 4.0 / 3.0 * std::tan(theta / 4.0) * radius;
  for (int i = 0; i < pieces; ++i) {
    const double b0 = a0 + i * theta, b1 = b0 + theta;
    const Point2 p0{centre.r + radius * std::cos(b0), centre.z + radius * std::sin(b0)};
    const Point2 p1{centre.r + radius * std::cos(b1), centre.z + radius * std::sin(b1)};
    out.push_back({p0.r - k * std::sin(b0), p0.z + k * std::cos(b0)});
    out.push_back({p1.r + k * std::sin(b1), p1.z - k * std::cos(b1)});
    out.push_back(p1);
  }
  return out;
}

double arcError(double radius, double theta) {
  const double s = std::sin(theta / 4.0), c = std::cos(theta / 4.0);
  return radius * 2.0 * std::pow(s, 6) / (27.0 * c * c);
}

std::vector<Point2> bezierSphere(double radius, int pieces) {
  const double pi = std::numbers::pi;
  std::vector<Point2> points{{0.0, -radius}};
  for (const Point2& p : arcControls({0.0, 0.0}, radius, -pi / 2, pi / 2, pieces)) points.push_back(p);
  points.back() = {0.0, radius};  // the pole exactly on the axis
  return points;
}

std::vector<Point2> bezierTorus(double major, double minor, int pieces) {
  std::vector<Point2> points{{major + minor, 0.0}};
  for (const Point2& p : arcControls({major, 0.0}, minor, 0.0, 2.0 * std::numbers::pi, pieces)) points.push_back(p);
  points.back() = points.front();  // closed exactly
  return points;
}

namespace {

// A straight cubic piece from the last point to `to`: inner points at the thirds.
void straightTo(std::vector<Point2>& points, Point2 to) {
  const Point2 from = points.back();
  points.push_back({from.r + (to.r - from.r) / 3.0, from.z + (to.z - from.z) / 3.0});
  points.push_back({to.r + (from.r - to.r) / 3.0, to.z + (from.z - to.z) / 3.0});
  points.push_back(to);
}

void curveTo(std::vector<Point2>& points, Point2 c1, Point2 c2, Point2 to) {
  points.push_back(c1);
  points.push_back(c2);
  points.push_back(to);
}

}  // namespace

std::vector<NamedSpline> closedSplines() {
  const double pi = std::numbers::pi;
  std::vector<NamedSpline> splines;
  splines.push_back({"bezier sphere (4 arcs)", SplineKind::bezier, bezierSphere(0.5, 4)});
  splines.push_back({"bezier torus (8 arcs)", SplineKind::bezier, bezierTorus(0.6, 0.25, 8)});

  // A bottle: flat base, a fillet, a straight body, an S-shaped shoulder, a straight neck, a rounded
  // lip and a flat top; straight pieces horizontal, vertical and sloped.
  std::vector<Point2> bottle{{0.0, 0.0}};
  straightTo(bottle, {0.26, 0.0});
  for (const Point2& p : arcControls({0.26, 0.04}, 0.04, -pi / 2, 0.0, 1)) bottle.push_back(p);
  straightTo(bottle, {0.3, 0.6});
  curveTo(bottle, {0.3, 0.75}, {0.12, 0.7}, {0.11, 0.85});
  straightTo(bottle, {0.1, 1.0});
  curveTo(bottle, {0.1, 1.03}, {0.13, 1.03}, {0.12, 1.06});
  straightTo(bottle, {0.0, 1.06});
  splines.push_back({"bezier bottle (straight and curved pieces)", SplineKind::bezier, bottle});

  // A cup: a closed loop of quadratic pieces, up the outside and down the inside (not monotone in z).
  splines.push_back({"quadratic cup (a loop, not monotone in z)",
                     SplineKind::quadratic,
                     {{0.05, 0.0},
                      {0.3, 0.0},
                      {0.4, 0.05},
                      {0.5, 0.5},
                      {0.5, 1.0},
                      {0.5, 1.03},
                      {0.47, 1.03},
                      {0.46, 1.03},
                      {0.46, 1.0},
                      {0.46, 0.5},
                      {0.36, 0.1},
                      {0.2, 0.05},
                      {0.05, 0.05},
                      {0.0, 0.025},
                      {0.05, 0.0}}});
  splines.push_back(
      {"catmull-rom vase",
       SplineKind::catmullRom,
       {{0.0, 0.0}, {0.2, 0.01}, {0.3, 0.1}, {0.42, 0.4}, {0.35, 0.75}, {0.2, 0.95}, {0.24, 1.1}, {0.0, 1.12}}});
  splines.push_back(
      {"natural goblet",
       SplineKind::natural,
       {{0.0, 0.0}, {0.3, 0.02}, {0.12, 0.1}, {0.06, 0.3}, {0.2, 0.5}, {0.33, 0.75}, {0.36, 0.95}, {0.0, 1.0}}});
  // An hourglass pinched to a point on the axis in the middle.
  std::vector<Point2> hourglass{{0.0, -1.0}};
  straightTo(hourglass, {0.6, -1.0});
  curveTo(hourglass, {0.6, -0.5}, {0.1, -0.2}, {0.0, 0.0});
  curveTo(hourglass, {0.1, 0.2}, {0.6, 0.5}, {0.6, 1.0});
  straightTo(hourglass, {0.0, 1.0});
  splines.push_back({"bezier hourglass (pinched on the axis)", SplineKind::bezier, hourglass});
  // Periodic loops off the axis.
  std::vector<Point2> ellipse;
  for (int i = 0; i <= 9; ++i) {
    const double a = 2 * pi * (i % 9) / 9;
    ellipse.push_back({0.7 + 0.3 * std::cos(a), 0.5 * std::sin(a) + 0.1 * std::sin(2 * a)});
  }
  splines.push_back({"catmull-rom loop (periodic)", SplineKind::catmullRom, ellipse});
  splines.push_back({"natural loop (periodic)", SplineKind::natural, ellipse});
  return splines;
}

std::vector<Point2> densePolyline(std::span<const Point2> bezier, int perPiece) {
  std::vector<Point2> points{bezier[0]};
  for (std::size_t i = 0; i + 3 < bezier.size(); i += 3) {
    const Point2* c = &bezier[i];
    for (int j = 1; j <= perPiece; ++j) {
      const double u = double(j) / perPiece, v = 1.0 - u;
      const double b0 = v * v * v, b1 = 3 * v * v * u, b2 = 3 * v * u * u, b3 = u * u * u;
      points.push_back(j == perPiece ? c[3]
                                     : Point2{b0 * c[0].r + b1 * c[1].r + b2 * c[2].r + b3 * c[3].r,
                                              b0 * c[0].z + b1 * c[1].z + b2 * c[2].z + b3 * c[3].z});
    }
  }
  return points;
}

}  // namespace revolve::testing
