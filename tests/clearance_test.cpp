// Clearance in the meridian plane (revolve.h, "Clearance") against hand-derived closed forms (a
// pole, a cone, a table top over a robot, collisions with their depth), against a brute force
// that minimises the signed distance along every segment by golden-section search (it is convex
// there) instead of the library's case analysis, and against the long-double oracle's distance.
#include "support/reference.h"
#include "support/test_profiles.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace revolve {
namespace {

// Closed forms are evaluated in double from decimal inputs: a few ulps of the scene's size (~1).
constexpr double kClosedFormTolerance = 1e-14;

const Shape& pole() {  // radius 0.1, height 1: a closed capped cylinder (double coordinates)
  static const Shape shape{Profile(std::vector<Point2>{{0, 0}, {0.1, 0}, {0.1, 1}, {0, 1}})};
  return shape;
}

TEST(CylinderClearanceTest, PoleBesideAboveAndDiagonallyAway) {
  // Beside, overlapping heights: the gap is horizontal, d - a - R.
  EXPECT_NEAR(cylinderClearance(pole(), {1.0, 0.3, 0.1, 0.5}).clearance, 1.0 - 0.1 - 0.3, kClosedFormTolerance);
  // Above the pole's top disc (the robot's footprint covers it): the gap is vertical.
  EXPECT_NEAR(cylinderClearance(pole(), {0.2, 0.3, 1.25, 1.8}).clearance, 0.25, kClosedFormTolerance);
  // Beside and above: the top rim to the robot's bottom edge.
  EXPECT_NEAR(cylinderClearance(pole(), {1.0, 0.3, 1.5, 2.0}).clearance, std::hypot(0.6, 0.5), kClosedFormTolerance);
  // The closest profile point is on the side, at a height within the robot's, in the meridian.
  const CylinderClearance beside = cylinderClearance(pole(), {1.0, 0.3, 0.1, 0.5});
  EXPECT_DOUBLE_EQ(beside.point.r, 0.1);
  EXPECT_GE(beside.point.z, 0.1 - kClosedFormTolerance);
  EXPECT_LE(beside.point.z, 0.5 + kClosedFormTolerance);
}

TEST(CylinderClearanceTest, FlatEndsPassUnderATableTop) {
  // A disc of radius 0.5 at height 1 (a table top) over a robot 0.8 tall whose axis is 0.2 from the
  // table's: the gap is 0.2. A capsule (the axis segment's distance minus the radius) would report
  // 0.2 - 0.3 < 0, a collision that is not there.
  const Shape top{Profile(std::vector<Point2>{{0.0, 1.0}, {0.5, 1.0}})};
  EXPECT_NEAR(cylinderClearance(top, {0.2, 0.3, 0.0, 0.8}).clearance, 0.2, kClosedFormTolerance);
}

TEST(CylinderClearanceTest, CollisionsReportTheDeepestPenetration) {
  // The pole's side (r = 0.1) is 0.25 from the robot's axis at d = 0.35: 0.05 inside its side,
  // with 0.3 of height above and below.
  const CylinderClearance side = cylinderClearance(pole(), {0.35, 0.3, 0.2, 0.8});
  EXPECT_NEAR(side.clearance, -0.05, kClosedFormTolerance);
  EXPECT_DOUBLE_EQ(side.point.r, 0.1);
  // A robot around the pole's top (z from 0.8 to 1.2): the top disc (z = 1, r <= 0.1) lies 0.2 from
  // both its ends, depth min(0.3 - r, 0.2, 0.2) = 0.2; the side is no deeper.
  EXPECT_NEAR(cylinderClearance(pole(), {0.0, 0.3, 0.8, 1.2}).clearance, -0.2, kClosedFormTolerance);
  // Touching: the side at exactly the robot's radius.
  EXPECT_NEAR(cylinderClearance(pole(), {0.4, 0.3, 0.2, 0.8}).clearance, 0.0, kClosedFormTolerance);
  // Inside a closed shape without touching it is not a collision: surfaces are what count.
  const Shape drum{Profile(std::vector<Point2>{{0, 0}, {2, 0}, {2, 1}, {0, 1}})};
  EXPECT_NEAR(cylinderClearance(drum, {0.5, 0.3, 0.2, 0.7}).clearance, 0.2, kClosedFormTolerance);
}

TEST(CylinderClearanceTest, ConeSideApexAndCollision) {
  // A cone of base radius 0.5 and height 1: its side is the line 2r + z = 1 from (0.5, 0) to (0, 1).
  const Shape cone{Profile(std::vector<Point2>{{0.0, 0.0}, {0.5, 0.0}, {0.0, 1.0}})};
  // Robot at d = 1, R = 0.2, z in [0.5, 0.9]: its meridian rectangle's corner (0.8, 0.5) is nearest,
  // at (2 * 0.8 + 0.5 - 1) / sqrt(5) from the side, whose foot (0.36, 0.28) lies on the segment.
  const CylinderClearance side = cylinderClearance(cone, {1.0, 0.2, 0.5, 0.9});
  EXPECT_NEAR(side.clearance, 1.1 / std::sqrt(5.0), kClosedFormTolerance);
  EXPECT_NEAR(side.point.r, 0.36, kClosedFormTolerance);
  EXPECT_NEAR(side.point.z, 0.28, kClosedFormTolerance);
  // Over the apex: the gap from the apex (0, 1) up to the robot's bottom end at 1.2.
  EXPECT_NEAR(cylinderClearance(cone, {0.1, 0.2, 1.2, 1.5}).clearance, 0.2, kClosedFormTolerance);
  // Robot at d = 0.6, R = 0.2, z in [0.1, 0.3]: the side enters the rectangle [0.4, 0.8] x [0.1, 0.3];
  // along it r = (1 - z) / 2 and the depth is min(r - 0.4, z - 0.1, ...) = min(0.1 - z / 2, z - 0.1),
  // greatest where they meet, z = 2 / 15: depth 1 / 30.
  EXPECT_NEAR(cylinderClearance(cone, {0.6, 0.2, 0.1, 0.3}).clearance, -1.0 / 30.0, kClosedFormTolerance);
}

// The brute force: the signed distance function of the rectangle, minimised along each segment by
// golden-section search (valid because a convex set's signed distance is convex along a line).
double signedDistance(double rLow, double rHigh, double zLow, double zHigh, double r, double z) {
  const double dr = std::max(rLow - r, r - rHigh), dz = std::max(zLow - z, z - zHigh);
  if (dr <= 0 && dz <= 0) return std::max(dr, dz);
  return std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
}

double bruteForceClearance(std::span<const Point2> points, const UprightCylinder& c, MeridianScale scale) {
  const double rLow = c.axisDistance - c.radius, rHigh = c.axisDistance + c.radius;
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Point2 a{points[k].r * scale.radial, points[k].z * scale.axial};
    const Point2 b{points[k + 1].r * scale.radial, points[k + 1].z * scale.axial};
    const auto f = [&](double t) {
      return signedDistance(rLow, rHigh, c.zMin, c.zMax, a.r + t * (b.r - a.r), a.z + t * (b.z - a.z));
    };
    double lo = 0, hi = 1;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int i = 0; i < 100; ++i) {  // 0.618^100 ~ 1e-21: far below double resolution
      const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
      if (f(m1) <= f(m2)) {
        hi = m2;  // the minimum of a convex function lies left of m2
      } else {
        lo = m1;
      }
    }
    best = std::min({best, f(0), f(1), f(0.5 * (lo + hi))});
  }
  return best;
}

