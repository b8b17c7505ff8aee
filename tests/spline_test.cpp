// revolve::Spline: every validation rule's message, and the conversion of each kind to cubic Bezier
// pieces checked against the kind's definition (the points it passes through, its tangents, its
// continuity and end conditions), computed here apart from the library's conversion.
#include "support/spline_profiles.h"

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace revolve {
namespace {

using Rule = ProfileError::Rule;

// The ProfileError a spline of these points throws (fails the test if none).
ProfileError errorOf(SplineKind kind, std::vector<Point2> points) {
  try {
    const Spline spline(kind, points);
  } catch (const ProfileError& error) {
    return error;
  }
  ADD_FAILURE() << "no ProfileError";
  return ProfileError(Rule::tooFewPoints, 0, "");
}

void expectError(SplineKind kind, std::vector<Point2> points, Rule rule, std::size_t index, const std::string& words) {
  const ProfileError error = errorOf(kind, std::move(points));
  EXPECT_EQ(error.rule(), rule) << error.what();
  EXPECT_EQ(error.index(), index) << error.what();
  EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "one line: " << error.what();
}

TEST(SplineTest, KindNamesReadBack) {
  for (const SplineKind kind :
       {SplineKind::linear, SplineKind::quadratic, SplineKind::bezier, SplineKind::catmullRom, SplineKind::natural}) {
    EXPECT_EQ(splineKindNamed(splineKindName(kind)), kind);
  }
  EXPECT_EQ(std::string(splineKindName(SplineKind::catmullRom)), "catmull-rom");
  EXPECT_FALSE(splineKindNamed("cubic").has_value());
  EXPECT_FALSE(splineKindNamed("Bezier").has_value());
}

TEST(SplineTest, PointCountsFollowTheKind) {
  expectError(SplineKind::bezier, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}}, Rule::badPointCount, 4, "3n + 1");
  expectError(SplineKind::bezier, {{0, 0}, {1, 0}, {1, 1}}, Rule::badPointCount, 2, "3n + 1");
  expectError(SplineKind::quadratic, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, Rule::badPointCount, 3, "2n + 1");
  expectError(SplineKind::quadratic, {{0, 0}}, Rule::badPointCount, 0, "2n + 1");
  expectError(SplineKind::catmullRom, {{0, 0}}, Rule::tooFewPoints, 0, "at least 2");
  expectError(SplineKind::natural, {}, Rule::tooFewPoints, 0, "at least 2");
  EXPECT_NO_THROW(Spline(SplineKind::bezier, std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  EXPECT_NO_THROW(Spline(SplineKind::quadratic, std::vector<Point2>{{0, 0}, {1, 0}, {0, 1}}));
}

TEST(SplineTest, PointsMustBeFiniteAndInRange) {
  expectError(SplineKind::natural, {{0, 0}, {NAN, 1}, {0, 2}}, Rule::nonFinite, 1, "spline point 1");
  expectError(SplineKind::bezier, {{0, 0}, {1, INFINITY}, {1, 1}, {0, 1}}, Rule::nonFinite, 1, "finite");
  expectError(SplineKind::catmullRom, {{0, 0}, {0x1p61, 1}}, Rule::outOfRange, 1, "2^60");
  expectError(SplineKind::natural, {{0, 0}, {1e-300, 1e-300}}, Rule::outOfRange, 0, "below 2^-60");
}

TEST(SplineTest, RadiusMustBeNonNegativeWhereTheCurvePasses) {
  expectError(SplineKind::catmullRom, {{0, 0}, {-0.1, 1}, {0, 2}}, Rule::negativeRadius, 1, "r must be >= 0");
  expectError(SplineKind::bezier, {{0, 0}, {1, 0}, {1, 1}, {-0.5, 1}}, Rule::negativeRadius, 3, "spline point 3");
  // A control point off the curve may lie beyond the axis while the curve stays on its side.
  EXPECT_NO_THROW(Spline(SplineKind::bezier, std::vector<Point2>{{0.5, 0}, {-0.1, 0.3}, {-0.1, 0.7}, {0.5, 1}}));
}

TEST(SplineTest, CurvesCrossingTheAxisAreRefused) {
  // r(u) = 0.5 (1 - u)^3 + 3 (1 - u)^2 u (-1) + 3 (1 - u) u^2 (-1) + 0.5 u^3 reaches -0.25 at u = 1/2.
  expectError(SplineKind::bezier, {{0.5, 0}, {-1, 0.3}, {-1, 0.7}, {0.5, 1}}, Rule::crossesAxis, 0, "crosses the axis");
  // A quadratic from the axis heading into r < 0.
  expectError(SplineKind::quadratic, {{0, 0}, {-0.5, 0.5}, {0.2, 1}}, Rule::crossesAxis, 0, "r = -");
  // An interpolating curve overshooting the axis between points near it.
  expectError(SplineKind::natural, {{1, 0}, {0.001, 0.1}, {1, 0.2}, {0.001, 0.3}, {1, 0.4}}, Rule::crossesAxis, 0,
              "crosses the axis");
  // The same at r near 1e-230 (found by fuzzing): r(u) = 3 (1 - u)^2 u r1 + 3 (1 - u) u^2 r2 + u^3 r3 with
  // r1 = -2.8e-230 and r2, r3 below 1e-270 is about 3 u r1 < 0 just after u = 0. The turn of r must still be
  // found, though the derivative's discriminant (squares near 1e-460) underflows unless scaled.
  expectError(SplineKind::bezier,
              {{0.0, -0.5},
               {-2.834798116031923e-230, 0.1326082449197723},
               {3.2702877e-317, 4.172015059619754e-309},
               {1.267508284076368e-279, 3.642300968118686e-217}},
              Rule::crossesAxis, 0, "crosses the axis");
}

TEST(SplineTest, CurvesTouchingTheAxisBetweenTheirPointsAreRefused) {
  // The middle piece (1, 0), (-1, 0.5), (1, 1) has r = (1 - u)^2 - 2 u (1 - u) + u^2 = (1 - 2u)^2:
  // it touches the axis at u = 1/2, between the points the curve passes through.
  expectError(SplineKind::quadratic, {{0, 0}, {0.5, 0}, {1, 0}, {-1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}}, Rule::crossesAxis,
              2, "touches the axis");
  // Reaching the axis at a point the curve passes through stays valid (a pole).
  EXPECT_NO_THROW(Spline(SplineKind::quadratic, std::vector<Point2>{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0.5, 1}, {0, 1}}));
  // And a curve coming within 1e-6 of the axis (r = (1 - 2u)^2 + 4e-6 u (1 - u)) does not touch it.
  EXPECT_NO_THROW(Spline(SplineKind::quadratic,
                         std::vector<Point2>{{0, 0}, {0.5, 0}, {1, 0}, {-1 + 2e-6, 0.5}, {1, 1}, {0.5, 1}, {0, 1}}));
}

TEST(SplineTest, CurvesLyingOnTheAxisAreRefused) {
  // Every point at r = 0: each kind's pieces have r = 0 all along, a surface of no area (r never
  // turns there, so the test for touching the axis at a turn of r does not see it).
  expectError(SplineKind::quadratic, {{0, 0}, {0, 0.5}, {0, 1}}, Rule::crossesAxis, 0, "lies on the axis");
  expectError(SplineKind::bezier, {{0, 0}, {0, 0.3}, {0, 0.6}, {0, 1}}, Rule::crossesAxis, 0, "lies on the axis");
  expectError(SplineKind::catmullRom, {{0, 0}, {0, 0.5}, {0, 1}}, Rule::crossesAxis, 0, "lies on the axis");
  expectError(SplineKind::natural, {{0, 0}, {0, 0.5}, {0, 1}}, Rule::crossesAxis, 0, "lies on the axis");
  // One piece on the axis among others (a quadratic's second piece from (0, 1) up to (0, 2)).
  expectError(SplineKind::quadratic, {{0, 0}, {1, 0.5}, {0, 1}, {0, 1.5}, {0, 2}}, Rule::crossesAxis, 2,
              "lies on the axis");
}

TEST(SplineTest, InterpolatingKindsRefuseRepeatedPoints) {
  expectError(SplineKind::catmullRom, {{0, 0}, {1, 1}, {1, 1}, {0, 2}}, Rule::segmentTooShort, 2, "repeats point 1");
  expectError(SplineKind::natural, {{0, 0}, {0, 0}, {0, 2}}, Rule::segmentTooShort, 1, "chords");
  // Bezier kinds take repeated control points: a piece whose inner points repeat its ends is straight.
  EXPECT_NO_THROW(Spline(SplineKind::bezier, std::vector<Point2>{{0, 0}, {0, 0}, {1, 1}, {1, 1}}));
  expectError(SplineKind::bezier, {{0, 0}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}}, Rule::segmentTooShort, 3,
              "below 2^-60");
}

