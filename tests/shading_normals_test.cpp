// ShadingNormals against analytic shapes: polylines inscribed in a sphere and in a torus's tube
// shade with the analytic surface's normal (the interpolation is exact there, see revolve.h, so the
// tolerance is rounding alone), creases keep a capped cylinder's rims sharp, and a crease angle of
// 0 gives back the geometric normal; a polyline made from a curve shades with the curve's normals.
#include "support/spline_profiles.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace revolve {
namespace {

constexpr double kPi = std::numbers::pi;

struct Vec3d {
  double x, y, z;
};

Vec3d unit(Vec3d v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / n, v.y / n, v.z / n};
}

double angleBetween(Vec3 a, Vec3d b) {
  const Vec3d ua = unit({a.x, a.y, a.z}), ub = unit(b);
  const double cx = ua.y * ub.z - ua.z * ub.y, cy = ua.z * ub.x - ua.x * ub.z, cz = ua.x * ub.y - ua.y * ub.x;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ua.x * ub.x + ua.y * ub.y + ua.z * ub.z);
}

double length(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

// Rays from a sphere of 3 radii about the origin aimed at uniform points of the box [-R, R]^3.
std::vector<Ray> raysAt(double radius, std::mt19937_64& random, int count) {
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> box(-radius, radius);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Vec3d o = unit({gauss(random), gauss(random), gauss(random)});
    const Vec3 origin{float(3 * radius * o.x), float(3 * radius * o.y), float(3 * radius * o.z)};
    const Vec3 target{float(box(random)), float(box(random)), float(box(random))};
    rays.push_back({origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}});
  }
  return rays;
}

// Rounding bound for comparing a shading normal with the analytic normal at a hit point, in
// radians, for segments subtending at most 0.2 rad: the float u (half an ulp below 1, 2^-25, times
// 2 pi), the float v (2^-25 of the arc length, about pi R here: pi 2^-25 rad), the float hit point
// (within a few float ulps of R: 8 2^-24 over its distance from the centre, at least R cos 0.1),
// and the float normal itself (2^-24): about 8.5e-7 rad in all; 1.5e-6 leaves room.
constexpr double kRoundingRadians = 1.5e-6;

// A half circle of radius R about the origin, sampled unevenly (denser near the bottom pole), with
// the points in double precision so that they lie on the circle to 1e-16.
std::vector<Point2> unevenSphere(double radius, int segments) {
  std::vector<Point2> points;
  for (int i = 0; i <= segments; ++i) {
    const double theta = kPi * std::pow(double(i) / segments, 1.3);
    points.push_back({i == 0 || i == segments ? 0.0 : radius * std::sin(theta), -radius * std::cos(theta)});
  }
  return points;
}

TEST(ShadingNormalsTest, SpherePolylineShadesWithTheSphereNormal) {
  for (const int segments : {24, 64, 400}) {
    const double radius = 2.5;
    const Profile profile(unevenSphere(radius, segments));
    const Shape shape(profile);
    const ShadingNormals normals(profile, ShadingNormals::kDefaultCreaseDegrees);
    std::mt19937_64 random(1234 + segments);
    double worst = 0.0, worstFlat = 0.0;
    int hits = 0;
    for (const Ray& ray : raysAt(radius, random, 20000)) {
      const std::optional<Hit> hit = intersect(shape, ray);
      if (!hit) continue;
      ++hits;
      const Vec3 n = normals.normal(hit->segment, hit->u, hit->v);
      EXPECT_NEAR(length(n), 1.0, 1e-6);
      const Vec3d truth{hit->point.x, hit->point.y, hit->point.z};  // the sphere's normal: from the centre
      worst = std::max(worst, angleBetween(n, truth));
      worstFlat = std::max(worstFlat, angleBetween(hit->normal, truth));
    }
    EXPECT_GT(hits, 5000) << segments;
    EXPECT_LT(worst, kRoundingRadians) << segments << " segments";
    std::printf("%d segments: worst %.3g rad smooth, %.3g rad flat\n", segments, worst, worstFlat);
    // The geometric normals differ from the sphere's by up to half a segment's angle: the test
    // would see an interpolation that did nothing.
    EXPECT_GT(worstFlat, 0.3 * kPi / segments) << segments;
  }
}