TEST(CylinderClearanceTest, AgreesWithABruteForceOnEveryStandardProfile) {
  std::mt19937_64 random(20261124);
  std::printf("seed 20261124\n");
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    SCOPED_TRACE(named.name);
    const Shape shape{Profile(named.points)};
    const Bounds box = shape.bounds();
    const double size = std::max(double(box.upper.x), double(box.upper.z) - box.lower.z);
    std::uniform_real_distribution<double> d(0, 2 * size), radius(0, size), z(box.lower.z - size, box.upper.z + size);
    std::uniform_real_distribution<double> factor(0.25, 4);
    const int cases = shape.profile().points().size() > 500 ? 40 : 200;
    for (int i = 0; i < cases; ++i) {
      double z0 = z(random), z1 = z(random);
      if (z0 > z1) std::swap(z0, z1);
      const UprightCylinder cylinder{d(random), i % 10 == 0 ? 0.0 : radius(random), z0, i % 7 == 0 ? z0 : z1};
      const MeridianScale scale =
          i % 3 == 0 ? MeridianScale{} : MeridianScale{factor(random), (i % 2 ? -1 : 1) * factor(random)};
      const double reach = size * std::max({1.0, scale.radial, std::abs(scale.axial)});
      const CylinderClearance got = cylinderClearance(shape, cylinder, scale);
      const double expected = bruteForceClearance(named.points, cylinder, scale);
      // Both in double from the same inputs: rounding of a few operations on values of the reach.
      EXPECT_NEAR(got.clearance, expected, 1e-12 * reach) << "case " << i;
      // The point returned realises the clearance.
      EXPECT_NEAR(signedDistance(cylinder.axisDistance - cylinder.radius, cylinder.axisDistance + cylinder.radius,
                                 cylinder.zMin, cylinder.zMax, got.point.r, got.point.z),
                  got.clearance, 1e-12 * reach);
    }
  }
}

