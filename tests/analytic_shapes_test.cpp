// The library against closed-form answers: profiles that are exactly a cylinder, a cone, an apex
// cone and a disc, and polylines inscribed in a sphere and a torus, whose surfaces must lie between
// the analytic surface and its inner offset by the polyline's sagitta.
#include "support/reference.h"
#include "support/test_profiles.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace revolve {
namespace {

using reference::RefHit;
using reference::RefRay;

RefRay toRef(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

double length(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

// |cos| of the angle between the ray and the reference hit's normal.
double incidence(const Ray& ray, const RefHit& hit) {
  return std::abs(double(hit.nx * ray.direction.x + hit.ny * ray.direction.y + hit.nz * ray.direction.z)) /
         length(ray.direction);
}

// Whether the reference's hit/miss verdict flips when the ray's origin moves by 1e-9 of the shape's
// size along any axis: then the ray is within rounding of a silhouette or an edge, and either
// answer is right. 1e-9 is far above the kernel's double-precision error (~1e-15) and far below
// the float input's own resolution (~6e-8).
bool ambiguous(const std::function<std::optional<RefHit>(const RefRay&)>& truth, const Ray& ray, double size) {
  const RefRay base = toRef(ray);
  const bool hit = truth(base).has_value();
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      RefRay moved = base;
      (axis == 0 ? moved.ox : axis == 1 ? moved.oy : moved.oz) += sign * 1e-9 * size;
      if (truth(moved).has_value() != hit) return true;
    }
  }
  return false;
}

// Error bound of a float t from the double kernel (see meridian_ray.h): rounding to float (half an
// ulp, 2^-24 relative; counted twice for room) plus the kernel's own error, a few u R along the
// surface normal, i.e. 2^-40 R / (|d| cos) along the ray (generous by 2^10).
double tBound(double t, double size, const Ray& ray, double cosine) {
  return 0x1p-23 * std::abs(t) + 0x1p-40 * size / (length(ray.direction) * std::max(cosine, 1e-6));
}

struct Comparison {
  std::size_t hits = 0, misses = 0;
  // Disagreements within a 1e-9 nudge of the verdict flipping, among the incoherent rays and among
  // the awkward ones (aimed at vertex heights and the axis: edges by design).
  std::size_t ambiguousIncoherent = 0, ambiguousAwkward = 0;
};

// Compares intersect() with a closed form on incoherent and axis-aligned rays.
Comparison compareWithClosedForm(const std::vector<Point2>& points,
                                 const std::function<std::optional<RefHit>(const RefRay&)>& truth, std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 random(seed);
  const Shape shape{Profile(points)};
  const double size = length(shape.bounds().upper);
  constexpr std::size_t kIncoherent = 20000;
  std::vector<Ray> rays = testing::incoherentRays(shape, random, kIncoherent);
  const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 4000);
  rays.insert(rays.end(), awkward.begin(), awkward.end());
  Comparison result;
  int reported = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Ray& ray = rays[i];
    const std::optional<Hit> got = intersect(shape, ray);
    const std::optional<RefHit> expected = truth(toRef(ray));
    if (got.has_value() != expected.has_value()) {
      if (ambiguous(truth, ray, size)) {
        ++(i < kIncoherent ? result.ambiguousIncoherent : result.ambiguousAwkward);
        continue;
      }
      if (++reported <= 5) {
        ADD_FAILURE() << "o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                      << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << "): closed form "
                      << (expected ? "hits at t=" + std::to_string(double(expected->t)) : std::string("misses"))
                      << ", library " << (got ? "hits at t=" + std::to_string(got->t) : std::string("misses"));
      }
      continue;
    }
    if (!expected) {
      ++result.misses;
      continue;
    }
    ++result.hits;
    const double cosine = incidence(ray, *expected);
    EXPECT_NEAR(got->t, double(expected->t), tBound(double(expected->t), size, ray, cosine));
    // The normal of a cylinder or cone depends on the azimuth alone, which is ill-conditioned
    // near the axis; elsewhere it is the closed form's, rounded to float.
    if (std::hypot(got->point.x, got->point.y) > 1e-3 * size) {
      EXPECT_NEAR(got->normal.x, double(expected->nx), 1e-6);
      EXPECT_NEAR(got->normal.y, double(expected->ny), 1e-6);
      EXPECT_NEAR(got->normal.z, double(expected->nz), 1e-6);
    }
  }
  return result;
}

