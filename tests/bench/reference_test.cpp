// The benchmark measures every method against SmoothProfile and ReferenceTracer, so they are
// checked here against closed forms: a sphere and a torus, whose distance, normal, inside/outside
// and ray intersections have textbook formulas, and polylines whose chords' sagittas are known.
#include "reference_tracer.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace revolve::bench {
namespace {

// The sphere shape: centre (0, 0, 0.5), radius 0.5. The torus shape: tube radius 0.15 about the
// circle of radius 0.35 in the plane z = 0.15.
constexpr double kSphereZ = 0.5, kSphereR = 0.5;
constexpr double kTorusMajor = 0.35, kTorusMinor = 0.15, kTorusZ = 0.15;

TEST(SmoothProfileTest, DistanceAndSignMatchTheSphereAndTheTorus) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> r(0.0, 1.0), z(-0.5, 1.5);
  const SmoothProfile sphere = sphereShape(), torus = torusShape();
  for (int i = 0; i < 20000; ++i) {
    const Point2 p{r(random), z(random)};
    const double toCentre = std::hypot(p.r, p.z - kSphereZ);
    const ClosestPoint s = sphere.closest(p);
    ASSERT_NEAR(s.signedDistance, toCentre - kSphereR, 1e-14) << p.r << ", " << p.z;
    const double tube = std::hypot(p.r - kTorusMajor, p.z - kTorusZ);
    const ClosestPoint t = torus.closest(p);
    ASSERT_NEAR(t.signedDistance, tube - kTorusMinor, 1e-14) << p.r << ", " << p.z;
    // The normal points away from the tube's centre line, outwards.
    ASSERT_NEAR(t.normal.r, (p.r - kTorusMajor) / tube, 1e-12);
    ASSERT_NEAR(t.normal.z, (p.z - kTorusZ) / tube, 1e-12);
  }
}

TEST(SmoothProfileTest, SignIsRightAroundCornersAndTheAxis) {
  // The vase has a sharp rim (a convex corner) and ends on the axis. Points just outside and
  // inside its flat top and its flat bottom, near the rim and near the axis.
  const SmoothProfile vase = vaseShape();
  const SmoothProfile::Extent e = vase.extent();
  const Point2 top = vase.pieces().back().start;                              // the rim
  EXPECT_GT(vase.closest({top.r + 1e-3, top.z + 1e-3}).signedDistance, 0.0);  // beyond the rim, diagonally
  EXPECT_GT(vase.closest({top.r * 0.5, e.zHigh + 1e-3}).signedDistance, 0.0);
  EXPECT_LT(vase.closest({top.r * 0.5, e.zHigh - 1e-3}).signedDistance, 0.0);
  EXPECT_LT(vase.closest({1e-9, 0.4}).signedDistance, 0.0);    // on the axis, mid-height: inside
  EXPECT_GT(vase.closest({1e-9, -1e-3}).signedDistance, 0.0);  // just below the bottom's centre
  EXPECT_LT(vase.closest({1e-9, 1e-3}).signedDistance, 0.0);
}

TEST(SmoothProfileTest, SamplesLieOnTheCurveWithThePredictedSagitta) {
  for (const SmoothProfile& shape : testShapes()) {
    for (int points : {16, 100, 1000}) {
      const std::vector<Point2> polyline = shape.sample(points);
      ASSERT_EQ(polyline.size(), std::size_t(points)) << shape.name();
      double worst = 0.0;
      for (std::size_t i = 0; i < polyline.size(); ++i) {
        ASSERT_LT(shape.closest(polyline[i]).distance, 1e-14) << shape.name() << " point " << i;
        if (i == 0) continue;
        // A chord's midpoint is its farthest point from an arc: the sagitta.
        const Point2 middle{0.5 * (polyline[i - 1].r + polyline[i].r), 0.5 * (polyline[i - 1].z + polyline[i].z)};
        worst = std::max(worst, shape.closest(middle).distance);
      }
      // Another part of the curve may pass closer to a coarse chord's midpoint than its own arc.
      EXPECT_LE(worst, shape.sampleError(points) + 1e-12) << shape.name() << " at " << points << " points";
      if (points == 1000) {
        EXPECT_NEAR(worst, shape.sampleError(points), 1e-12) << shape.name();
      }
      EXPECT_NO_THROW(Profile{polyline}) << shape.name();
    }
  }
}