TEST(ShadingNormalsTest, TorusLoopShadesWithTheTubeNormal) {
  // A closed loop off the axis: the joint of the last segment with the first is smoothed too.
  const double major = 3.0, minor = 1.0;
  const int segments = 48;
  std::vector<Point2> points;
  for (int i = 0; i < segments; ++i) {
    const double theta = 2 * kPi * i / segments + 0.05 * std::sin(3.0 * i);  // uneven; steps stay positive (0.13 - 0.1)
    points.push_back({major + minor * std::cos(theta), minor * std::sin(theta)});
  }
  points.push_back(points.front());
  const Profile profile(points);
  const Shape shape(profile);
  const ShadingNormals normals(profile, ShadingNormals::kDefaultCreaseDegrees);
  std::mt19937_64 random(99);
  double worst = 0.0;
  int hits = 0, nearJoint = 0;
  for (const Ray& ray : raysAt(major + minor, random, 20000)) {
    const std::optional<Hit> hit = intersect(shape, ray);
    if (!hit) continue;
    ++hits;
    if (hit->segment == 0 || hit->segment == segments - 1) ++nearJoint;
    const Vec3 n = normals.normal(hit->segment, hit->u, hit->v);
    // The tube's normal: from the nearest point of the major circle to the hit. Whether it points
    // outwards depends on the loop's sense: compare with the side of the geometric normal.
    const double rho = std::hypot(double(hit->point.x), double(hit->point.y));
    Vec3d truth{hit->point.x - major * hit->point.x / rho, hit->point.y - major * hit->point.y / rho, hit->point.z};
    const double side = truth.x * hit->normal.x + truth.y * hit->normal.y + truth.z * hit->normal.z;
    if (side < 0) truth = {-truth.x, -truth.y, -truth.z};
    // The tube's radius is the scale here: rounding of the hit point counts relative to it.
    worst = std::max(worst, angleBetween(n, truth));
  }
  EXPECT_GT(hits, 3000);
  EXPECT_GT(nearJoint, 50);
  std::printf("torus: worst %.3g rad\n", worst);
  EXPECT_LT(worst, 4 * kRoundingRadians);  // the hit point's error is relative to R + r = 4 r
}

// The capped cylinder r = 1, z in [0, 2]: bottom disc (length 1), wall (length 2), top disc
// (length 1); arc lengths 0, 1, 3, 4. Both rims turn by 90 degrees.
const std::vector<Point2> kCappedCylinder{{0, 0}, {1, 0}, {1, 2}, {0, 2}};

TEST(ShadingNormalsTest, CreasesKeepACappedCylinderRimSharp) {
  const Profile profile(kCappedCylinder);
  const ShadingNormals normals(profile, 89.0);
  for (const float u : {0.0f, 0.125f, 0.6f}) {
    const double phi = 2 * kPi * u;
    // On the wall right up to the top rim (v = 3 / 4): the wall's own normal, radial.
    for (const float v : {0.26f, 0.5f, 0.7499f, 0.75f}) {
      const Vec3 n = normals.normal(1, u, v);
      EXPECT_NEAR(n.x, std::cos(phi), 1e-7);
      EXPECT_NEAR(n.y, std::sin(phi), 1e-7);
      EXPECT_NEAR(n.z, 0.0, 1e-7);
    }
    // On the top disc right up to the rim: +z; on the bottom disc: -z.
    for (const float v : {0.75f, 0.76f, 0.9f, 1.0f}) {
      const Vec3 n = normals.normal(2, u, v);
      EXPECT_NEAR(n.z, 1.0, 1e-7);
    }
    EXPECT_NEAR(normals.normal(0, u, 0.25f).z, -1.0, 1e-7);
  }
}

TEST(ShadingNormalsTest, BelowTheCreaseAngleARimIsRounded) {
  const Profile profile(kCappedCylinder);
  const ShadingNormals normals(profile, 91.0);
  // At the top rim the circle through (1, 0), (1, 2), (0, 2) has its centre at (0.5, 1): the rim's
  // normal is (0.5, 1) / |(0.5, 1)| = (1, 2) / sqrt(5), the weighted sum 1 (1, 0) + 2 (0, 1).
  const float u = 0.3f;
  const double phi = 2 * kPi * u;
  const Vec3 wall = normals.normal(1, u, 0.75f), disc = normals.normal(2, u, 0.75f);
  for (const Vec3 n : {wall, disc}) {
    EXPECT_NEAR(n.x, std::cos(phi) / std::sqrt(5.0), 1e-7);
    EXPECT_NEAR(n.y, std::sin(phi) / std::sqrt(5.0), 1e-7);
    EXPECT_NEAR(n.z, 2.0 / std::sqrt(5.0), 1e-7);
  }
  // The top disc's end on the axis is a pole: its mirror image continues it straight, so the normal
  // there is the axis; halfway to the rim it is the normalised blend of (0, 1) and (1, 2) / sqrt 5,
  // and its azimuth is u's (a disc's geometric normal has none).
  const Vec3 pole = normals.normal(2, u, 1.0f);
  EXPECT_NEAR(pole.z, 1.0, 1e-7);
  const Vec3 half = normals.normal(2, u, 0.875f);
  const double r = 0.5 / std::sqrt(5.0), z = 0.5 + 1.0 / std::sqrt(5.0), n = std::hypot(r, z);
  EXPECT_NEAR(half.x, r / n * std::cos(phi), 1e-7);
  EXPECT_NEAR(half.y, r / n * std::sin(phi), 1e-7);
  EXPECT_NEAR(half.z, z / n, 1e-7);
}

