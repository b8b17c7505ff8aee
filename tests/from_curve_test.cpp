// Profile::fromCurve: the polyline stays within its tolerance of the curve (measured here by dense
// sampling against the polyline, and by the long-double oracle's distance from the polyline's
// points to the curve), spends no points on straight runs, and needs no more points than the chords
// of a circle need (the fewest, in closed form); at any tolerance, however coarse, it is a valid
// profile (chords that would cross are refined).
#include "support/curve_reference.h"
#include "support/spline_profiles.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve {
namespace {

double pointSegmentDistance(Point2 p, Point2 a, Point2 b) {
  const double er = b.r - a.r, ez = b.z - a.z, length2 = er * er + ez * ez;
  const double t = length2 > 0 ? std::clamp(((p.r - a.r) * er + (p.z - a.z) * ez) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(p.r - a.r - t * er, p.z - a.z - t * ez);
}

// The largest distance from the curve (sampled `perPiece` times a piece) to the polyline.
double curveToPolyline(const Spline& spline, std::span<const Point2> polyline, int perPiece) {
  double worst = 0;
  for (std::size_t piece = 0; piece < spline.pieceCount(); ++piece) {
    for (int k = 0; k <= perPiece; ++k) {
      const Point2 p = spline.at(piece, double(k) / perPiece);
      double best = INFINITY;
      for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
        best = std::min(best, pointSegmentDistance(p, polyline[i], polyline[i + 1]));
      worst = std::max(worst, best);
    }
  }
  return worst;
}

TEST(FromCurveTest, EveryPolylineStaysWithinItsTolerance) {
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Spline spline(named.kind, named.points);
    for (const double tolerance : {1e-2, 1e-3, 1e-5}) {
      SCOPED_TRACE(named.name + ", tolerance " + std::to_string(tolerance));
      const Profile polyline = Profile::fromCurve(spline, tolerance);
      const std::span<const Point2> p = polyline.points();
      EXPECT_LE(curveToPolyline(spline, p, 200), tolerance * (1 + 1e-9));
      // And the other way: the polyline's points (vertices and chord middles) lie that close to the curve.
      for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        for (const double f : {0.0, 0.5}) {
          const double r = p[i].r + f * (p[i + 1].r - p[i].r), z = p[i].z + f * (p[i + 1].z - p[i].z);
          EXPECT_LE(double(reference::curveMeridianDistance(spline.bezier(), r, 0, z)), tolerance * (1 + 1e-9));
        }
      }
      EXPECT_EQ(polyline.closed(), spline.closed());
      // The ends are the curve's own.
      EXPECT_EQ(p.front().r, spline.bezier().front().r);
      EXPECT_EQ(p.back().z, spline.bezier().back().z);
    }
  }
}

TEST(FromCurveTest, StraightRunsGetNoPoints) {
  // A capped cylinder of straight cubic pieces, each with its inner points on the chord (off the
  // thirds, so its parametrisation is not uniform): the polyline is its four corners.
  const std::vector<Point2> points{{0, 0},     {0.1, 0}, {0.45, 0}, {0.5, 0},  {0.5, 0.1},
                                   {0.5, 0.9}, {0.5, 1}, {0.3, 1},  {0.25, 1}, {0, 1}};
  const Profile polyline = Profile::fromCurve(Spline(SplineKind::bezier, points), 1e-9);
  const std::vector<Point2> corners{{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}};
  ASSERT_EQ(polyline.points().size(), corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    EXPECT_EQ(polyline.points()[i].r, corners[i].r);
    EXPECT_EQ(polyline.points()[i].z, corners[i].z);
  }
  // Two collinear straight pieces in a row merge into one chord (a wall at r = 0.5: a curve on the
  // axis itself is refused).
  const Profile merged = Profile::fromCurve(
      Spline(SplineKind::bezier,
             std::vector<Point2>{{0.5, 0}, {0.5, 0.1}, {0.5, 0.2}, {0.5, 0.3}, {0.5, 0.5}, {0.5, 0.7}, {0.5, 1}}),
      1e-9);
  EXPECT_EQ(merged.points().size(), 2u);
}

TEST(FromCurveTest, ACircleGetsTheFewestChords) {
  // Chords of a circle of radius R whose sagitta R (1 - cos(phi / 2)) is within the tolerance
  // span at most phi = 2 acos(1 - tolerance / R): a half circle needs ceil(pi / phi) of them. The
  // cubic arcs lie within 1e-9 of the circle, far below the tolerances.
  const double radius = 0.5;
  const Spline sphere(SplineKind::bezier, testing::bezierSphere(radius, 16));
  ASSERT_LT(testing::arcError(radius, std::numbers::pi / 16), 1e-9);
  for (const double tolerance : {1e-2, 1e-3, 1e-4, 1e-5}) {
    const double phi = 2 * std::acos(1 - tolerance / radius);
    const auto fewest = std::size_t(std::ceil(std::numbers::pi / phi));
    const Profile polyline = Profile::fromCurve(sphere, tolerance);
    // Greedy chords reach as far as the tolerance allows; only the last one may be short.
    EXPECT_LE(polyline.segmentCount(), fewest + 1) << tolerance;
    EXPECT_GE(polyline.segmentCount(), fewest) << tolerance;
  }
}

