// insideSolid and Shape::closed (revolve/core.h) against closed forms, never against the code's own
// output. Polylines: the meridian polygons of a sphere and a torus inscribed in their circles
// (convex, so a point is inside iff it lies on the inner side of every edge's line: no crossing
// count), a cup whose walls are straight lines (inside iff between them, above the floor and below
// the rim), and Sunday's winding number in long double for every closed standard profile. Splines:
// curves known in closed form (a parabola, cubic Bezier circles within their known deviation, a
// wave that is a graph over r, an arch and a loop whose two crossings at a height are a quadratic's
// roots, periodic Catmull-Rom and natural loops through a regular octagon, whose pieces follow from
// its symmetry), and for every shared closed spline the winding number of a dense polyline of its
// Bezier pieces, which lies within a stated chord error of the curve.
//
// On the surface either answer is right (the header's promise): no test asks there. Random points
// are kept only when they lie farther than kMargin of the shape's size from the surface; hand-picked
// points lie a stated tiny distance (1e-9 relative) off it, where the closed form is unambiguous.
// Why kMargin is safe: a polyline's crossing r = a.r + (b.r - a.r) ((z - a.z) / (b.z - a.z)) rounds
// four times, an error of a few ulps of the size along the point's own height line (no more across:
// the horizontal distance to a segment is at least the perpendicular one); a spline's crossing is
// bisected to adjacent doubles of u, within cubicAt's error (2^-49 of the size) of the height line,
// and a point whose r lies between that and the true crossing is within that error of the arc
// joining them. kMargin = 2^-40 is 500 times either.
#include "support/spline_profiles.h"
#include "support/test_profiles.h"
#include "support/test_seeds.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace revolve {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMargin = 0x1p-40;  // of the shape's size: see the header comment
constexpr double kNudge = 1e-9;      // relative offset of hand-picked points from a flat or straight part

std::string show(Point2 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(rho, z) = (%.17g, %.17g)", p.r, p.z);
  return text;
}

// One hand-picked point and its closed-form answer.
void expectAt(const Shape& shape, Point2 p, bool inside, const std::string& why) {
  EXPECT_EQ(insideSolid(shape, p), inside) << why << " at " << show(p);
}

enum class Truth { inside, outside, unsure };

// The answers a property test gathered: how many points fell each way, so that a test whose closed
// form put (nearly) every point on one side, or near the surface, cannot pass unnoticed.
struct Tally {
  std::size_t inside = 0, outside = 0, unsure = 0, wrong = 0;

  void check(const Shape& shape, Point2 p, Truth truth) {
    if (truth == Truth::unsure) {
      ++unsure;
      return;
    }
    const bool expected = truth == Truth::inside;
    ++(expected ? inside : outside);
    if (insideSolid(shape, p) != expected && ++wrong <= 8) {
      ADD_FAILURE() << show(p) << " should be " << (expected ? "inside" : "outside");
    }
  }
  // Every decided point right, both sides well represented, few points left undecided.
  void expectSound(std::size_t total) const {
    EXPECT_EQ(wrong, 0u) << "of " << inside + outside << " decided points";
    EXPECT_GT(inside, total / 10) << "too few points inside";
    EXPECT_GT(outside, total / 10) << "too few points outside";
    EXPECT_LT(unsure, total / 20) << "too many points within the margin of the surface";
  }
};

// ---------------------------------------------------------------------------------------------
// Independent geometry in long double.

// The cosine and sine of k / m quarter turns (any integer k), from one quarter's table mirrored into
// the others, so that points symmetric about either axis of the circle have exactly mirrored
// coordinates (two vertices of a loop share a height exactly) and the quarter points are exact.
struct Direction {
  double c, s;
};
Direction unitCircle(int k, int m) {
  k = ((k % (4 * m)) + 4 * m) % (4 * m);
  const auto quarter = [m](int j) -> Direction {
    if (j == 0) return {1.0, 0.0};
    if (j == m) return {0.0, 1.0};
    const double angle = 0.5 * kPi * j / m;
    return {std::cos(angle), std::sin(angle)};
  };
  // (0.0 - x, not -x: no negative zero at the quarter points.)
  if (k <= m) return quarter(k);
  if (k <= 2 * m) {
    const Direction d = quarter(2 * m - k);
    return {0.0 - d.c, d.s};
  }
  if (k <= 3 * m) {
    const Direction d = quarter(k - 2 * m);
    return {0.0 - d.c, 0.0 - d.s};
  }
  const Direction d = quarter(4 * m - k);
  return {d.c, 0.0 - d.s};
}

long double segmentDistance(Point2 a, Point2 b, Point2 p) {
  const long double dr = (long double)b.r - a.r, dz = (long double)b.z - a.z;
  const long double pr = (long double)p.r - a.r, pz = (long double)p.z - a.z;
  const long double length2 = dr * dr + dz * dz;
  const long double t = length2 > 0 ? std::clamp((pr * dr + pz * dz) / length2, 0.0L, 1.0L) : 0.0L;
  return std::hypot(pr - t * dr, pz - t * dz);
}

// Whether p lies within `distance` of a polyline's segments (not of a closing edge along the axis:
// no surface there), pruning runs of 32 segments by their boxes.
class NearPolyline {
 public:
  explicit NearPolyline(std::span<const Point2> points) : points_(points) {
    for (std::size_t start = 0; start + 1 < points.size(); start += kRun) {
      Run run{start, std::min(start + kRun, points.size() - 1), INFINITY, -INFINITY, INFINITY, -INFINITY};
      for (std::size_t i = run.first; i <= run.last; ++i) {
        run.rMin = std::min(run.rMin, points[i].r), run.rMax = std::max(run.rMax, points[i].r);
        run.zMin = std::min(run.zMin, points[i].z), run.zMax = std::max(run.zMax, points[i].z);
      }
      runs_.push_back(run);
    }
  }
  bool within(Point2 p, long double distance) const {
    for (const Run& run : runs_) {
      if (p.r < run.rMin - distance || p.r > run.rMax + distance || p.z < run.zMin - distance ||
          p.z > run.zMax + distance) {
        continue;
      }
      for (std::size_t i = run.first; i < run.last; ++i) {
        if (segmentDistance(points_[i], points_[i + 1], p) < distance) return true;
      }
    }
    return false;
  }

 private:
  static constexpr std::size_t kRun = 32;
  struct Run {
    std::size_t first, last;  // segments first .. last - 1
    double rMin, rMax, zMin, zMax;
  };
  std::span<const Point2> points_;
  std::vector<Run> runs_;
};

// Sunday's winding number of the polygon `points` closed by the edge from its last point to its
// first (along the axis, or of length zero for a loop), about p: signed crossings decided by the
// orientation of p against each upward or downward edge, with no intersection point computed.
int windingNumber(std::span<const Point2> points, Point2 p) {
  int winding = 0;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 a = points[i], b = points[(i + 1) % n];
    const long double side =
        ((long double)b.r - a.r) * ((long double)p.z - a.z) - ((long double)p.r - a.r) * ((long double)b.z - a.z);
    if (a.z <= p.z) {
      if (b.z > p.z && side > 0) ++winding;
    } else if (b.z <= p.z && side < 0) {
      --winding;
    }
  }
  return winding;
}

// A convex polygon listed counter-clockwise in the (r, z) plane (r across, z up), closed along the
// axis or by its own last segment: p (r >= 0) is inside iff it lies left of every segment's line.
// The axis edge needs no test: every query has r >= 0, and points on the axis are inside the solid.
Truth convexTruth(std::span<const Point2> ccw, Point2 p, double margin) {
  long double least = INFINITY;
  for (std::size_t i = 0; i + 1 < ccw.size(); ++i) {
    const Point2 a = ccw[i], b = ccw[i + 1];
    const long double dr = (long double)b.r - a.r, dz = (long double)b.z - a.z;
    const long double side = (dr * ((long double)p.z - a.z) - dz * ((long double)p.r - a.r)) / std::hypot(dr, dz);
    least = std::min(least, side);
  }
  return least > margin ? Truth::inside : least < -margin ? Truth::outside : Truth::unsure;
}