// The sphere's hits in closed form, in long double.
std::optional<long double> sphereHit(const Ray& ray) {
  const long double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z - kSphereZ};
  const long double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const long double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const long double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const long double c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - kSphereR * kSphereR;
  const long double discriminant = b * b - a * c;
  if (discriminant < 0) return std::nullopt;
  const long double t = (-b - std::sqrt(discriminant)) / a;
  if (t < ray.tnear) return std::nullopt;
  return t;
}

TEST(ReferenceTracerTest, FindsTheSpheresHitsInClosedForm) {
  const SmoothProfile sphere = sphereShape();
  const ReferenceTracer tracer(sphere);
  std::mt19937_64 random(11);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(-0.6, 0.6);
  int hits = 0, grazing = 0;
  for (int i = 0; i < 5000; ++i) {
    double u[3] = {normal(random), normal(random), normal(random)};
    const double n = std::hypot(u[0], u[1], u[2]);
    Ray ray;
    ray.origin = {float(1.8 * u[0] / n), float(1.8 * u[1] / n), float(kSphereZ + 1.8 * u[2] / n)};
    ray.direction = {float(unit(random) - ray.origin.x), float(unit(random) - ray.origin.y),
                     float(kSphereZ + unit(random) - ray.origin.z)};
    const ReferenceHit reference = tracer.trace(ray);
    const std::optional<long double> exact = sphereHit(ray);
    if (reference.grazing) {
      ++grazing;
      continue;
    }
    ASSERT_EQ(reference.hit, exact.has_value()) << "ray " << i;
    if (!exact) continue;
    ++hits;
    const double length = std::hypot(ray.direction.x, ray.direction.y, ray.direction.z);
    EXPECT_NEAR(reference.t * length, double(*exact) * length, 1e-12) << "ray " << i;
    const double p[3] = {reference.point[0], reference.point[1], reference.point[2] - kSphereZ};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(reference.normal[k], p[k] / kSphereR, 1e-9);
  }
  EXPECT_GT(hits, 2000);
  EXPECT_LT(grazing, 5);  // only rays within 1e-10 of the silhouette
}

TEST(ReferenceTracerTest, FindsTheTorusHitsAlongItsAxisOfSymmetry) {
  // A horizontal ray through the axis at the tube's centre height meets the tube at r = 0.5 and
  // r = 0.2 on each side; one passing above the tube misses; one along the z axis misses.
  const SmoothProfile torus = torusShape();
  const ReferenceTracer tracer(torus);
  Ray through;
  through.origin = {-2.0f, 0.0f, float(kTorusZ)};
  through.direction = {1.0f, 0.0f, 0.0f};
  const ReferenceHit first = tracer.trace(through);
  ASSERT_TRUE(first.hit);
  EXPECT_NEAR(first.t, 2.0 - (kTorusMajor + kTorusMinor), 1e-7);  // the float origin's z is within 1e-8
  through.tnear = 1.6f;  // past the first tube crossing: the next surface is the tube's inside
  EXPECT_NEAR(tracer.trace(through).t, 2.0 - (kTorusMajor - kTorusMinor), 1e-7);
  Ray above = through;
  above.tnear = 0.0f;
  above.origin.z = float(kTorusZ + kTorusMinor + 1e-3);
  EXPECT_FALSE(tracer.trace(above).hit);
  Ray axis;
  axis.origin = {0.0f, 0.0f, -1.0f};
  axis.direction = {0.0f, 0.0f, 1.0f};
  EXPECT_FALSE(tracer.trace(axis).hit);
}

}  // namespace
}  // namespace revolve::bench