TEST(FromCurveTest, NeedsFewerPointsThanEqualParameterSteps) {
  // Equal steps of each piece's parameter, refined until they meet the same tolerance, against the
  // adaptive polyline: the bottle's straight body and neck cost equal steps points, and adaptive none.
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Spline spline(named.kind, named.points);
    const double tolerance = 1e-4;
    const std::size_t adaptive = Profile::fromCurve(spline, tolerance).points().size();
    int steps = 1;
    std::vector<Point2> uniform;
    do {
      steps *= 2;
      uniform = {spline.at(0, 0.0)};
      for (std::size_t piece = 0; piece < spline.pieceCount(); ++piece) {
        for (int k = 1; k <= steps; ++k) uniform.push_back(spline.at(piece, double(k) / steps));
      }
    } while (curveToPolyline(spline, uniform, 200) > tolerance);
    EXPECT_LT(adaptive, uniform.size()) << named.name;
  }
}

TEST(FromCurveTest, RefusesBadTolerances) {
  const Spline sphere(SplineKind::bezier, testing::bezierSphere(0.5, 4));
  for (const double bad : {0.0, -1e-3, double(NAN), double(INFINITY)})
    EXPECT_THROW((void)Profile::fromCurve(sphere, bad), std::invalid_argument) << bad;
  EXPECT_THROW((void)Profile::fromCurve(sphere, 1e-14), std::invalid_argument);  // below 2^-40 of the extent
  // A linear spline is its own polyline.
  const std::vector<Point2> points{{0, 0}, {1, 0}, {1, 1}};
  EXPECT_EQ(Profile::fromCurve(Spline(SplineKind::linear, points), 1.0).points().size(), 3u);
}

// The polyline is a valid profile (Profile's exact self-intersection test passed, or fromCurve
// would not return), every point of it lies on the curve at its recorded parameter, and it lies
// within the tolerance of the curve both ways: dense samples of the curve against the polyline, and
// the long-double oracle's distance from its vertices and chord middles to the curve.
void expectValidWithin(const Spline& spline, double tolerance) {
  Profile polyline = Profile::fromCurve(spline, tolerance);  // a ProfileError fails the test
  const std::span<const Point2> p = polyline.points();
  const std::span<const double> T = polyline.curveParameters();
  ASSERT_EQ(T.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t piece = std::min(std::size_t(T[i]), spline.pieceCount() - 1);
    const Point2 on = spline.at(piece, T[i] - double(piece));
    EXPECT_EQ(on.r, p[i].r) << "point " << i;
    EXPECT_EQ(on.z, p[i].z) << "point " << i;
    if (i > 0) {
      EXPECT_GT(T[i], T[i - 1]) << "point " << i;
    }
  }
  EXPECT_LE(curveToPolyline(spline, p, 400), tolerance * (1 + 1e-9));
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (const double f : {0.0, 0.25, 0.5, 0.75}) {
      const double r = p[i].r + f * (p[i + 1].r - p[i].r), z = p[i].z + f * (p[i + 1].z - p[i].z);
      EXPECT_LE(double(reference::curveMeridianDistance(spline.bezier(), r, 0, z)), tolerance * (1 + 1e-9))
          << "segment " << i;
    }
  }
  EXPECT_EQ(polyline.closed(), spline.closed());
}