// A cubic Bezier piece's point at u (Bernstein form, long double).
struct LongPoint {
  long double r, z;
};
LongPoint bezierAt(const Point2* c, long double u) {
  const long double v = 1 - u, b0 = v * v * v, b1 = 3 * v * v * u, b2 = 3 * v * u * u, b3 = u * u * u;
  return {b0 * c[0].r + b1 * c[1].r + b2 * c[2].r + b3 * c[3].r, b0 * c[0].z + b1 * c[1].z + b2 * c[2].z + b3 * c[3].z};
}

// A polyline through `perPiece` equal steps of u on each cubic piece of `bezier`, and how far the
// curve may stray from it: linear interpolation of a C2 function over a step h errs by at most
// h^2 / 8 max |f''|, and a cubic's second derivative is 6 times a convex combination of its control
// points' second differences, per coordinate (their sum bounds the Euclidean distance).
struct DensePolyline {
  std::vector<Point2> points;
  double chordError = 0;
};
DensePolyline densePolyline(std::span<const Point2> bezier, int perPiece) {
  DensePolyline dense{{bezier[0]}, 0.0};
  for (std::size_t i = 0; i + 3 < bezier.size(); i += 3) {
    const Point2* c = &bezier[i];
    for (int j = 1; j <= perPiece; ++j) {
      const LongPoint p = bezierAt(c, (long double)j / perPiece);
      dense.points.push_back(j == perPiece ? c[3] : Point2{double(p.r), double(p.z)});
    }
    double secondR = 0, secondZ = 0;
    for (int k = 0; k < 2; ++k) {
      secondR = std::max(secondR, std::abs(c[k + 2].r - 2 * c[k + 1].r + c[k].r));
      secondZ = std::max(secondZ, std::abs(c[k + 2].z - 2 * c[k + 1].z + c[k].z));
    }
    dense.chordError = std::max(dense.chordError, 6.0 * (secondR + secondZ) / (8.0 * perPiece * perPiece));
  }
  return dense;
}

struct Box {
  double rMax, zMin, zMax;
};
Box controlBox(std::span<const Point2> points) {
  Box box{0.0, INFINITY, -INFINITY};
  for (const Point2& p : points) box = {std::max(box.rMax, p.r), std::min(box.zMin, p.z), std::max(box.zMax, p.z)};
  return box;
}

// Random points for a property test, a third of each: uniform over the box padded by a quarter of
// its size; near the given points (vertices or curve points), offset by a log-uniform distance from
// 10^nearest (default 1e-10) to 1e-2 of the size; and at exactly the height of one of them (half of
// these on the axis).
std::vector<Point2> probePoints(std::mt19937_64& random, Box box, std::span<const Point2> near, std::size_t count,
                                double nearest = -10) {
  const double size = std::max({box.rMax, box.zMax - box.zMin, std::abs(box.zMin), std::abs(box.zMax)});
  const double pad = 0.25 * std::max(box.rMax, box.zMax - box.zMin);
  std::uniform_real_distribution<double> unit(0.0, 1.0), exponent(nearest, -2.0), angle(0.0, 2 * kPi);
  std::uniform_int_distribution<std::size_t> pick(0, near.size() - 1);
  std::vector<Point2> points;
  for (std::size_t i = 0; i < count; ++i) {
    switch (i % 3) {
      case 0:
        points.push_back(
            {unit(random) * (box.rMax + pad), box.zMin - pad + unit(random) * (box.zMax - box.zMin + 2 * pad)});
        break;
      case 1: {
        const Point2 at = near[pick(random)];
        const double distance = size * std::pow(10.0, exponent(random)), a = angle(random);
        points.push_back({std::abs(at.r + distance * std::cos(a)), at.z + distance * std::sin(a)});
        break;
      }
      default:
        points.push_back({random() % 2 == 0 ? 0.0 : unit(random) * (box.rMax + pad), near[pick(random)].z});
        break;
    }
  }
  return points;
}

// ---------------------------------------------------------------------------------------------
// Polylines.

// The inscribed polygon of the half circle of `radius` about the origin, 2m segments from the south
// pole to the north pole (counter-clockwise), poles exactly on the axis, heights mirrored exactly.
std::vector<Point2> semicircle(double radius, int m) {
  std::vector<Point2> points;
  for (int k = 3 * m; k <= 5 * m; ++k) {
    const Direction d = unitCircle(k, m);
    points.push_back({radius * d.c, radius * d.s});
  }
  return points;
}

// The inscribed polygon of the circle of radius `minor` about (major, 0), counter-clockwise, a closed
// loop of 4m segments. With vertices at the quarter points (0, 90, 180, 270 degrees: a vertex at the
// top and the bottom) or, `flatTop`, half a step off them (a horizontal edge at the top and the
// bottom, and two vertices sharing each height exactly).
std::vector<Point2> torusSection(double major, double minor, int m, bool flatTop) {
  std::vector<Point2> points;
  for (int k = 0; k < 4 * m; ++k) {
    const Direction d = flatTop ? unitCircle(2 * k + 1, 2 * m) : unitCircle(k, m);
    points.push_back({major + minor * d.c, minor * d.s});
  }
  points.push_back(points.front());
  return points;
}

TEST(SolidInsidePolylineTest, SphereAgreesWithItsInscribedPolygonAtRandomPoints) {
  // The solid of a polyline is its polygon swept: the closed form is the convex polygon's, not the
  // circle's, so points in the band between the polygon and the circle (up to the sagitta
  // R (1 - cos(pi / 4m)) inside the circle) are decided too, and must be.
  constexpr double radius = 1.75;
  constexpr int m = 50;
  const std::vector<Point2> points = semicircle(radius, m);
  const Shape shape{Profile(points)};
  ASSERT_TRUE(shape.closed());
  const double apothem = radius * std::cos(kPi / (4 * m));
  for (const std::uint64_t seed : testing::testSeeds({0x501d, 0x501e})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::vector<Point2> probes = probePoints(random, controlBox(points), points, 3000);
    // And a third more in the sagitta band, where the circle does not decide but the polygon does.
    std::uniform_real_distribution<double> band(apothem * (1 - 1e-4), radius * (1 + 1e-4)), angle(-kPi / 2, kPi / 2);
    for (int i = 0; i < 1000; ++i) {
      const double d = band(random), a = angle(random);
      probes.push_back({d * std::cos(a), d * std::sin(a)});
    }
    Tally tally;
    std::size_t inBand = 0;
    for (const Point2 p : probes) {
      const Truth truth = convexTruth(points, p, kMargin * radius);
      // The reference against the circle, where the circle decides: inside the apothem's circle,
      // inside the polygon; outside the circle, outside it.
      const double d = std::hypot(p.r, p.z);
      if (d < apothem * (1 - 1e-12)) {
        ASSERT_EQ(truth, Truth::inside) << show(p);
      }
      if (d > radius * (1 + 1e-12)) {
        ASSERT_EQ(truth, Truth::outside) << show(p);
      }
      if (d > apothem && d < radius && truth != Truth::unsure) ++inBand;
      tally.check(shape, p, truth);
    }
    tally.expectSound(probes.size());
    EXPECT_GT(inBand, 500u) << "points between the polygon and its circle";
  }
}

TEST(SolidInsidePolylineTest, SphereAtEveryVertexHeightCountsTheVertexOnce) {
  // A horizontal line through a vertex where the profile keeps rising crosses it once: counting it
  // twice (both segments' closed ends) or never (both open ends) would turn the whole chord at that
  // height inside out, the axis included.
  constexpr double radius = 1.75;
  const std::vector<Point2> points = semicircle(radius, 50);
  const Shape shape{Profile(points)};
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    const Point2 v = points[k];
    const std::string why = "height of vertex " + std::to_string(k);
    expectAt(shape, {0.0, v.z}, true, why + ", on the axis");
    expectAt(shape, {0.5 * v.r, v.z}, true, why);
    expectAt(shape, {v.r * (1 - kNudge), v.z}, true, why + ", just inside the vertex");
    expectAt(shape, {v.r * (1 + kNudge), v.z}, false, why + ", just outside the vertex");
    expectAt(shape, {2 * radius, v.z}, false, why + ", beyond the sphere");
  }
}