TEST(ShadingNormalsTest, AConeTipStaysSharp) {
  // A cone with its tip on the axis at z = 1 and a base disc: the tip's mirror image turns by
  // 90 degrees, more than the default crease, so the tip keeps the side's normal (1, 1) / sqrt 2.
  const Profile profile(std::vector<Point2>{{0, 0}, {1, 0}, {0, 1}});
  const ShadingNormals normals(profile, ShadingNormals::kDefaultCreaseDegrees);
  const Vec3 tip = normals.normal(1, 0.0f, 1.0f);
  EXPECT_NEAR(tip.x, 1 / std::sqrt(2.0), 1e-7);
  EXPECT_NEAR(tip.z, 1 / std::sqrt(2.0), 1e-7);
}

TEST(ShadingNormalsTest, ZeroCreaseAngleGivesTheGeometricNormal) {
  // Flat shading: every vertex is a crease, so the shading normal is the segment's own normal, the
  // one intersect reports, on any profile (this one zigzags and has horizontal runs).
  const Profile profile(
      std::vector<Point2>{{0, 0}, {1, 0}, {1.5, 0.5}, {0.7, 1}, {1.2, 1.5}, {1.2, 2}, {0.4, 2}, {0.4, 2.6}, {0, 2.6}});
  const Shape shape(profile);
  const ShadingNormals normals(profile, 0.0);
  std::mt19937_64 random(7);
  int hits = 0;
  for (const Ray& ray : raysAt(2.0, random, 5000)) {
    const std::optional<Hit> hit = intersect(shape, ray);
    if (!hit) continue;
    ++hits;
    const Vec3 n = normals.normal(hit->segment, hit->u, hit->v);
    // Rounding of u (2 pi 2^-25) and of each float normal: 1e-6 rad.
    EXPECT_LT(angleBetween(n, {hit->normal.x, hit->normal.y, hit->normal.z}), 1e-6);
  }
  EXPECT_GT(hits, 1000);
}