// Where two parts of a curve pass closer than twice the tolerance, chords within the tolerance may
// cross or touch; the polyline is refined there instead of refused. The wine glass of
// scenes/spline_still_life.json (its foot's rim, its bowl's thin wall) at the tolerances of a
// 105-pixel-high view (0.0046) and at 0.01 made crossing chords before.
TEST(FromCurveTest, ATolerancePastAThinWallIsRefinedIntoAValidPolylineWithinIt) {
  const Spline wineGlass(
      SplineKind::bezier,
      std::vector<Point2>{{0.0, 0.0},         {0.011333, 0.0},    {0.022667, 0.0}, {0.034, 0.0},    {0.0375, 0.0},
                          {0.0375, 0.004},    {0.034, 0.004},     {0.012, 0.006},  {0.004, 0.012},  {0.0035, 0.03},
                          {0.0035, 0.048333}, {0.0035, 0.066667}, {0.0035, 0.085}, {0.0035, 0.1},   {0.012, 0.102},
                          {0.03, 0.112},      {0.05, 0.124},      {0.05, 0.165},   {0.038, 0.2},    {0.0376, 0.2012},
                          {0.0362, 0.2012},   {0.0358, 0.2},      {0.0472, 0.166}, {0.0472, 0.126}, {0.0285, 0.1145},
                          {0.014, 0.106},     {0.006, 0.1045},    {0.0, 0.104}});
  for (const double tolerance : {0.0046079899299041995, 0.01, 0.02, 0.05, 1e-3, 3e-4}) {
    SCOPED_TRACE("wine glass, tolerance " + std::to_string(tolerance));
    expectValidWithin(wineGlass, tolerance);
  }
  // A wall 1e-3 thick, bent: chords of tolerance 0.05 would cut through it and cross each other.
  const Spline thin(
      SplineKind::bezier,
      std::vector<Point2>{{0, 0}, {0.6, 0}, {0.6, 1}, {0.3, 1}, {0.6 - 1e-3, 1 - 1e-3}, {0.6 - 1e-3, 1e-3}, {0, 1e-3}});
  for (const double tolerance : {0.3, 0.05, 1e-3, 1e-5}) {
    SCOPED_TRACE("thin wall, tolerance " + std::to_string(tolerance));
    expectValidWithin(thin, tolerance);
  }
}

// Found by fuzzing: curves whose last control points lie 1e-10 apart, so that the last 1e-5 or so
// of a piece's parameter range moves the point by a few roundings only (one ends in a hook 1e-21
// long, past its end point and back). Points computed there carry no order along the curve, and
// the polyline used to zigzag between them and fold back on itself, which no refinement could
// undo; points closer than twice their rounding are now one vertex.
TEST(FromCurveTest, CurvesEndingSlowerThanRoundingGiveValidPolylines) {
  const Spline hooked(SplineKind::bezier, std::vector<Point2>{{0x1.fe0000000bp+3, 0x1.6000000016p+2},
                                                              {0x1.6p-34, 0x1.100000005p+0},
                                                              {0x1.6000000016p+2, 0x1.6000000016p+2},
                                                              {0x1.6000000001p+2, 0x1.6p+2}});
  const Spline slowJoin(SplineKind::bezier, std::vector<Point2>{{0x0p+0, 0x1.ep-37},
                                                                {0x1.ccp-34, 0x1.e0000000e6p-1},
                                                                {0x1.cc0000001ccp+2, 0x1.cc0000001ccp+2},
                                                                {0x1.cc0000001ccp+2, 0x1.cbffffffe38p+2},
                                                                {0x1.17ffffffffep+3, -0x1.fffffffaep-5},
                                                                {0x1.ep-1, 0x1.000000001p-4},
                                                                {0x1.7e000000002p+3, 0x0p+0}});
  for (const double tolerance : {1e-2, 1e-3, 1e-5}) {
    SCOPED_TRACE("tolerance " + std::to_string(tolerance));
    expectValidWithin(hooked, tolerance);
    expectValidWithin(slowJoin, tolerance);
  }
}

// A loop smaller than the tolerance (a teardrop 1e-3 across, one Bezier piece from P back to P):
// it lies within the tolerance of a chord from P to almost P, and the walk used to take that chord
// and leave one distinct point (found by fuzzing, with a loop 8e-11 across at r = 5.5). It gets a
// triangle at least.
TEST(FromCurveTest, ALoopSmallerThanTheToleranceKeepsThreePoints) {
  for (const double size : {1e-3, 8e-11}) {
    const Spline loop(SplineKind::bezier, std::vector<Point2>{{1, 1}, {1 + size, 1}, {1, 1 + size}, {1, 1}});
    for (const double tolerance : {1e-2, 1e-3, 1e-4}) {
      SCOPED_TRACE("loop " + std::to_string(size) + " across, tolerance " + std::to_string(tolerance));
      expectValidWithin(loop, tolerance);
      EXPECT_GE(Profile::fromCurve(loop, tolerance).points().size(), 4u);  // a closed triangle at least
    }
  }
}

// Every test curve at tolerances from a tenth of its size down: never an error.
TEST(FromCurveTest, EveryCurveAtEveryToleranceGivesAValidPolyline) {
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Spline spline(named.kind, named.points);
    double extent = 0;
    for (const Point2& q : spline.bezier()) extent = std::max({extent, std::abs(q.r), std::abs(q.z)});
    for (const double fraction : {0.3, 0.1, 0.05, 0.02, 0.01, 3e-3, 1e-3}) {
      SCOPED_TRACE(named.name + ", tolerance " + std::to_string(fraction) + " of the extent");
      expectValidWithin(spline, fraction * extent);
    }
  }
}

}  // namespace
}  // namespace revolve