TEST(SolidInsidePolylineTest, SphereOnTheAxisIsInsideBetweenThePolesOnly) {
  // The profile's ends lie on the axis (the closing edge, never crossed): on the axis the chord from
  // the axis to the polygon is crossed once between the poles, never beyond them.
  constexpr double radius = 1.75;
  const Shape shape{Profile(semicircle(radius, 50))};
  expectAt(shape, {0.0, 0.0}, true, "the centre");
  expectAt(shape, {0.0, radius * (1 - kNudge)}, true, "just below the north pole");
  expectAt(shape, {0.0, -radius * (1 - kNudge)}, true, "just above the south pole");
  expectAt(shape, {0.0, radius * (1 + kNudge)}, false, "just above the north pole");
  expectAt(shape, {0.0, -radius * (1 + kNudge)}, false, "just below the south pole");
  expectAt(shape, {0.0, 3 * radius}, false, "far above");
  expectAt(shape, {0.0, -3 * radius}, false, "far below");
  // Beside the poles, at their very height: the line touches the polygon only at the pole.
  expectAt(shape, {0.5 * radius, radius}, false, "beside the north pole");
  expectAt(shape, {0.5 * radius, -radius}, false, "beside the south pole");
}

TEST(SolidInsidePolylineTest, TorusAgreesWithItsInscribedPolygonAtRandomPoints) {
  // (rho - a)^2 + z^2 < b^2 up to the sagitta b (1 - cos(pi / 4m)); within it the convex polygon
  // decides. Points on the axis and in the hole are among the probes (a third at vertex heights,
  // half of those on the axis), all outside.
  constexpr double major = 2.5, minor = 0.75;
  for (const bool flatTop : {false, true}) {
    SCOPED_TRACE(flatTop ? "flat top and bottom" : "vertices at the top and bottom");
    const std::vector<Point2> points = torusSection(major, minor, 24, flatTop);
    const Shape shape{Profile(points)};
    ASSERT_TRUE(shape.closed());
    const double apothem = minor * std::cos(kPi / (4 * 24));
    for (const std::uint64_t seed : testing::testSeeds({0x7025})) {
      SCOPED_TRACE(testing::seedTrace(seed));
      std::mt19937_64 random(seed);
      const std::vector<Point2> probes = probePoints(random, controlBox(points), points, 3000);
      Tally tally;
      std::size_t axis = 0, hole = 0;
      for (const Point2 p : probes) {
        const Truth truth = convexTruth(points, p, kMargin * (major + minor));
        const double d = std::hypot(p.r - major, p.z);
        if (d < apothem * (1 - 1e-12)) {
          ASSERT_EQ(truth, Truth::inside) << show(p);
        }
        if (d > minor * (1 + 1e-12)) {
          ASSERT_EQ(truth, Truth::outside) << show(p);
        }
        axis += p.r == 0.0;
        hole += p.r > 0.0 && p.r < major - minor && std::abs(p.z) < minor;
        tally.check(shape, p, truth);
      }
      tally.expectSound(probes.size());
      EXPECT_GT(axis, 100u);
      EXPECT_GT(hole, 100u);
    }
  }
}

TEST(SolidInsidePolylineTest, TorusAtEveryVertexHeightIsInsideTheTubeOnly) {
  // At a vertex's height the line meets the polygon at two vertices with the same z exactly (mirror
  // images), or touches the top or bottom. Inside iff between the two: the axis, the hole and
  // beyond are outside. At the top vertex (a local maximum) and the bottom one (a minimum) the line
  // meets the polygon at that vertex alone, so everything else on it is outside: each of the two
  // segments must count it the same way (both or neither). With a flat top and bottom, a horizontal
  // edge lies on the line: everything beside it is outside.
  constexpr double major = 2.5, minor = 0.75;
  for (const bool flatTop : {false, true}) {
    SCOPED_TRACE(flatTop ? "flat top and bottom" : "vertices at the top and bottom");
    const std::vector<Point2> points = torusSection(major, minor, 24, flatTop);
    const Shape shape{Profile(points)};
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      const Point2 v = points[k];
      const double half = std::abs(v.r - major);  // the tube's half-width at this height
      const bool extreme = std::abs(v.z) == minor || half == 0.0;
      const std::string why = "height of vertex " + std::to_string(k);
      expectAt(shape, {0.0, v.z}, false, why + ", on the axis");
      expectAt(shape, {0.5 * (major - minor), v.z}, false, why + ", in the hole");
      expectAt(shape, {major + 2 * minor, v.z}, false, why + ", beyond the torus");
      if (extreme && !flatTop) {
        expectAt(shape, {major - 0.5 * minor, v.z}, false, why + " (the top or bottom), left of it");
        expectAt(shape, {major + 0.5 * minor, v.z}, false, why + " (the top or bottom), right of it");
        continue;
      }
      const bool flatEdge = flatTop && std::abs(v.z) == minor * unitCircle(2 * 24 - 1, 2 * 24).s;
      if (flatEdge) {  // on the top or bottom edge's line: beside the edge, outside
        expectAt(shape, {(major - half) * (1 - kNudge), v.z}, false, why + " (a flat top or bottom), left of the edge");
        expectAt(shape, {(major + half) * (1 + kNudge), v.z}, false,
                 why + " (a flat top or bottom), right of the edge");
        continue;
      }
      expectAt(shape, {major, v.z}, true, why + ", the tube's middle");
      expectAt(shape, {(major - half) * (1 + kNudge), v.z}, true, why + ", just inside the inner vertex");
      expectAt(shape, {(major + half) * (1 - kNudge), v.z}, true, why + ", just inside the outer vertex");
      expectAt(shape, {(major - half) * (1 - kNudge), v.z}, false, why + ", just outside the inner vertex");
      expectAt(shape, {(major + half) * (1 + kNudge), v.z}, false, why + ", just outside the outer vertex");
    }
    // Just inside the top and bottom (the flat edges, or below the top vertex): inside.
    const double top = flatTop ? minor * unitCircle(2 * 24 - 1, 2 * 24).s : minor;
    expectAt(shape, {major, top * (1 - kNudge)}, true, "just below the top");
    expectAt(shape, {major, -top * (1 - kNudge)}, true, "just above the bottom");
    expectAt(shape, {major, top * (1 + kNudge)}, false, "just above the top");
    expectAt(shape, {major, -top * (1 + kNudge)}, false, "just below the bottom");
  }
}

// A cup with sloping walls: from the axis out along the base, up the outer wall to the rim, across
// the flat rim, down the inner wall to the inner floor and along it back to the axis.
//   outer wall r = 0.75 + z / 8 (from (0.75, 0) to (1, 2)), rim z = 2 from r = 1 to 0.875,
//   inner wall r = 0.625 + (z - 0.25) / 7 (from (0.875, 2) to (0.625, 0.25)), floor z = 0.25.
const std::vector<Point2> kCup{{0, 0}, {0.75, 0}, {1, 2}, {0.875, 2}, {0.625, 0.25}, {0, 0.25}};
double cupOuter(double z) { return 0.75 + z / 8; }
double cupInner(double z) { return 0.625 + (z - 0.25) / 7; }

// Inside iff above the base, below the rim, inside the outer wall and, above the floor, outside
// the inner wall. Unsure within `margin` of one of the six edges (horizontally for the walls, which
// is at least the distance across them); a point on the line of an edge but beyond its ends is
// decided (at the vertex heights, the lines the half-open rule is about).
Truth cupTruth(Point2 p, double margin) {
  const long double z = p.z, rho = p.r;
  const long double outer = 0.75L + z / 8, inner = 0.625L + (z - 0.25L) / 7;
  const auto near = [margin](long double gap) { return std::abs(gap) < margin; };
  const auto within = [margin](long double x, long double low, long double high) {
    return x > low - margin && x < high + margin;
  };
  if ((near(z) && rho < 0.75L + margin) || (near(z - 0.25L) && rho < 0.625L + margin) ||
      (near(z - 2) && within(rho, 0.875L, 1)) || (near(rho - outer) && within(z, 0, 2)) ||
      (near(rho - inner) && within(z, 0.25L, 2))) {
    return Truth::unsure;
  }
  const bool inside = z > 0 && z < 2 && rho < outer && (z < 0.25L || rho > inner);
  return inside ? Truth::inside : Truth::outside;
}