TEST(SplineTest, SelfIntersectionsAreRefused) {
  // Two pieces crossing like an X.
  expectError(SplineKind::bezier, {{0, 0}, {0.3, 0.3}, {0.6, 0.6}, {1, 1}, {1, 0.6}, {0.4, 0.3}, {0, 1}},
              Rule::selfIntersecting, 0, "cross or touch");
  // One piece looping over itself.
  expectError(SplineKind::bezier, {{0.5, 0}, {2, 1}, {-0.5 + 0.5, 1}, {1.5, 0}}, Rule::selfIntersecting, 0,
              "crosses or touches itself");
  // A cusp: the curve turns back on itself at a join.
  expectError(SplineKind::bezier, {{0, 0}, {0.3, 0.3}, {0.6, 0.6}, {1, 1}, {0.7, 0.7}, {0.4, 0.4}, {0.2, 0.2}},
              Rule::selfIntersecting, 0, "cusp");
  // Touching: the end of a hook resting on the curve.
  expectError(SplineKind::bezier, {{0, 0}, {0.3, 0}, {0.7, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 0}},
              Rule::selfIntersecting, 0, "cross or touch");
}

TEST(SplineTest, CurvesRunningWithinRoundingOfThemselvesAreRefusedQuickly) {
  // Found by fuzzing: quadratic pieces folding up and down along the axis, 1e-12 apart over much of
  // their length (2^-39 of the extent), where sub-parts separate only when about that small: the
  // check used to subdivide without end; it must refuse them (and end).
  expectError(SplineKind::quadratic,
              {{0.0, 0.4375},
               {0.0, 2.091837814077735e-11},
               {8.185452315956354e-12, 0.125},
               {0.0, -1.3642420526593924e-11},
               {0.0, 0.4375},
               {0.0, 2.091837814077735e-11},
               {8.185452315956354e-12, 0.125},
               {0.0, 0.0},
               {0.0, 0.500000000001819},
               {0.0, 0.0625},
               {0.500000000001819, 0.0}},
              Rule::selfIntersecting, 0, "run that close for long");
}