TEST(CylinderClearanceTest, ScaleMatchesAProfileScaledBeforehand) {
  // The scaled search (boxes scaled on the fly) against a tree built on pre-scaled points; an
  // axial factor below zero against the profile mirrored in z.
  std::mt19937_64 random(5);
  const std::vector<Point2> vase = testing::hollowVase();
  const Shape shape{Profile(vase)};
  for (const MeridianScale scale : {MeridianScale{2.0, 0.5}, MeridianScale{0.7, -1.3}}) {
    std::vector<Point2> scaled;
    for (const Point2 p : vase) scaled.push_back({p.r * scale.radial, p.z * scale.axial});
    const Shape placed{Profile(scaled)};
    std::uniform_real_distribution<double> u(-3, 3);
    for (int i = 0; i < 200; ++i) {
      double z0 = u(random), z1 = u(random);
      if (z0 > z1) std::swap(z0, z1);
      const UprightCylinder c{std::abs(u(random)), std::abs(u(random)) / 3, z0, z1};
      EXPECT_NEAR(cylinderClearance(shape, c, scale).clearance, cylinderClearance(placed, c).clearance, 1e-12);
    }
  }
}

TEST(ClosestMeridianPointTest, MatchesTheOraclesDistance) {
  std::mt19937_64 random(11);
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    SCOPED_TRACE(named.name);
    const Shape shape{Profile(named.points)};
    const Bounds box = shape.bounds();
    std::uniform_real_distribution<double> r(0, 2 * box.upper.x), z(2 * box.lower.z, 2 * box.upper.z);
    for (int i = 0; i < 300; ++i) {
      const Point2 q{r(random), z(random)};
      const MeridianPoint closest = closestMeridianPoint(shape, q);
      const double expected = double(reference::meridianDistance(named.points, q.r, 0, q.z));
      const double size = box.upper.x + box.upper.z - box.lower.z;
      EXPECT_NEAR(closest.distance, expected, 1e-13 * size);
      EXPECT_NEAR(std::hypot(closest.point.r - q.r, closest.point.z - q.z), expected, 1e-13 * size);
    }
  }
}

TEST(CylinderClearanceTest, ViolatedPreconditionsGiveNaN) {
  const Shape& shape = pole();
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {-1, 0.3, 0, 1}).clearance));
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {1, -0.3, 0, 1}).clearance));
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {1, 0.3, 1, 0}).clearance));
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {NAN, 0.3, 0, 1}).clearance));
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {1, 0.3, 0, INFINITY}).clearance));
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {1, 0.3, 0, 1}, {0, 1}).clearance));
  EXPECT_TRUE(std::isnan(cylinderClearance(shape, {1, 0.3, 0, 1}, {1, 0}).clearance));
  EXPECT_TRUE(std::isnan(closestMeridianPoint(shape, {-1, 0}).distance));
  EXPECT_TRUE(std::isnan(closestMeridianPoint(shape, {1, NAN}).distance));
}

}  // namespace
}  // namespace revolve