TEST(SolidInsidePolylineTest, CupWallAndFloorAreInsideItsCavityIsNot) {
  const Shape shape{Profile(kCup)};
  ASSERT_TRUE(shape.closed());
  expectAt(shape, {0.8, 1.0}, true, "in the wall");
  expectAt(shape, {0.3, 0.125}, true, "in the floor");
  expectAt(shape, {0.0, 0.125}, true, "in the floor, on the axis");
  expectAt(shape, {0.3, 1.0}, false, "in the cavity");
  expectAt(shape, {0.0, 1.0}, false, "in the cavity, on the axis");
  expectAt(shape, {0.0, -0.5}, false, "below, on the axis");
  expectAt(shape, {0.5, -0.5}, false, "below");
  expectAt(shape, {0.5, 3.0}, false, "above");
  expectAt(shape, {0.0, 3.0}, false, "above, on the axis");
  expectAt(shape, {1.5, 1.0}, false, "beside");
  // A tiny distance across each straight part, where the closed form is unambiguous. At z = 1.125
  // the walls lie at exactly r = 0.890625 and r = 0.75.
  expectAt(shape, {0.5, kNudge}, true, "just above the base");
  expectAt(shape, {0.5, -kNudge}, false, "just below the base");
  expectAt(shape, {0.5, 0.25 - kNudge}, true, "just below the inner floor");
  expectAt(shape, {0.5, 0.25 + kNudge}, false, "just above the inner floor");
  expectAt(shape, {0.9375, 2 - kNudge}, true, "just below the rim");
  expectAt(shape, {0.9375, 2 + kNudge}, false, "just above the rim");
  ASSERT_EQ(cupOuter(1.125), 0.890625);
  ASSERT_EQ(cupInner(1.125), 0.75);
  expectAt(shape, {0.890625 * (1 - kNudge), 1.125}, true, "just inside the outer wall");
  expectAt(shape, {0.890625 * (1 + kNudge), 1.125}, false, "just outside the outer wall");
  expectAt(shape, {0.75 * (1 + kNudge), 1.125}, true, "just inside the inner wall");
  expectAt(shape, {0.75 * (1 - kNudge), 1.125}, false, "just outside the inner wall (in the cavity)");
}

TEST(SolidInsidePolylineTest, CupAtItsVertexHeightsWithHorizontalEdgesOnTheLine) {
  // At each vertex height a horizontal edge of the profile lies on the line (the base, the inner
  // floor, the rim), and the line passes through the vertices at its ends. The half-open rule must
  // count the wall that leaves the line once, and the horizontal edge never.
  const Shape shape{Profile(kCup)};
  // z = 0, the base: beyond the base's outer corner (0.75, 0) there is nothing.
  expectAt(shape, {0.75 * (1 + kNudge), 0.0}, false, "base height, just beyond the base's corner");
  expectAt(shape, {2.0, 0.0}, false, "base height, far out");
  // z = 0.25, the inner floor: between the inner floor's corner (0.625) and the outer wall (0.78125)
  // lies the wall; beyond, nothing. (The floor itself, r < 0.625, is the surface.)
  ASSERT_EQ(cupOuter(0.25), 0.78125);
  expectAt(shape, {0.7, 0.25}, true, "inner floor height, in the wall");
  expectAt(shape, {0.625 * (1 + kNudge), 0.25}, true, "inner floor height, just beside the floor's corner");
  expectAt(shape, {0.78125 * (1 - kNudge), 0.25}, true, "inner floor height, just inside the outer wall");
  expectAt(shape, {0.78125 * (1 + kNudge), 0.25}, false, "inner floor height, just outside the outer wall");
  expectAt(shape, {2.0, 0.25}, false, "inner floor height, far out");
  // z = 2, the rim: over the cavity, on the axis and beyond the rim, outside.
  expectAt(shape, {0.0, 2.0}, false, "rim height, on the axis");
  expectAt(shape, {0.5, 2.0}, false, "rim height, over the cavity");
  expectAt(shape, {0.875 * (1 - kNudge), 2.0}, false, "rim height, just inside the rim's inner corner");
  expectAt(shape, {1.0 * (1 + kNudge), 2.0}, false, "rim height, just beyond the rim's outer corner");
  expectAt(shape, {2.0, 2.0}, false, "rim height, far out");
}

TEST(SolidInsidePolylineTest, CupAgreesWithItsWallsAtRandomPoints) {
  const Shape shape{Profile(kCup)};
  for (const std::uint64_t seed : testing::testSeeds({0xc0b})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    const std::vector<Point2> probes = probePoints(random, controlBox(kCup), kCup, 6000);
    Tally tally;
    std::size_t atVertexHeights = 0;
    for (const Point2 p : probes) {
      const Truth truth = cupTruth(p, kMargin * 2);
      atVertexHeights += truth != Truth::unsure && (p.z == 0 || p.z == 0.25 || p.z == 2);
      tally.check(shape, p, truth);
    }
    // The cup's wall is thin (an eighth of its radius): fewer points land inside than out. A third
    // of the points lie at vertex heights, half of those on the axis, many on a horizontal edge
    // (the surface, undecided).
    EXPECT_EQ(tally.wrong, 0u);
    EXPECT_GT(tally.inside, probes.size() / 20);
    EXPECT_GT(tally.outside, probes.size() / 10);
    EXPECT_LT(tally.unsure, probes.size() / 4);
    EXPECT_GT(atVertexHeights, probes.size() / 10);
  }
}

TEST(SolidInsidePolylineTest, EveryClosedStandardProfileAgreesWithAWindingNumber) {
  // Non-convex profiles (a hollow vase, an hourglass pinched on the axis, a zigzag column, a random
  // star) against Sunday's winding number in long double, which decides by orientation alone.
  for (const std::uint64_t seed : testing::testSeeds({0x5a1d})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::size_t profiles = 0;
    for (const testing::NamedProfile& named : testing::standardProfiles()) {
      const Shape shape{Profile(named.points)};
      if (!shape.closed()) continue;
      ++profiles;
      SCOPED_TRACE(named.name);
      const Box box = controlBox(named.points);
      const double size = std::max({box.rMax, std::abs(box.zMin), std::abs(box.zMax)});
      const std::vector<Point2> probes = probePoints(random, box, named.points, 3000);
      const NearPolyline surface(named.points);
      Tally tally;
      for (const Point2 p : probes) {
        const Truth truth = surface.within(p, kMargin * size)     ? Truth::unsure
                            : windingNumber(named.points, p) != 0 ? Truth::inside
                                                                  : Truth::outside;
        tally.check(shape, p, truth);
      }
      // A third of the points lie at vertex heights, where a horizontal edge (a disc, the hourglass's
      // ends) leaves some on the surface, undecided: most of them for the capped cylinder, whose
      // every vertex ends a disc.
      EXPECT_EQ(tally.wrong, 0u);
      EXPECT_GT(tally.inside, probes.size() / 20);
      EXPECT_GT(tally.outside, probes.size() / 20);
      EXPECT_LT(tally.unsure, probes.size() / 3);
    }
    EXPECT_GE(profiles, 9u);
  }
}

// ---------------------------------------------------------------------------------------------
// Splines.

// A spline shape's points against a closed form, at random points of its control box (padded) and
// near the given curve points.
template <typename TruthOf>
Tally checkSplineAtRandom(const Shape& shape, std::span<const Point2> near, std::uint64_t seed, TruthOf truthOf) {
  std::mt19937_64 random(seed);
  const std::vector<Point2> probes = probePoints(random, controlBox(shape.spline()->bezier()), near, 3000);
  Tally tally;
  for (const Point2 p : probes) tally.check(shape, p, truthOf(p));
  return tally;
}