// A hairpin: out from the axis just above z = 0 and back just below it. The halves meet only at
// the turn, on either side of its z, but 2e-300 apart they run within rounding of each other, and
// points computed on them cross (found by fuzzing, as a curve 1e-13 long with subnormal z).
TEST(SplineTest, HairpinsNarrowerThanRoundingAreRefused) {
  expectError(SplineKind::bezier, {{0, 1e-300}, {1, 1e-300}, {1, -1e-300}, {0, -1e-300}}, Rule::selfIntersecting, 0,
              "crosses or touches itself");
  expectError(SplineKind::bezier, {{0, 1e-14}, {1, 1e-14}, {1, -1e-14}, {0, -1e-14}}, Rule::selfIntersecting, 0,
              "crosses or touches itself");
  // 2e-6 wide it is a thin disc, far above rounding.
  EXPECT_NO_THROW(Spline(SplineKind::bezier, std::vector<Point2>{{0, 1e-6}, {1, 1e-6}, {1, -1e-6}, {0, -1e-6}}));
}

// Found by fuzzing: a join 8.4e-323 from the axis, the first piece arriving from below, the second
// leaving towards a control point 1.8e-315 away along r and then rising. Since hairpins (above) are
// no longer passed on their boxes alone, only the cones from the join can part it, and their angles
// came from cross and dot products that underflowed to 0: the join was taken for a cusp. Directions
// are now scaled first, and the cones (below, and from r towards z) are apart.
TEST(SplineTest, ACornerLeavingAlongASubnormalControlOffsetIsValid) {
  EXPECT_NO_THROW(Spline(SplineKind::bezier, std::vector<Point2>{{0x1p-463, -0x1.197990071ea11p-41},
                                                                 {0x1.36e89edf33b47p-42, 0x1.50056162dea11p-319},
                                                                 {0x1.8051e1010100ap-861, -0x1.3003f1e10181p-42},
                                                                 {0x0.0000000000011p-1022, 0x0p+0},
                                                                 {0x0.00000162dea11p-1022, 0x0p+0},
                                                                 {0x1.0000000000005p-47, 0x1.19799812dea11p-41},
                                                                 {0x0p+0, 0x1.19799812dea11p-41}}));
}