// A polyline made from a curve shades with the curve's own normal at the point of the chord's arc
// that projects onto the hit. The reference here finds that point apart from the library: bisection
// on the projection of Spline::at over the chord's parameter range, the tangent by a central
// difference of Spline::at (one-sided at a piece's end), the azimuth from the hit point.
TEST(ShadingNormalsTest, APolylineMadeFromACurveShadesWithTheCurvesNormal) {
  double worstOfAll = 0;
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Spline curve(named.kind, named.points);
    double extent = 0;
    for (const Point2& q : curve.bezier()) extent = std::max({extent, std::abs(q.r), std::abs(q.z)});
    const Profile polyline = Profile::fromCurve(curve, 0.01 * extent);  // coarse: a few degrees a chord
    const Shape shape(polyline);
    const ShadingNormals fromCurve(polyline, curve), interpolated(polyline, ShadingNormals::kDefaultCreaseDegrees);
    const std::span<const double> T = polyline.curveParameters();
    const std::span<const Point2> p = polyline.points();
    // The curve's largest curvature, from second differences of Spline::at (200 a piece).
    double curvature = 0;
    for (std::size_t piece = 0; piece < curve.pieceCount(); ++piece) {
      for (int k = 1; k < 200; ++k) {
        const double u = k / 200.0, h = 1e-4;
        const Point2 m = curve.at(piece, u - h), c = curve.at(piece, u), q = curve.at(piece, u + h);
        const double dr = (q.r - m.r) / (2 * h), dz = (q.z - m.z) / (2 * h);
        const double ddr = (q.r - 2 * c.r + m.r) / (h * h), ddz = (q.z - 2 * c.z + m.z) / (h * h);
        curvature = std::max(curvature, std::abs(dr * ddz - dz * ddr) / std::pow(std::hypot(dr, dz), 3));
      }
    }
    std::mt19937_64 random(99);
    double worst = 0, worstInterpolated = 0;
    int hits = 0;
    for (const Ray& ray : raysAt(extent, random, 4000)) {
      const std::optional<Hit> hit = intersect(shape, ray);
      if (!hit) continue;
      ++hits;
      const std::uint32_t i = hit->segment;
      const Point2 a = p[i], b = p[i + 1];
      const double rho = std::hypot(double(hit->point.x), double(hit->point.y)), er = b.r - a.r, ez = b.z - a.z;
      const double target = ((rho - a.r) * er + (hit->point.z - a.z) * ez) / (er * er + ez * ez);
      const double firstPiece = std::floor(T[i]), lastPiece = std::max(std::ceil(T[i + 1]) - 1, firstPiece);
      const auto at = [&](double t) {
        const double k = std::clamp(std::floor(t), firstPiece, lastPiece);
        return curve.at(std::size_t(k), std::clamp(t - k, 0.0, 1.0));
      };
      const auto projection = [&](double t) {
        const Point2 q = at(t);
        return ((q.r - a.r) * er + (q.z - a.z) * ez) / (er * er + ez * ez);
      };
      double lo = T[i], hi = T[i + 1];
      for (int k = 0; k < 60; ++k)
        (projection(0.5 * (lo + hi)) < std::clamp(target, 0.0, 1.0) ? lo : hi) = 0.5 * (lo + hi);
      const double t = 0.5 * (lo + hi), h = 1e-7 * (T[i + 1] - T[i]);
      const Point2 before = at(std::max(t - h, T[i])), after = at(std::min(t + h, T[i + 1]));
      const double tr = after.r - before.r, tz = after.z - before.z,
                   phi = std::atan2(double(hit->point.y), double(hit->point.x));
      const double nr = tz / std::hypot(tr, tz), nz = -tr / std::hypot(tr, tz);
      const Vec3d truth{nr * std::cos(phi), nr * std::sin(phi), nz};
      const Vec3 n = fromCurve.normal(hit->segment, hit->u, hit->v);
      EXPECT_NEAR(length(n), 1.0, 1e-6);
      worst = std::max(worst, angleBetween(n, truth));
      worstInterpolated =
          std::max(worstInterpolated, angleBetween(interpolated.normal(hit->segment, hit->u, hit->v), truth));
    }
    EXPECT_GT(hits, 300) << named.name;
    // The library places the point by the float v (2^-25 of the profile's length), the reference by
    // the float hit point (2^-24 of its distance from the origin a coordinate, within the extent):
    // they may disagree along the curve by 4 2^-24 (length + extent), over which the normal turns
    // by the curvature times that; plus the float normal's rounding (2^-23).
    const double bound = 4 * 0x1p-24 * (polyline.arcLength().back() + extent) * curvature + 0x1p-23;
    EXPECT_LT(worst, bound) << named.name;
    std::printf(
        "%s: %zu points, largest curvature %.3g: worst %.3g rad from the curve (bound %.3g), %.3g interpolated\n",
        named.name.c_str(), p.size(), curvature, worst, bound, worstInterpolated);
    worstOfAll = std::max(worstOfAll, worstInterpolated);
  }
  // Normals interpolated between the chords are off by far more (creases at chords turning by more
  // than 30 degrees, circle fits elsewhere): the test sees the difference.
  EXPECT_GT(worstOfAll, 0.1);
  // Normals of one curve for a polyline of another are refused.
  const Spline sphere(SplineKind::bezier, testing::bezierSphere(0.5, 4)),
      larger(SplineKind::bezier, testing::bezierSphere(0.6, 4));
  EXPECT_THROW(ShadingNormals(Profile::fromCurve(sphere, 1e-3), larger), std::invalid_argument);
  EXPECT_THROW(ShadingNormals(Profile(std::vector<Point2>{{0, -0.5}, {0.5, 0}, {0, 0.5}}), sphere),
               std::invalid_argument);
}

TEST(ShadingNormalsTest, RejectsCreaseAnglesOutsideZeroTo180) {
  const Profile profile(kCappedCylinder);
  EXPECT_THROW(ShadingNormals(profile, -1.0), std::invalid_argument);
  EXPECT_THROW(ShadingNormals(profile, 180.5), std::invalid_argument);
  EXPECT_THROW(ShadingNormals(profile, std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(ShadingNormals(profile, 180.0));
}

}  // namespace
}  // namespace revolve