TEST(SolidInsideSplineTest, QuadraticParabolaLensIsInsideItsParabola) {
  // One quadratic piece from (0, -h) through the control point (2w, 0) to (0, h):
  // r = 4 w u (1 - u), z = h (2u - 1), so its boundary is r = w (1 - (z / h)^2), a closed form.
  constexpr double w = 0.75, h = 1.25;
  const Shape shape{Spline(SplineKind::quadratic, std::vector<Point2>{{0, -h}, {2 * w, 0}, {0, h}})};
  ASSERT_TRUE(shape.closed());
  const auto truth = [](Point2 p) {
    const long double t = (long double)p.z / h, boundary = w * (1 - t * t);
    if (std::abs(p.r - boundary) < kMargin * 2 || std::abs(std::abs(t) - 1) < kMargin * 2) return Truth::unsure;
    return std::abs(t) < 1 && p.r < boundary ? Truth::inside : Truth::outside;
  };
  std::vector<Point2> near;
  for (int i = 0; i <= 40; ++i) {
    const double z = h * (i / 20.0 - 1);
    near.push_back({w * (1 - (z / h) * (z / h)), z});
  }
  for (const std::uint64_t seed : testing::testSeeds({0x9a1})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    checkSplineAtRandom(shape, near, seed, truth).expectSound(3000);
  }
  expectAt(shape, {0.0, 0.0}, true, "the centre");
  expectAt(shape, {w * (1 - kNudge), 0.0}, true, "just inside the widest point");
  expectAt(shape, {w * (1 + kNudge), 0.0}, false, "just outside the widest point");
  // Near the tips the lens is 2 w (1 - |z| / h) wide: 1e-9 below the tip, about 1.2e-9 from the axis.
  expectAt(shape, {0.0, h * (1 - kNudge)}, true, "on the axis just below the upper tip");
  expectAt(shape, {0.0, -h * (1 - kNudge)}, true, "on the axis just above the lower tip");
  expectAt(shape, {0.0, h * (1 + kNudge)}, false, "on the axis just above the upper tip");
  expectAt(shape, {0.25, h}, false, "beside the upper tip, at its height");
}

TEST(SolidInsideSplineTest, QuadraticArchCrossedTwiceByOnePieceAtEachHeight) {
  // An arch: one quadratic piece (1, 0), (1.5, 2), (2, 0), i.e. r = 1 + u, z = 4 u (1 - u), closed
  // by a straight quadratic piece back along z = 0. A line at height 0 < h < 1 crosses the arch's
  // single piece twice, at u = (1 -+ sqrt(1 - h)) / 2: inside iff |rho - 1.5| < sqrt(1 - h) / 2.
  // Counting a piece whose ends lie on the same side of the line as no crossing (not splitting it
  // where z turns) would leave the whole arch outside.
  const Shape shape{Spline(SplineKind::quadratic, std::vector<Point2>{{1, 0}, {1.5, 2}, {2, 0}, {1.5, 0}, {1, 0}})};
  ASSERT_TRUE(shape.closed());
  const auto truth = [](Point2 p) {
    const long double z = p.z, halfWidth = z <= 1 ? std::sqrt(1 - z) / 2 : -1.0L;
    const long double gap = halfWidth - std::abs(p.r - 1.5L);
    // Horizontally within the margin of a crossing, or vertically of the base, or of the top.
    if (std::abs(gap) < kMargin * 2 || std::abs(z) < kMargin * 2 || std::abs(z - 1) < kMargin * 2) return Truth::unsure;
    return z > 0 && z < 1 && gap > 0 ? Truth::inside : Truth::outside;
  };
  std::vector<Point2> near;
  for (int i = 0; i <= 40; ++i) near.push_back({1 + i / 40.0, 4 * (i / 40.0) * (1 - i / 40.0)});
  for (const std::uint64_t seed : testing::testSeeds({0xa4c})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    checkSplineAtRandom(shape, near, seed, truth).expectSound(3000);
  }
  expectAt(shape, {1.5, 0.5}, true, "under the arch");
  expectAt(shape, {1.2, 0.5}, true, "under the arch, near its left side (1.146)");
  expectAt(shape, {1.1, 0.5}, false, "left of the arch: both crossings lie beyond");
  expectAt(shape, {0.0, 0.5}, false, "on the axis: both crossings lie beyond");
  expectAt(shape, {2.5, 0.5}, false, "right of the arch");
  expectAt(shape, {1.5, kNudge}, true, "just above the base");
  expectAt(shape, {1.5, -kNudge}, false, "just below the base");
  expectAt(shape, {1.5, 1 - kNudge}, true, "just below the top");
  expectAt(shape, {1.5, 1 + kNudge}, false, "just above the top");
  expectAt(shape, {1.25, 1.0}, false, "beside the top, at its height");
}