TEST(SplineTest, NearlyTouchingPartsAndSharpCornersAreValid) {
  // A thin wall: up the outside and down the inside 1e-6 apart, a sharp rim between.
  EXPECT_NO_THROW(Spline(
      SplineKind::bezier,
      std::vector<Point2>{{0, 0}, {0.3, 0}, {0.5, 0.4}, {0.5, 1}, {0.5 - 1e-6, 0.6}, {0.3 - 1e-6, 1e-6}, {0, 1e-6}}));
  // Every closed test spline.
  for (const testing::NamedSpline& s : testing::closedSplines()) {
    EXPECT_NO_THROW({
      const Spline spline(s.kind, s.points);
      EXPECT_TRUE(spline.closed()) << s.name;
    }) << s.name;
  }
}

TEST(SplineTest, QuadraticPiecesAreRaisedToCubicsOfTheSameCurve) {
  const std::vector<Point2> points{{0, 0}, {1, 0.5}, {0.5, 1}, {0.2, 1.5}, {0.7, 2}};
  const Spline spline(SplineKind::quadratic, points);
  ASSERT_EQ(spline.pieceCount(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(spline.pieceStart(i), 2 * i);
    for (double u = 0; u <= 1; u += 0.125) {
      const Point2 a = points[2 * i], m = points[2 * i + 1], b = points[2 * i + 2];
      const double v = 1 - u;
      const Point2 expected{v * v * a.r + 2 * u * v * m.r + u * u * b.r, v * v * a.z + 2 * u * v * m.z + u * u * b.z};
      const Point2 got = spline.at(i, u);
      EXPECT_NEAR(got.r, expected.r, 1e-15);
      EXPECT_NEAR(got.z, expected.z, 1e-15);
    }
  }
}

TEST(SplineTest, CatmullRomPassesThroughItsPointsWithCentripetalTangents) {
  const std::vector<Point2> p{{0, 0}, {0.3, 0.05}, {0.5, 0.4}, {0.35, 0.8}, {0.4, 1.2}};
  const Spline spline(SplineKind::catmullRom, p);
  ASSERT_EQ(spline.pieceCount(), 4u);
  const std::span<const Point2> c = spline.bezier();
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(c[3 * i].r, p[i].r);
    EXPECT_EQ(c[3 * i].z, p[i].z);
  }
  // The tangent at an inner point, from the knots t_{i+1} - t_i = |p_{i+1} - p_i|^(1/2) (Barry and
  // Goldman's pyramid differentiated at t_i), equals 3 (c_{3i+1} - c_{3i}) / (t_{i+1} - t_i).
  const auto d = [&](std::size_t i) { return std::sqrt(std::hypot(p[i + 1].r - p[i].r, p[i + 1].z - p[i].z)); };
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const double d0 = d(i - 1), d1 = d(i);
    for (int axis = 0; axis < 2; ++axis) {
      const auto x = [&](std::size_t k) { return axis == 0 ? p[k].r : p[k].z; };
      const auto y = [&](std::size_t k) { return axis == 0 ? c[k].r : c[k].z; };
      const double tangent = (x(i) - x(i - 1)) / d0 - (x(i + 1) - x(i - 1)) / (d0 + d1) + (x(i + 1) - x(i)) / d1;
      EXPECT_NEAR(3 * (y(3 * i + 1) - y(3 * i)) / d1, tangent, 1e-12);
      EXPECT_NEAR(3 * (y(3 * i) - y(3 * i - 1)) / d0, tangent, 1e-12);  // C1 across the join
    }
  }
  // Open ends leave along the first and last chords, a third of the way.
  EXPECT_NEAR(c[1].r, p[0].r + (p[1].r - p[0].r) / 3, 1e-15);
  EXPECT_NEAR(c[1].z, p[0].z + (p[1].z - p[0].z) / 3, 1e-15);
  EXPECT_NEAR(c[c.size() - 2].z, p.back().z + (p[p.size() - 2].z - p.back().z) / 3, 1e-15);
}

// Second derivative of piece i at an end (u = 0 or 1), per unit chord parameter (piece length h).
Point2 secondDerivative(std::span<const Point2> c, std::size_t i, bool atEnd, double h) {
  const Point2* q = &c[3 * i];
  const Point2 a = atEnd ? q[1] : q[0], b = atEnd ? q[2] : q[1], e = atEnd ? q[3] : q[2];
  return {6 * (a.r - 2 * b.r + e.r) / (h * h), 6 * (a.z - 2 * b.z + e.z) / (h * h)};
}