TEST(AnalyticShapesTest, VerticalSegmentIsACylinder) {
  const std::vector<Point2> points{{0.75, -0.5}, {0.75, 1.25}};
  const Comparison c = compareWithClosedForm(
      points, [](const RefRay& ray) { return reference::intersectCylinder(0.75L, -0.5L, 1.25L, ray); }, 1);
  EXPECT_GT(c.hits, 5000u);
  EXPECT_GT(c.misses, 2000u);
  EXPECT_LE(c.ambiguousIncoherent, 20u);  // random rays rarely pass within 1e-9 of an edge
}

TEST(AnalyticShapesTest, ObliqueSegmentIsATruncatedCone) {
  const std::vector<Point2> points{{1.0, -0.5}, {0.25, 1.0}};
  const Comparison c = compareWithClosedForm(
      points, [](const RefRay& ray) { return reference::intersectCone(1.0L, -0.5L, 0.25L, 1.0L, ray); }, 2);
  EXPECT_GT(c.hits, 5000u);
  EXPECT_LE(c.ambiguousIncoherent, 20u);
}

TEST(AnalyticShapesTest, SegmentFromTheAxisIsAConeWithItsApex) {
  // Apex at (0, 0, 1), opening downwards to radius 0.5 at z = 0: its mirror nappe above the apex
  // must never be hit, and rays through the apex must be.
  const std::vector<Point2> points{{0.0, 1.0}, {0.5, 0.0}};
  const Comparison c = compareWithClosedForm(
      points, [](const RefRay& ray) { return reference::intersectCone(0.0L, 1.0L, 0.5L, 0.0L, ray); }, 3);
  EXPECT_GT(c.hits, 5000u);
  EXPECT_LE(c.ambiguousIncoherent, 20u);
}

TEST(AnalyticShapesTest, HorizontalSegmentIsADiscOrAnAnnulus) {
  const std::vector<Point2> disc{{0.0, 0.25}, {1.0, 0.25}};
  compareWithClosedForm(
      disc, [](const RefRay& ray) { return reference::intersectDisc(0.25L, 0.0L, 1.0L, ray); }, 4);
  const std::vector<Point2> annulus{{0.8, -0.25}, {0.3, -0.25}};
  const Comparison c = compareWithClosedForm(
      annulus, [](const RefRay& ray) { return reference::intersectDisc(-0.25L, 0.8L, 0.3L, ray); }, 5);
  EXPECT_GT(c.hits, 3000u);
}

TEST(AnalyticShapesTest, HandPickedHitsOfACappedCylinder) {
  // r = 1, z in [0, 2], listed bottom (axis) -> rim -> top rim -> top (axis): normals point out.
  const Shape shape{Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 2}, {0, 2}})};
  const auto hit = [&](Vec3 o, Vec3 d) { return intersect(shape, {o, d}); };
  // From x = -5 along +x at mid height: the side at x = -1, t = 4, normal -x, u = 1/2 (phi = pi),
  // v = (1 + 1) / 4 (bottom disc 1, half the side 1, total length 4).
  const auto side = hit({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(side);
  EXPECT_EQ(side->t, 4.0f);
  EXPECT_EQ(side->normal.x, -1.0f);
  EXPECT_EQ(side->u, 0.5f);
  EXPECT_EQ(side->v, 0.5f);
  EXPECT_EQ(side->segment, 1u);
  // Down the axis from z = 5 with a direction of length 2: the top disc at t = 3 / 2.
  const auto top = hit({0, 0, 5}, {0, 0, -2});
  ASSERT_TRUE(top);
  EXPECT_EQ(top->t, 1.5f);
  EXPECT_EQ(top->normal.z, 1.0f);
  EXPECT_EQ(top->segment, 2u);
  // From inside, along +y: the side at t = 1 with the outward normal +y, u = 1/4.
  const auto inside = hit({0, 0, 1}, {0, 1, 0});
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->t, 1.0f);
  EXPECT_EQ(inside->normal.y, 1.0f);
  EXPECT_EQ(inside->u, 0.25f);
  // tnear beyond the first hit finds the second; tfar before the first finds nothing.
  const auto second = intersect(shape, {{-5, 0, 1}, {1, 0, 0}, 4.5f});
  ASSERT_TRUE(second);
  EXPECT_EQ(second->t, 6.0f);
  EXPECT_FALSE(intersect(shape, {{-5, 0, 1}, {1, 0, 0}, 0.0f, 3.5f}));
  EXPECT_TRUE(intersect(shape, {{-5, 0, 1}, {1, 0, 0}, 0.0f, 4.0f}));  // tfar is inclusive
  // Degenerate rays miss rather than fail.
  EXPECT_FALSE(intersect(shape, {{-5, 0, 1}, {0, 0, 0}}));
  EXPECT_FALSE(intersect(shape, {{NAN, 0, 1}, {1, 0, 0}}));
  EXPECT_FALSE(intersect(shape, {{-5, 0, 1}, {1, 0, 0}, 2.0f, 1.0f}));
}