TEST(SolidInsideSplineTest, BezierSphereAndTorusLieWithinTheirKnownDeviation) {
  // Cubic arcs of a circle lie outside it, by at most arcError (a closed form, Goldapp 1991): inside
  // the circle is inside, beyond the circle by more than that is outside.
  struct Case {
    const char* name;
    std::vector<Point2> points;
    Point2 centre;
    double radius, error;
  };
  const std::vector<Case> cases{
      {"sphere, 4 arcs", testing::bezierSphere(1.5, 4), {0, 0}, 1.5, testing::arcError(1.5, kPi / 4)},
      {"sphere, 3 arcs", testing::bezierSphere(1.5, 3), {0, 0}, 1.5, testing::arcError(1.5, kPi / 3)},
      {"torus, 8 arcs", testing::bezierTorus(2.0, 0.5, 8), {2.0, 0}, 0.5, testing::arcError(0.5, kPi / 4)},
      {"torus, 5 arcs", testing::bezierTorus(2.0, 0.5, 5), {2.0, 0}, 0.5, testing::arcError(0.5, 2 * kPi / 5)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Shape shape{Spline(SplineKind::bezier, c.points)};
    ASSERT_TRUE(shape.closed());
    const double size = c.centre.r + c.radius;
    const auto truth = [&](Point2 p) {
      const double d = std::hypot(p.r - c.centre.r, p.z - c.centre.z);
      if (d < c.radius - kMargin * size) return Truth::inside;
      if (d > c.radius + c.error + kMargin * size) return Truth::outside;
      return Truth::unsure;
    };
    std::vector<Point2> near;
    for (int i = 0; i < 64; ++i) {
      const Direction d = unitCircle(i, 16);
      if (c.centre.r + c.radius * d.c >= 0) near.push_back({c.centre.r + c.radius * d.c, c.radius * d.s});
    }
    for (const std::uint64_t seed : testing::testSeeds({0xb5})) {
      SCOPED_TRACE(testing::seedTrace(seed));
      const Tally tally = checkSplineAtRandom(shape, near, seed, truth);
      EXPECT_EQ(tally.wrong, 0u);
      EXPECT_GT(tally.inside, 300u);
      EXPECT_GT(tally.outside, 300u);
      // Points nearer the circle than the arcs' deviation (up to ~1e-4 of the radius) stay undecided:
      // most of those drawn near it at log-uniform distances, at most half of all.
      EXPECT_LT(tally.unsure, 1500u);
    }
    // At the joins' heights (the pieces' ends: the half-open rule across pieces), on the axis and
    // off it. The joins lie on the circle; beside them the curve is within the deviation.
    for (std::size_t j = 0; j < c.points.size(); j += 3) {
      const Point2 join = c.points[j];
      const std::string why = "height of join " + std::to_string(j / 3);
      if (std::abs(join.z - c.centre.z) > c.radius * (1 - 1e-12)) {  // a pole, or the torus's top or bottom
        // (A sphere's pole is on the axis: the surface, no question asked there.)
        if (c.centre.r > 0) {
          expectAt(shape, {0.0, join.z}, false, why + " (an extreme), on the axis");
          expectAt(shape, {0.5 * c.centre.r, join.z}, false, why + " (an extreme), left of it");
        }
        expectAt(shape, {c.centre.r + 0.5 * c.radius, join.z}, false, why + " (an extreme), right of it");
        continue;
      }
      // Across the circle's chord at this height: 1e-6 inside the circle is inside; outside, the
      // step must clear the deviation: (half + step)^2 + z^2 > (R + e)^2 when step > (R e + e^2) / half.
      const double half = std::sqrt(c.radius * c.radius - join.z * join.z);  // the circle's half-chord
      const double outer = c.centre.r + half, inner = c.centre.r - half;
      const double step = (c.radius * c.error + c.error * c.error) / half + 1e-6;
      expectAt(shape, {outer - 1e-6, join.z}, true, why + ", just inside the outer side");
      expectAt(shape, {outer + step, join.z}, false, why + ", just outside the outer side");
      expectAt(shape, {2 * size, join.z}, false, why + ", far out");
      if (c.centre.r == 0) {
        expectAt(shape, {0.0, join.z}, true, why + ", on the axis");
      } else {
        expectAt(shape, {c.centre.r, join.z}, true, why + ", the tube's middle");
        expectAt(shape, {inner + 1e-6, join.z}, true, why + ", just inside the inner side");
        expectAt(shape, {inner - step, join.z}, false, why + ", just outside the inner side (the hole)");
        expectAt(shape, {0.0, join.z}, false, why + ", on the axis");
      }
    }
  }
}

// The wave block below: a straight base, the wave, a straight top (straight pieces with their inner
// controls at the thirds).
const std::vector<Point2> kWaveBlock{{0, 0},  {1.0 / 3, 0}, {2.0 / 3, 0},     {1, 0},       {1.5, 2},
                                     {2, -1}, {2.5, 1},     {2.5 * 2 / 3, 1}, {2.5 / 3, 1}, {0, 1}};
// The loop below: one cubic piece from (1, 0) back to itself.
const std::vector<Point2> kLoop{{1, 0}, {2, 2}, {0, 2}, {1, 0}};

TEST(SolidInsideSplineTest, BezierWaveCrossedThreeTimesByOnePiece) {
  // A block from the axis to r = 1 whose right side is one cubic piece, a wave: controls r = 1, 1.5,
  // 2, 2.5 (so r = 1 + 1.5 u exactly) and z = 0, 2, -1, 1, which rises to ~0.724, falls to ~0.276
  // and rises to 1 (z turns twice in the piece), then a flat top back to the axis. The solid is
  // below the top and above the base and the wave, a graph over r:
  //   inside iff 0 < z < 1 and (rho < 1, or rho < 2.5 and z > wave((rho - 1) / 1.5)).
  // A line between the wave's turns crosses the one piece three times.
  const Shape shape{Spline(SplineKind::bezier, kWaveBlock)};
  ASSERT_TRUE(shape.closed());
  const auto wave = [](long double u) {
    const long double v = 1 - u;
    return 6 * v * v * u - 3 * v * u * u + u * u * u;
  };
  const auto truth = [&](Point2 p) {
    const long double rho = p.r, z = p.z;
    // Vertically within the margin of the wave (whose slope dz/dr is at most 6: the z differences
    // 2, -3, 2 times 3 over 1.5) is within it across; or of the base, the top, the wave's end r = 2.5.
    const long double waveZ = rho >= 1 && rho <= 2.5 ? wave((rho - 1) / 1.5L) : -1.0L;
    for (const long double gap : {z, z - 1, rho - 2.5L, (z - waveZ) / 7}) {
      if (std::abs(gap) < kMargin * 3) return Truth::unsure;
    }
    const bool inside = z > 0 && z < 1 && (rho < 1 || (rho < 2.5L && z > waveZ));
    return inside ? Truth::inside : Truth::outside;
  };
  std::vector<Point2> near;
  for (int i = 0; i <= 60; ++i) near.push_back({1 + 1.5 * i / 60.0, double(wave(i / 60.0L))});
  for (const std::uint64_t seed : testing::testSeeds({0x3a5e})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    checkSplineAtRandom(shape, near, seed, truth).expectSound(3000);
  }
  // At z = 0.5: wave(0.25) = 0.71875 above the line, wave(0.5) = 0.5 on it, wave(0.75) = 0.28125
  // below it: the line crosses the wave before u = 0.25, at u = 0.5 (rho = 1.75) and after 0.75.
  ASSERT_EQ(wave(0.25L), 0.71875L);
  ASSERT_EQ(wave(0.5L), 0.5L);
  ASSERT_EQ(wave(0.75L), 0.28125L);
  expectAt(shape, {0.5, 0.5}, true, "left of all three crossings");
  expectAt(shape, {1.375, 0.5}, false, "under the wave's crest, two crossings to the right");
  expectAt(shape, {2.125, 0.5}, true, "over the wave's trough, one crossing to the right");
  expectAt(shape, {2.75, 0.5}, false, "beyond the wave");
  expectAt(shape, {0.0, 0.5}, true, "on the axis");
  expectAt(shape, {0.5, kNudge}, true, "just above the base");
  expectAt(shape, {0.5, -kNudge}, false, "just below the base");
  expectAt(shape, {2.0, 1 - kNudge}, true, "just below the top");
  expectAt(shape, {2.0, 1 + kNudge}, false, "just above the top");
}

TEST(SolidInsideSplineTest, BezierLoopOfOnePieceCrossedTwiceAtEachHeight) {
  // One cubic piece that starts and ends at (1, 0), controls (2, 2) and (0, 2): a closed loop with
  // z = 6 u (1 - u), turning at u = 1/2, and r(u) - r(1 - u) = 6 u (1 - u) (1 - 2u). At height
  // 0 < h < 1.5 the loop spans r(1 - u) < rho < r(u), u = (1 - sqrt(1 - 2h/3)) / 2, with
  // r(u) = (1 - u)^3 + 6 u (1 - u)^2 + u^3.
  const Shape shape{Spline(SplineKind::bezier, kLoop)};
  ASSERT_TRUE(shape.closed());
  const auto r = [](long double u) {
    const long double v = 1 - u;
    return v * v * v + 6 * u * v * v + u * u * u;
  };
  const auto truth = [&](Point2 p) {
    const long double z = p.z;
    if (std::abs(z) < kMargin * 4 || std::abs(z - 1.5L) < kMargin * 4) return Truth::unsure;
    if (z <= 0 || z >= 1.5L) return Truth::outside;
    const long double u = (1 - std::sqrt(1 - 2 * z / 3)) / 2;
    const long double right = r(u), left = r(1 - u);
    if (std::abs(p.r - right) < kMargin * 4 || std::abs(p.r - left) < kMargin * 4) return Truth::unsure;
    return p.r > left && p.r < right ? Truth::inside : Truth::outside;
  };
  std::vector<Point2> near;
  for (int i = 0; i <= 60; ++i) {
    const long double u = i / 60.0L;
    near.push_back({double(r(u)), double(6 * u * (1 - u))});
  }
  for (const std::uint64_t seed : testing::testSeeds({0x100b})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    checkSplineAtRandom(shape, near, seed, truth).expectSound(3000);
  }
  // At height z(1/4) = 1.125 the loop spans r(3/4) = 0.71875 to r(1/4) = 1.28125.
  ASSERT_EQ(r(0.25L), 1.28125L);
  ASSERT_EQ(r(0.75L), 0.71875L);
  expectAt(shape, {1.0, 1.125}, true, "inside the loop");
  expectAt(shape, {0.71875 * (1 + kNudge), 1.125}, true, "just inside its left side");
  expectAt(shape, {1.28125 * (1 - kNudge), 1.125}, true, "just inside its right side");
  expectAt(shape, {0.71875 * (1 - kNudge), 1.125}, false, "just outside its left side: both crossings lie beyond");
  expectAt(shape, {1.28125 * (1 + kNudge), 1.125}, false, "just outside its right side");
  expectAt(shape, {0.5, 1.125}, false, "left of the loop: both crossings lie beyond");
  expectAt(shape, {0.0, 1.125}, false, "on the axis");
  expectAt(shape, {1.5, 1.125}, false, "right of the loop");
  expectAt(shape, {1.0, 1.5 * (1 - kNudge)}, true, "just below the top (the turn)");
  expectAt(shape, {1.0, 1.5 * (1 + kNudge)}, false, "just above the top");
  expectAt(shape, {0.5, 1.5}, false, "at the top's height, left of it");
  expectAt(shape, {1.5, 1.5}, false, "at the top's height, right of it");
}

// The cubic Bezier pieces of the periodic spline of `kind` through the regular polygon of n vertices
// on the circle of `radius` about `centre`, derived here from the kinds' definitions (core.h). All
// chords are equal, so both parametrisations (sqrt of the chord, the chord) space the knots
// equally. Catmull-Rom with equal knots: the tangent at P_i is (P_{i+1} - P_{i-1}) / 2 a knot step,
// so the inner controls are P_i + (P_{i+1} - P_{i-1}) / 6 and P_{i+1} - (P_{i+2} - P_i) / 6. The
// natural periodic spline with step h: its second derivatives M_i solve M_{i-1} + 4 M_i + M_{i+1} =
// 6 / h^2 (P_{i+1} - 2 P_i + P_{i-1}); by the polygon's symmetry P_{i+1} + P_{i-1} - 2 P_i =
// 2 (cos a - 1) (P_i - c) (a = 2 pi / n), so M_i = mu / h^2 (P_i - c) with mu = 6 (cos a - 1) / (cos a + 2),
// and the inner controls P_i + (P_{i+1} - P_i) / 3 - mu (2 (P_i - c) + (P_{i+1} - c)) / 18 and
// P_{i+1} - (P_{i+1} - P_i) / 3 - mu ((P_i - c) + 2 (P_{i+1} - c)) / 18.
std::vector<Point2> regularLoopBezier(SplineKind kind, Point2 centre, double radius, int n) {
  std::vector<LongPoint> p;  // relative to the centre
  for (int i = 0; i < n; ++i) {
    const long double a = 2 * std::numbers::pi_v<long double> * i / n;
    p.push_back({radius * std::cos(a), radius * std::sin(a)});
  }
  const auto at = [&](int i) { return p[((i % n) + n) % n]; };
  const long double mu = 6 * (std::cos(2 * std::numbers::pi_v<long double> / n) - 1) /
                         (std::cos(2 * std::numbers::pi_v<long double> / n) + 2);
  std::vector<Point2> bezier;
  const auto push = [&](LongPoint q) { bezier.push_back({double(centre.r + q.r), double(centre.z + q.z)}); };
  for (int i = 0; i < n; ++i) {
    const LongPoint a = at(i), b = at(i + 1), before = at(i - 1), after = at(i + 2);
    push(a);
    if (kind == SplineKind::catmullRom) {
      push({a.r + (b.r - before.r) / 6, a.z + (b.z - before.z) / 6});
      push({b.r - (after.r - a.r) / 6, b.z - (after.z - a.z) / 6});
    } else {
      push({a.r + (b.r - a.r) / 3 - mu * (2 * a.r + b.r) / 18, a.z + (b.z - a.z) / 3 - mu * (2 * a.z + b.z) / 18});
      push({b.r - (b.r - a.r) / 3 - mu * (a.r + 2 * b.r) / 18, b.z - (b.z - a.z) / 3 - mu * (a.z + 2 * b.z) / 18});
    }
  }
  push(at(0));
  return bezier;
}

TEST(SolidInsideSplineTest, PeriodicCatmullRomAndNaturalLoopsThroughAnOctagon) {
  // Each loop's distance from the centre stays within [dMin, dMax] (from its pieces, derived above,
  // and their chord error): nearer is inside, farther is outside. The axis and the hole are outside.
  constexpr double major = 1.5, minor = 0.5;
  for (const SplineKind kind : {SplineKind::catmullRom, SplineKind::natural}) {
    SCOPED_TRACE(splineKindName(kind));
    std::vector<Point2> through;
    for (int i = 0; i <= 8; ++i) {
      const double a = 2 * kPi * (i % 8) / 8;
      through.push_back({major + minor * std::cos(a), minor * std::sin(a)});
    }
    const Shape shape{Spline(kind, through)};
    ASSERT_TRUE(shape.closed());
    const DensePolyline dense = densePolyline(regularLoopBezier(kind, {major, 0}, minor, 8), 400);
    long double dMin = INFINITY, dMax = 0;
    for (std::size_t i = 0; i + 1 < dense.points.size(); ++i) {
      dMin = std::min(dMin, segmentDistance(dense.points[i], dense.points[i + 1], {major, 0}));
      dMax = std::max(dMax, std::hypot((long double)dense.points[i].r - major, (long double)dense.points[i].z));
    }
    dMin -= dense.chordError;
    dMax += dense.chordError;
    // A check of the derivation: a smooth loop through a regular octagon stays near its circle.
    ASSERT_GT(dMin, 0.85 * minor);
    ASSERT_LT(dMax, 1.1 * minor);
    const double size = major + minor;
    const auto truth = [&](Point2 p) {
      const long double d = std::hypot((long double)p.r - major, (long double)p.z);
      if (d < dMin - kMargin * size) return Truth::inside;
      if (d > dMax + kMargin * size) return Truth::outside;
      return Truth::unsure;
    };
    for (const std::uint64_t seed : testing::testSeeds({0x8090})) {
      SCOPED_TRACE(testing::seedTrace(seed));
      // About 300 points fall inside (the loop covers an eighth of the box): half of that at least.
      const Tally tally = checkSplineAtRandom(shape, through, seed, truth);
      EXPECT_EQ(tally.wrong, 0u);
      EXPECT_GT(tally.inside, 150u);
      EXPECT_GT(tally.outside, 300u);
    }
    expectAt(shape, {major, 0.0}, true, "the loop's centre");
    expectAt(shape, {0.0, 0.0}, false, "on the axis");
    expectAt(shape, {0.5 * (major - minor), 0.0}, false, "in the hole");
    expectAt(shape, {major + 2 * minor, 0.0}, false, "beyond");
    // At the heights of the points it passes through (the pieces' ends).
    for (const Point2 q : through) {
      if (std::abs(q.z) == minor) continue;  // the top and bottom: the line touches there
      expectAt(shape, {major, q.z}, true, "the middle, at a knot's height");
      expectAt(shape, {0.0, q.z}, false, "the axis, at a knot's height");
    }
  }
}

TEST(SolidInsideSplineTest, EveryClosedSplineAgreesWithTheWindingNumberOfItsDenseCurve) {
  // The shared closed splines of every kind (a quadratic cup, a Catmull-Rom vase, a natural goblet,
  // Bezier pieces straight and curved, a pinch on the axis, periodic loops): insideSolid against the
  // winding number of a polyline through 1024 points of each Bezier piece of the curve, where a point
  // farther than the chord error (plus the margin) from that polyline lies on the same side of it as
  // of the curve. Outside the control points' box is outside (the convex hull property).
  for (const std::uint64_t seed : testing::testSeeds({0xd15e})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::vector<bool> kinds(5, false);
    for (const testing::NamedSpline& named : testing::closedSplines()) {
      SCOPED_TRACE(named.name);
      const Shape shape{Spline(named.kind, named.points)};
      ASSERT_TRUE(shape.closed());
      kinds[std::size_t(named.kind)] = true;
      const std::span<const Point2> bezier = shape.spline()->bezier();
      const DensePolyline dense = densePolyline(bezier, 1024);
      const Box box = controlBox(bezier);
      const double size = std::max({box.rMax, std::abs(box.zMin), std::abs(box.zMax)});
      // Near points from 1e-5 of the size out: nearer lie within the chord error, undecided.
      const std::vector<Point2> probes = probePoints(random, box, dense.points, 3000, -5);
      const NearPolyline surface(dense.points);
      Tally tally;
      std::size_t beyondHull = 0;
      for (const Point2 p : probes) {
        Truth truth = Truth::unsure;
        if (p.r > box.rMax || p.z < box.zMin || p.z > box.zMax) {
          truth = Truth::outside;
          ++beyondHull;
        } else if (!surface.within(p, dense.chordError + kMargin * size)) {
          truth = windingNumber(dense.points, p) != 0 ? Truth::inside : Truth::outside;
        }
        tally.check(shape, p, truth);
      }
      // As above: points on a flat top or bottom at vertex heights stay undecided.
      EXPECT_EQ(tally.wrong, 0u);
      EXPECT_GT(tally.inside, probes.size() / 20);
      EXPECT_GT(tally.outside, probes.size() / 10);
      EXPECT_LT(tally.unsure, probes.size() / 4);
      EXPECT_GT(beyondHull, 50u);
    }
    // Every curved kind at least once.
    for (const SplineKind kind :
         {SplineKind::quadratic, SplineKind::bezier, SplineKind::catmullRom, SplineKind::natural}) {
      EXPECT_TRUE(kinds[std::size_t(kind)]) << splineKindName(kind);
    }
  }
}

TEST(SolidInsideSplineTest, HourglassPinchedOnTheAxis) {
  // The shared Bezier hourglass meets the axis at (0, 0), a point it passes through, with the
  // tangents (0.1, -0.2) and (0.1, 0.2) there: just above or below the pinch, the solid reaches
  // r ~ |z| / 2 from the axis, so the axis itself is inside, and the pinch's own height is the
  // surface only at r = 0 (beside it, nothing at that height but the pinch: outside).
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    if (named.name.find("hourglass") == std::string::npos) continue;
    const Shape shape{Spline(named.kind, named.points)};
    expectAt(shape, {0.0, 0.5}, true, "on the axis, upper bulb");
    expectAt(shape, {0.0, -0.5}, true, "on the axis, lower bulb");
    expectAt(shape, {0.0, 1e-6}, true, "on the axis just above the pinch");
    expectAt(shape, {0.0, -1e-6}, true, "on the axis just below the pinch");
    expectAt(shape, {1e-3, 1e-6}, false, "beside the pinch, just above its height");
    expectAt(shape, {0.25, 0.0}, false, "at the pinch's height, off the axis");
    return;
  }
  FAIL() << "no hourglass among the shared closed splines";
}