TEST(SplineTest, NaturalSplineIsC2ThroughItsPointsWithFreeEnds) {
  const std::vector<Point2> p{{0, 0}, {0.3, 0.05}, {0.5, 0.4}, {0.35, 0.8}, {0.4, 1.2}, {0.1, 1.3}};
  const Spline spline(SplineKind::natural, p);
  const std::span<const Point2> c = spline.bezier();
  const auto h = [&](std::size_t i) { return std::hypot(p[i + 1].r - p[i].r, p[i + 1].z - p[i].z); };
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(c[3 * i].r, p[i].r);
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    // C1 and C2 across each inner point, in the chord-length parameter.
    EXPECT_NEAR(3 * (c[3 * i].r - c[3 * i - 1].r) / h(i - 1), 3 * (c[3 * i + 1].r - c[3 * i].r) / h(i), 1e-12);
    const Point2 before = secondDerivative(c, i - 1, true, h(i - 1)), after = secondDerivative(c, i, false, h(i));
    EXPECT_NEAR(before.r, after.r, 1e-9);
    EXPECT_NEAR(before.z, after.z, 1e-9);
  }
  // Free ends: zero second derivative.
  const Point2 start = secondDerivative(c, 0, false, h(0)),
               end = secondDerivative(c, p.size() - 2, true, h(p.size() - 2));
  EXPECT_NEAR(start.r, 0, 1e-9);
  EXPECT_NEAR(start.z, 0, 1e-9);
  EXPECT_NEAR(end.r, 0, 1e-9);
  EXPECT_NEAR(end.z, 0, 1e-9);
}

TEST(SplineTest, ClosedInterpolatingSplinesArePeriodic) {
  std::vector<Point2> p;
  for (int i = 0; i <= 7; ++i) p.push_back({0.7 + 0.3 * std::cos(i * 2 * M_PI / 7), 0.5 * std::sin(i * 2 * M_PI / 7)});
  p.back() = p.front();
  const std::size_t m = p.size() - 1;
  const auto h = [&](std::size_t i) { return std::hypot(p[i + 1].r - p[i].r, p[i + 1].z - p[i].z); };
  for (const SplineKind kind : {SplineKind::catmullRom, SplineKind::natural}) {
    const Spline spline(kind, p);
    EXPECT_TRUE(spline.closed());
    const std::span<const Point2> c = spline.bezier();
    // Across the closing join: the same direction (C1 in the kind's parameter).
    const Point2 out{c[1].r - c[0].r, c[1].z - c[0].z}, in{c[3 * m].r - c[3 * m - 1].r, c[3 * m].z - c[3 * m - 1].z};
    EXPECT_NEAR(out.r * in.z - out.z * in.r, 0, 1e-12) << splineKindName(kind);
    EXPECT_GT(out.r * in.r + out.z * in.z, 0) << splineKindName(kind);
    if (kind == SplineKind::natural) {  // and, in the chord-length parameter, C1 and C2
      EXPECT_NEAR(out.r / h(0), in.r / h(m - 1), 1e-12);
      const Point2 before = secondDerivative(c, m - 1, true, h(m - 1)), after = secondDerivative(c, 0, false, h(0));
      EXPECT_NEAR(before.r, after.r, 1e-9);
      EXPECT_NEAR(before.z, after.z, 1e-9);
    }
  }
}