// A polyline inscribed in a circle stays between the circle and the concentric circle shrunk by
// its sagitta, 1 - cos(step / 2) of the radius; so does the swept surface, between two spheres or
// two tori. Rays meeting the inner surface must hit the polyline's between the two surfaces'
// hits; rays missing the outer surface must miss.
void checkBetween(const Shape& shape, const std::function<std::optional<RefHit>(const RefRay&)>& outer,
                  const std::function<std::optional<RefHit>(const RefRay&)>& inner, std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 random(seed);
  std::size_t bracketed = 0;
  const double size = length(shape.bounds().upper);
  for (const Ray& ray : testing::incoherentRays(shape, random, 20000)) {
    const std::optional<Hit> got = intersect(shape, ray);
    const std::optional<RefHit> out = outer(toRef(ray)), in = inner(toRef(ray));
    if (!out) {
      if (!ambiguous(outer, ray, size)) {
        EXPECT_FALSE(got.has_value());
      }
      continue;
    }
    if (!in || ambiguous(inner, ray, size)) continue;
    ASSERT_TRUE(got.has_value());
    const double slack = tBound(double(in->t), size, ray, 1e-3);
    EXPECT_GE(got->t, double(out->t) - slack);
    EXPECT_LE(got->t, double(in->t) + slack);
    ++bracketed;
  }
  EXPECT_GT(bracketed, 5000u);
}

TEST(AnalyticShapesTest, SphereLikePolylineLiesBetweenTwoSpheres) {
  const int segments = 1000;
  const Shape shape{Profile(testing::sphereLike(1.0, segments))};
  // The test profile rounds its vertices to float (up to 2^-24 off the circle): both bounding
  // radii are widened by that.
  const long double sagitta = 1 - std::cos(std::numbers::pi_v<long double> / (2 * segments));
  const long double slack = 0x1p-23L;
  checkBetween(
      shape, [&](const RefRay& ray) { return reference::intersectSphere(0, 1 + slack, ray); },
      [&](const RefRay& ray) { return reference::intersectSphere(0, 1 - sagitta - slack, ray); }, 6);
}

TEST(AnalyticShapesTest, TorusLikePolylineLiesBetweenTwoTori) {
  const int segments = 400;
  const Shape shape{Profile(testing::torusLike(1.0, 0.35, segments))};
  const long double sagitta = 0.35L * (1 - std::cos(std::numbers::pi_v<long double> / segments));
  const long double slack = 0x1p-23L;
  checkBetween(
      shape, [&](const RefRay& ray) { return reference::intersectTorus(1, 0.35L + slack, ray); },
      [&](const RefRay& ray) { return reference::intersectTorus(1, 0.35L - sagitta - slack, ray); }, 7);
}

TEST(ClosestPointTest, MatchesTheOraclesMeridianDistanceAndLiesOnTheSurface) {
  // The closest point of every standard profile's surface to random points, against the oracle's
  // long-double distance; the point returned must itself lie on the surface, at that distance.
  std::mt19937_64 random(8);
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    SCOPED_TRACE(named.name);
    const Shape shape{Profile(named.points)};
    const Bounds box = shape.bounds();
    std::uniform_real_distribution<float> x(-2 * box.upper.x, 2 * box.upper.x), z(2 * box.lower.z, 2 * box.upper.z);
    for (int i = 0; i < 2000; ++i) {
      const Vec3 p{x(random), x(random), z(random)};
      const SurfacePoint closest = closestPoint(shape, p);
      const double expected = double(reference::meridianDistance(named.points, p.x, p.y, p.z));
      const double size = length(box.upper);
      // Computed in double, rounded to float: a few float ulps of the size.
      EXPECT_NEAR(closest.distance, expected, 4 * 0x1p-24 * (expected + size));
      EXPECT_NEAR(double(reference::meridianDistance(named.points, closest.point.x, closest.point.y, closest.point.z)),
                  0.0, 4 * 0x1p-24 * size);
      EXPECT_NEAR(length({closest.point.x - p.x, closest.point.y - p.y, closest.point.z - p.z}), expected,
                  4 * 0x1p-24 * (expected + size));
    }
  }
  const Shape shape{Profile(testing::cup())};
  EXPECT_TRUE(std::isnan(closestPoint(shape, {NAN, 0, 0}).distance));
  EXPECT_TRUE(std::isnan(closestPoint(shape, {0, INFINITY, 0}).distance));
}

}  // namespace
}  // namespace revolve