TEST(SolidInsideSplineTest, ShapesScaledByPowersOfTwoAnswerAsAtUnitScale) {
  // Scaling by a power of two is exact, so each closed form scales with the shape: the hand-picked
  // points of the cup (a polyline), the wave and the loop (splines: their turns found from scaled
  // derivatives, their crossings bisected) near the ends of the coordinate range.
  struct Probe {
    Point2 at;
    bool inside;
  };
  const std::vector<Probe> cupProbes{{{0.8, 1.0}, true},   {{0.3, 1.0}, false},   {{0.7, 0.25}, true},
                                     {{0.5, 2.0}, false},  {{0.5, kNudge}, true}, {{0.5, -kNudge}, false},
                                     {{0.0, 0.125}, true}, {{0.0, 1.0}, false}};
  const std::vector<Probe> waveProbes{
      {{0.5, 0.5}, true}, {{1.375, 0.5}, false}, {{2.125, 0.5}, true}, {{2.75, 0.5}, false}, {{0.0, 0.5}, true}};
  const std::vector<Probe> loopProbes{{{1.0, 1.125}, true},
                                      {{0.5, 1.125}, false},
                                      {{1.5, 1.125}, false},
                                      {{0.71875 * (1 + kNudge), 1.125}, true},
                                      {{1.28125 * (1 + kNudge), 1.125}, false}};
  for (const int exponent : {-50, 50}) {
    SCOPED_TRACE("scale 2^" + std::to_string(exponent));
    const auto scaled = [exponent](std::vector<Point2> points) {
      for (Point2& p : points) p = {std::ldexp(p.r, exponent), std::ldexp(p.z, exponent)};
      return points;
    };
    const auto check = [&](const Shape& shape, const std::vector<Probe>& probes, const char* name) {
      for (const Probe& probe : probes) {
        expectAt(shape, {std::ldexp(probe.at.r, exponent), std::ldexp(probe.at.z, exponent)}, probe.inside, name);
      }
    };
    check(Shape{Profile(scaled(kCup))}, cupProbes, "cup");
    check(Shape{Spline(SplineKind::bezier, scaled(kWaveBlock))}, waveProbes, "wave");
    check(Shape{Spline(SplineKind::bezier, scaled(kLoop))}, loopProbes, "loop");
  }
}