TEST(SplineTest, ALinearSplineIsItsPolyline) {
  const std::vector<Point2> p{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Spline spline(SplineKind::linear, p);
  EXPECT_EQ(spline.points().size(), 4u);  // the repeat dropped, with a warning, as Profile does
  ASSERT_EQ(spline.warnings().size(), 1u);
  EXPECT_EQ(spline.pieceCount(), 3u);
  EXPECT_EQ(spline.pieceStart(2), 3u);
  expectError(SplineKind::linear, {{0, 0}, {1, 1}, {1, 0}, {0, 1}}, Rule::selfIntersecting, 0, "intersect");
  const Shape shape(spline);
  EXPECT_EQ(shape.spline(), nullptr);  // traced as the polyline
  EXPECT_EQ(shape.profile().points().size(), 4u);
}

TEST(SplineTest, BezierKindKeepsItsControlPointsOnce) {
  // Its points are its control points: bezier() gives the given points, in a copy of the spline
  // too (what a Shape keeps), and the spline holds them once.
  const std::vector<Point2> p{{0.5, 0}, {1, 0.25}, {1, 0.75}, {0.5, 1}, {0.25, 1.25}, {0.25, 1.5}, {0, 2}};
  const Spline spline(SplineKind::bezier, p);
  const Spline copy = spline;
  for (const Spline* s : {&spline, &copy}) {
    ASSERT_EQ(s->bezier().size(), p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      EXPECT_EQ(s->bezier()[i].r, p[i].r) << i;
      EXPECT_EQ(s->bezier()[i].z, p[i].z) << i;
    }
    EXPECT_EQ(s->pieceCount(), 2u);
    EXPECT_EQ(s->at(1, 1.0).z, 2.0);
  }
  EXPECT_EQ(spline.memoryBytes(), p.size() * sizeof(Point2));
  const Shape shape(spline);
  ASSERT_NE(shape.spline(), nullptr);
  EXPECT_EQ(shape.spline()->bezier().size(), p.size());
  EXPECT_EQ(shape.spline()->bezier().back().z, 2.0);
}

TEST(SplineTest, ShapesReportTheirParts) {
  const Spline sphere(SplineKind::bezier, testing::bezierSphere(1.0, 4));
  const Shape shape(sphere);
  ASSERT_NE(shape.spline(), nullptr);
  // Each quarter's two arcs are monotone already: the parts are the pieces, the knots their ends.
  EXPECT_EQ(shape.profile().segmentCount(), 4u);
  for (std::uint32_t k = 0; k < 4; ++k) EXPECT_EQ(shape.splinePiece(k), k);
  // A torus circle in 3 arcs of 120 degrees: each arc turns through an extremum of r or z and splits.
  const Shape torus{Spline(SplineKind::bezier, testing::bezierTorus(0.6, 0.25, 3))};
  EXPECT_EQ(torus.profile().segmentCount(), 6u);
  // Its arcs start at 0, 120 and 240 degrees: one turn inside each (at 90, 180, 270), two parts each.
  for (std::uint32_t k = 0; k < 6; ++k) EXPECT_EQ(torus.splinePiece(k), k / 2) << "part " << k;
  // Arc length: a quarter of the sphere's circumference over its half.
  EXPECT_NEAR(shape.profile().arcLength().back(), M_PI, 1e-5);
  EXPECT_THROW(Shape(sphere, BuildOptions{.method = Method::kajiya}), std::invalid_argument);
}

// Every part is named after a piece that holds it: its ends (the profile's points k and k + 1) lie in
// the box of that piece's control points (the curve lies in their hull), within a few roundings;
// the pieces follow the curve's order, and each has a part.
TEST(SplineTest, EachPartsPieceHoldsIt) {
  for (const testing::NamedSpline& s : testing::closedSplines()) {
    SCOPED_TRACE(s.name);
    const Spline spline(s.kind, s.points);
    const Shape shape(spline);
    const std::span<const Point2> b = spline.bezier(), points = shape.profile().points();
    double extent = 0.0;
    for (const Point2& p : b) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
    // A few roundings of values up to 2 extents (de Casteljau's split points, z - centre + centre).
    const double rounding = 0x1p-48 * extent;
    std::uint32_t previous = 0;
    for (std::uint32_t k = 0; k < shape.profile().segmentCount(); ++k) {
      const std::uint32_t piece = shape.splinePiece(k);
      ASSERT_LT(piece, spline.pieceCount()) << "part " << k;
      EXPECT_TRUE(piece == previous || piece == previous + 1) << "part " << k << ": piece " << piece;
      previous = piece;
      for (const Point2& p : {points[k], points[k + 1]}) {
        bool inside = true;
        for (const auto coordinate : {&Point2::r, &Point2::z}) {
          double low = b[3 * piece].*coordinate, high = low;
          for (int i = 1; i < 4; ++i) {
            low = std::min(low, b[3 * piece + i].*coordinate);
            high = std::max(high, b[3 * piece + i].*coordinate);
          }
          inside = inside && p.*coordinate >= low - rounding && p.*coordinate <= high + rounding;
        }
        EXPECT_TRUE(inside) << "part " << k << " (piece " << piece << ") ends at r = " << p.r << ", z = " << p.z;
      }
    }
    EXPECT_EQ(shape.splinePiece(0), 0u);
    EXPECT_EQ(previous, spline.pieceCount() - 1);
  }
}

}  // namespace
}  // namespace revolve