// ---------------------------------------------------------------------------------------------
// Shape::closed: the ends meet, or both lie on the axis (core.h).

TEST(SolidInsideClosedTest, ClosedIffTheEndsMeetOrBothLieOnTheAxis) {
  const auto closed = [](std::vector<Point2> points) { return Shape{Profile(points)}.closed(); };
  EXPECT_TRUE(closed({{0, 0}, {1, 0}, {1, 1}, {0, 1}})) << "both ends on the axis";
  EXPECT_TRUE(closed({{0, 0}, {1, 0.5}, {0, 1}})) << "both ends on the axis (a double cone)";
  EXPECT_TRUE(closed({{1, 0}, {2, 0}, {1.5, 1}, {1, 0}})) << "a loop off the axis";
  EXPECT_TRUE(closed({{0, 0}, {1, 0}, {1, 1}, {0, 0}})) << "a loop through the axis";
  EXPECT_FALSE(closed({{0, 1}, {0.5, 0}})) << "an open cone: one end on the axis";
  EXPECT_FALSE(closed({{0, 0}, {1, 0}, {1, 1}})) << "one end on the axis";
  EXPECT_FALSE(closed({{0.2, 0}, {0.6, 0}})) << "an annulus: neither end on the axis";
  EXPECT_FALSE(closed({{1, 0}, {2, 0}, {1.5, 1}, {1, 1e-12}})) << "ends 1e-12 apart do not meet";
  EXPECT_FALSE(closed({{1e-300, 0}, {1, 0}, {1, 1}, {0, 1}})) << "an end 1e-300 from the axis is off it";
  // The profile says the same as the shape built from it.
  const Profile cup{kCup};
  EXPECT_TRUE(cup.closed());
  EXPECT_EQ(Shape{Profile(kCup)}.closed(), cup.closed());
}

TEST(SolidInsideClosedTest, SplinesAreClosedIffTheirCurveEndsMeetOrLieOnTheAxis) {
  const auto closed = [](SplineKind kind, std::vector<Point2> points) {
    const Spline spline(kind, points);
    const bool shape = Shape{Spline(kind, points)}.closed();
    EXPECT_EQ(shape, spline.closed()) << "the shape answers as its spline";
    return shape;
  };
  EXPECT_TRUE(closed(SplineKind::quadratic, {{0, -1}, {2, 0}, {0, 1}})) << "quadratic, both ends on the axis";
  EXPECT_FALSE(closed(SplineKind::quadratic, {{0, -1}, {2, 0}, {0.5, 1}})) << "quadratic, one end on the axis";
  EXPECT_TRUE(closed(SplineKind::bezier, {{1, 0}, {2, 2}, {0, 2}, {1, 0}})) << "bezier loop";
  EXPECT_FALSE(closed(SplineKind::bezier, {{1, 0}, {2, 2}, {0, 2}, {1, 0.5}})) << "bezier, ends apart";
  EXPECT_TRUE(closed(SplineKind::catmullRom, {{0, 0}, {0.5, 0.5}, {0, 1}})) << "catmull-rom, ends on the axis";
  EXPECT_FALSE(closed(SplineKind::catmullRom, {{0.1, 0}, {0.5, 0.5}, {0, 1}})) << "catmull-rom, one end off the axis";
  EXPECT_TRUE(closed(SplineKind::natural, {{1, 0}, {1.5, 0.5}, {1, 1}, {0.5, 0.5}, {1, 0}})) << "natural, periodic";
  EXPECT_FALSE(closed(SplineKind::natural, {{1, 0}, {1.5, 0.5}, {1, 1}, {0.5, 0.5}})) << "natural, open";
  EXPECT_TRUE(closed(SplineKind::linear, {{0, 0}, {1, 0}, {0, 1}})) << "linear, both ends on the axis";
  EXPECT_FALSE(closed(SplineKind::linear, {{0, 0}, {1, 0}, {1, 1}})) << "linear, one end on the axis";
}

TEST(SolidInsideClosedTest, ALinearSplineAnswersAsItsPolyline) {
  // A linear spline builds the polyline shape: the same answers as the cup's polyline closed form.
  const Shape shape{Spline(SplineKind::linear, kCup)};
  ASSERT_EQ(shape.spline(), nullptr);
  expectAt(shape, {0.8, 1.0}, true, "in the wall");
  expectAt(shape, {0.3, 1.0}, false, "in the cavity");
  expectAt(shape, {0.7, 0.25}, true, "inner floor height, in the wall");
  expectAt(shape, {0.5, 2.0}, false, "rim height, over the cavity");
}

}  // namespace
}  // namespace revolve
