// The nearest surface point inside a cone (geometry/cone_nearest.h) against closed forms (a plane
// seen by a tilted cone, a vertical cylinder and a sphere beside the cone's axis and just outside
// its edge) and against a dense long-double search over surface points of every standard profile
// and of random triangles: the reading is never farther than the nearest sample inside the cone,
// no nearer than the samples' spacing allows, and its point lies on the surface inside the cone.
#include "geometry/cone_nearest.h"

#include "support/test_profiles.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace revolve {
namespace {

using app::ConeNearest;
using app::SensorCone;
using app::Vec3d;
constexpr double kPi = std::numbers::pi;

// Double arithmetic on metre-sized closed forms, through polynomials solved in long double.
constexpr double kExact = 1e-12;

ConeNearest nearestOnRevolution(const std::vector<Point2>& profile, const SensorCone& cone) {
  ConeNearest best;
  app::nearestOnRevolution(profile, cone, best);
  return best;
}

ConeNearest nearestOnSquare(double x, double half, const SensorCone& cone) {
  // The square {x} x [-half, half]^2 as two triangles.
  ConeNearest best;
  const Vec3d a{x, -half, -half}, b{x, half, -half}, c{x, half, half}, d{x, -half, half};
  app::nearestOnTriangle({a, b, c}, cone, best);
  app::nearestOnTriangle({a, c, d}, cone, best);
  return best;
}

// The cone's axis at angle `tilt` from +X towards +Z (in the XZ plane), turned by `turn` about +X.
Vec3d tiltedAxis(double tilt, double turn = 0) {
  return {std::cos(tilt), std::sin(tilt) * std::sin(turn), std::sin(tilt) * std::cos(turn)};
}

TEST(ConeNearest, PlaneAtDistanceDSeenByATiltedCone) {
  // A plane at distance D, the cone of half-angle a tilted by b from its normal: the nearest point
  // inside the cone is along the boundary ray nearest the normal, D / cos(max(b - a, 0)).
  const double D = 2.0;
  for (const double a : {0.01, 0.1, 0.3, 0.7, 1.2, kPi / 2}) {
    for (const double b : {0.0, 0.05, 0.2, 0.3, 0.5, 0.9, 1.3, 1.5}) {
      for (const double turn : {0.0, 0.4, 2.0}) {
        const SensorCone cone({0, 0, 0}, tiltedAxis(b, turn), a);
        const double expected = D / std::cos(std::max(b - a, 0.0));
        const ConeNearest found = nearestOnSquare(D, 1e4, cone);
        EXPECT_NEAR(found.distance, expected, kExact * expected) << "a = " << a << ", b = " << b << ", turn = " << turn;
        EXPECT_NEAR(found.point[0], D, kExact * D);
      }
    }
  }
  // Turned away from the plane (b - a > pi/2): the cone holds no point of it.
  EXPECT_EQ(nearestOnSquare(D, 1e4, SensorCone({0, 0, 0}, tiltedAxis(1.7), 0.1)).distance, INFINITY);
}

// The first hit, from the apex, of the boundary ray nearest the centre of a circle (in the plane
// of the cone's axis and the centre): the reading of a sphere, or of a tall vertical cylinder seen
// by a horizontal cone from its mid-height, centre at distance D and angle beta from the axis.
double circleReading(double D, double R, double beta, double a) {
  const double gamma = std::max(beta - a, 0.0);
  const double offset = D * std::sin(gamma);
  if (offset > R) return INFINITY;
  return D * std::cos(gamma) - std::sqrt(R * R - offset * offset);
}

TEST(ConeNearest, VerticalCylinderBesideTheAxisAndJustOutsideTheEdge) {
  const double R = 0.3, D = 3.0, height = 40.0;
  // A capped cylinder about x = D, y = 0, heights [-height/2, height/2]: moved to the origin, the
  // apex at (-D cos(beta), -D sin(beta), 0) relative to it.
  const std::vector<Point2> cylinder{{0, -0.5 * height}, {R, -0.5 * height}, {R, 0.5 * height}, {0, 0.5 * height}};
  const double a = 0.2;
  const double edge = a + std::asin(R / D);  // beyond it the cone misses the cylinder
  for (const double beta : {0.0, 0.1, 0.2, 0.25, 0.3, edge - 1e-6, edge - 1e-9, edge + 1e-6, 0.5}) {
    // The cone looks along +X; the cylinder's centre lies at angle beta from it.
    const Vec3d apex{-D * std::cos(beta), -D * std::sin(beta), 0};
    const ConeNearest found = nearestOnRevolution(cylinder, SensorCone(apex, {1, 0, 0}, a));
    const double expected = circleReading(D, R, beta, a);
    if (std::isinf(expected)) {
      EXPECT_EQ(found.distance, INFINITY) << "beta = " << beta;
    } else {
      // Near the edge the reading is ill-conditioned in beta: a change of beta by its rounding moves the
      // tangent point by sqrt of it; the tolerance is that of the closed form's own evaluation.
      const double conditioning =
          1 / std::max(1e-6, std::sqrt(std::max(0.0, R * R - std::pow(D * std::sin(beta - a), 2))));
      EXPECT_NEAR(found.distance, expected, kExact * D * std::max(1.0, conditioning * R)) << "beta = " << beta;
      EXPECT_NEAR(found.point[2], 0.0, 1e-6) << "the nearest point lies at the apex's height";
    }
  }
}

TEST(ConeNearest, SphereInFrontOfTheConeOffAxis) {
  // A sphere's profile, an inscribed half-polygon of n segments, lies within the sagitta R (1 -
  // cos(pi / n)) inside the sphere; along a ray meeting the sphere at incidence i the first hit moves
  // by at most sagitta / cos(i) (the polygon's surface is convex, so the offset is one-sided).
  const double R = 0.5, D = 2.0;
  const int n = 1 << 14;
  std::vector<Point2> sphere;  // in double (the shared test profiles are rounded to float)
  for (int i = 0; i <= n; ++i) {
    const double theta = kPi * i / n;
    sphere.push_back({i == 0 || i == n ? 0.0 : R * std::sin(theta), -R * std::cos(theta)});
  }
  const double sagitta = R * (1 - std::cos(kPi / n));
  const double a = 0.15;
  for (const double beta : {0.0, 0.1, 0.2, 0.3, 0.35}) {
    for (const double turn : {0.0, 1.0, 2.5}) {
      // The centre at the origin; the apex at distance D, the cone's axis at angle beta from the
      // direction to the centre.
      const Vec3d toCentre = tiltedAxis(0.4, 0.7);
      const Vec3d apex{-D * toCentre[0], -D * toCentre[1], -D * toCentre[2]};
      // An axis at angle beta from toCentre: turned about a perpendicular.
      const Vec3d side = app::cross(toCentre, Vec3d{0, 0, 1});
      const double sideLength = std::sqrt(app::dot(side, side));
      const Vec3d s{side[0] / sideLength, side[1] / sideLength, side[2] / sideLength};
      const Vec3d t = app::cross(toCentre, s);
      Vec3d axis;
      for (int i = 0; i < 3; ++i)
        axis[i] = std::cos(beta) * toCentre[i] + std::sin(beta) * (std::cos(turn) * s[i] + std::sin(turn) * t[i]);
      const ConeNearest found = nearestOnRevolution(sphere, SensorCone(apex, axis, a));
      const double expected = circleReading(D, R, beta, a);
      ASSERT_TRUE(std::isfinite(expected));
      const double gamma = std::max(beta - a, 0.0);
      const double incidence = std::asin(std::min(1.0, D * std::sin(gamma) / R));
      EXPECT_GE(found.distance, expected - kExact * D)
          << "beta = " << beta << ": nearer than the sphere itself, by " << expected - found.distance;
      EXPECT_LE(found.distance, expected + sagitta / std::cos(incidence) + kExact * D)
          << "beta = " << beta << ", turn = " << turn << ": " << found.distance - expected << " farther, sagitta "
          << sagitta;
    }
  }
}

// --- Dense search in long double --------------------------------------------------------------

struct Sampled {
  long double distance = INFINITY;
  double spacing = 0;  // every surface point lies within this of a sample
};

using Long3 = std::array<long double, 3>;

bool insideCone(const Long3& x, const SensorCone& cone, long double& distance) {
  const long double d0 = x[0] - cone.apex()[0], d1 = x[1] - cone.apex()[1], d2 = x[2] - cone.apex()[2];
  distance = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
  const long double along = d0 * cone.axis()[0] + d1 * cone.axis()[1] + d2 * cone.axis()[2];
  return along >= distance * std::cos(static_cast<long double>(cone.halfAngle()));
}

Sampled sampleRevolution(const std::vector<Point2>& profile, const SensorCone& cone, int around, int along) {
  Sampled result;
  std::vector<long double> cosines(static_cast<std::size_t>(around)), sines(static_cast<std::size_t>(around));
  for (int k = 0; k < around; ++k) {
    const long double phi = 2 * std::numbers::pi_v<long double> * k / around;
    cosines[std::size_t(k)] = std::cos(phi), sines[std::size_t(k)] = std::sin(phi);
  }
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const Point2 a = profile[i], b = profile[i + 1];
    const double length = std::hypot(b.r - a.r, b.z - a.z), rMax = std::max(a.r, b.r);
    result.spacing = std::max(result.spacing, std::hypot(length / along, 2 * kPi * rMax / around));
    for (int j = 0; j <= along; ++j) {
      const long double l = static_cast<long double>(j) / along;
      const long double r = a.r + l * (b.r - a.r), z = a.z + l * (b.z - a.z);
      for (std::size_t k = 0; k < std::size_t(around); ++k) {
        long double distance;
        if (insideCone({r * cosines[k], r * sines[k], z}, cone, distance))
          result.distance = std::min(result.distance, distance);
      }
    }
  }
  return result;
}

// The least distance from the apex to points of a barycentric grid of `steps` a side on the triangle
// inside the cone, in long double.
long double sampleTriangle(const std::array<Vec3d, 3>& triangle, const SensorCone& cone, int steps) {
  long double sampled = INFINITY;
  for (int i = 0; i <= steps; ++i) {
    for (int j = 0; i + j <= steps; ++j) {
      const long double u = static_cast<long double>(i) / steps, v = static_cast<long double>(j) / steps;
      Long3 x;
      for (std::size_t c = 0; c < 3; ++c)
        x[c] = triangle[0][c] + u * (triangle[1][c] - triangle[0][c]) + v * (triangle[2][c] - triangle[0][c]);
      long double distance;
      if (insideCone(x, cone, distance)) sampled = std::min(sampled, distance);
    }
  }
  return sampled;
}

// The distance from (rho, z) to the profile polyline in the meridian plane.
double meridianDistance(const std::vector<Point2>& profile, double rho, double z) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const Point2 a = profile[i], b = profile[i + 1];
    const double dr = b.r - a.r, dz = b.z - a.z;
    const double l = std::clamp(((rho - a.r) * dr + (z - a.z) * dz) / (dr * dr + dz * dz), 0.0, 1.0);
    best = std::min(best, std::hypot(rho - (a.r + l * dr), z - (a.z + l * dz)));
  }
  return best;
}

// The reading's point is a point of the surface, inside the cone, at the reading's distance.
void expectValidPoint(const ConeNearest& found, const SensorCone& cone, double size, double surfaceDistance,
                      const std::string& what) {
  const Vec3d d = app::minus(found.point, cone.apex());
  const double length = std::sqrt(app::dot(d, d));
  EXPECT_NEAR(length, found.distance, kExact * size) << what;
  EXPECT_LE(surfaceDistance, kExact * size) << what << ": the point is off the surface";
  // Inside: the angle from the axis at most the half-angle (to rounding: 1e-7 rad is the angle's
  // own conditioning, sqrt of double's unit, at a point on the boundary).
  if (length > kExact * size) {
    const double angle = std::acos(std::clamp(app::dot(d, cone.axis()) / length, -1.0, 1.0));
    EXPECT_LE(angle, cone.halfAngle() + 1e-7) << what << ": the point is outside the cone";
  }
}

SensorCone randomCone(std::mt19937_64& random, double size) {
  std::uniform_real_distribution<double> unit(-1, 1), angle(0.02, 1.3), distance(1.2, 3.0);
  Vec3d apex;
  double n2;
  do {
    apex = {unit(random), unit(random), unit(random)};
    n2 = app::dot(apex, apex);
  } while (n2 > 1 || n2 < 1e-4);
  const double scale = distance(random) * size / std::sqrt(n2);
  apex = {apex[0] * scale, apex[1] * scale, apex[2] * scale + 0.5 * size};
  // Aimed near the shape: at a random point of its box.
  const Vec3d target{0.6 * size * unit(random), 0.6 * size * unit(random), 0.5 * size + 0.6 * size * unit(random)};
  const double halfAngle = random() % 8 == 0 ? kPi / 2 : angle(random);
  return SensorCone(apex, app::minus(target, apex), halfAngle);
}

TEST(ConeNearest, EveryStandardProfileAgainstADenseSearch) {
  for (const std::uint64_t seed : testing::testSeeds({1, 2})) {
    std::mt19937_64 random(seed);
    for (const testing::NamedProfile& named : testing::standardProfiles()) {
      double size = 0, zLow = INFINITY, zHigh = -INFINITY;
      for (const Point2 p : named.points)
        size = std::max(size, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
      size = std::max(size, zHigh - zLow);
      // Shift to z in [0, size] so that randomCone's box holds the shape.
      std::vector<Point2> profile = named.points;
      for (Point2& p : profile) p.z -= zLow;
      for (int trial = 0; trial < 5; ++trial) {
        const SensorCone cone = randomCone(random, size);
        const ConeNearest found = nearestOnRevolution(profile, cone);
        const Sampled sampled = sampleRevolution(profile, cone, 512, 16);
        const std::string what = named.name + ", seed " + std::to_string(seed) + ", trial " + std::to_string(trial);
        if (std::isfinite(sampled.distance)) {
          ASSERT_TRUE(std::isfinite(found.distance)) << what << ": the samples found a point inside the cone";
          EXPECT_LE(found.distance, double(sampled.distance) + kExact * size) << what << ": a sample is nearer";
          EXPECT_GE(found.distance, double(sampled.distance) - sampled.spacing) << what;
        }
        if (std::isfinite(found.distance)) {
          const Vec3d x = found.point;
          expectValidPoint(found, cone, size, meridianDistance(profile, std::hypot(x[0], x[1]), x[2]), what);
        }
      }
    }
  }
}

TEST(ConeNearest, ApexOnTheAxisAndAxisAlongIt) {
  // Degenerate symmetry: the cone's axis is the shape's axis, so every boundary direction is
  // stationary (the degree-8 polynomial vanishes identically) and the crossings are whole circles.
  const std::vector<Point2> cylinder = testing::cappedCylinder(1.0, 0.0, 4.0);
  for (const double a : {0.1, 0.5, 1.0, kPi / 2}) {
    // From below, looking up: the bottom disc at distance 1 is seen straight on.
    EXPECT_NEAR(nearestOnRevolution(cylinder, SensorCone({0, 0, -1}, {0, 0, 1}, a)).distance, 1.0, kExact);
    // From inside, looking up: the top disc at distance 2, or the side wall (radius 1) where the
    // cone's boundary meets it, at 1 / sin(a), whichever is nearer (the wall is met below the top
    // only where 1 / sin(a) < sqrt(5), so the nearer one is always there).
    EXPECT_NEAR(nearestOnRevolution(cylinder, SensorCone({0, 0, 2}, {0, 0, 1}, a)).distance,
                std::min(2.0, 1 / std::sin(a)), kExact)
        << "a = " << a;
  }
}

// Cases an independent review found: a half-space (every boundary crossing a double root of the
// squared equation), and apexes within 1e-9 of a triangle's edge or a profile's vertex circle (the
// crossing polynomials' values there below their coefficients' rounding).
TEST(ConeNearest, HalfSpacesAndApexesBesideEdgesAgainstADenseSearch) {
  const auto check = [](const std::vector<Point2>& profile, const SensorCone& cone, const std::string& what) {
    const ConeNearest found = nearestOnRevolution(profile, cone);
    const Sampled sampled = sampleRevolution(profile, cone, 4096, 256);
    // An apex within the rounding of a crossing's computation of the surface (2^-40 of the
    // coordinates: SensorCone::onBoundary) touches it, to that rounding: a reading that small is one.
    const double touching = 0x1p-40 * std::sqrt(app::dot(cone.apex(), cone.apex()));
    if (found.distance <= touching) return;
    if (std::isfinite(sampled.distance)) {
      EXPECT_LE(found.distance, double(sampled.distance) + kExact) << what;
      EXPECT_GE(found.distance, double(sampled.distance) - sampled.spacing) << what;
    }
    if (std::isfinite(found.distance)) {
      const Vec3d x = found.point;
      expectValidPoint(found, cone, 1.0, meridianDistance(profile, std::hypot(x[0], x[1]), x[2]), what);
    }
  };
  // The rim circle (r = 1, z = 0) crosses the boundary plane of the half-space z <= 1 ... : the
  // nearest point lies on the rim, in the plane.
  for (const double half : {kPi / 2, std::nextafter(kPi / 2, 0.0), kPi / 2 - 1e-12})
    check({{1, 0}, {1, -1}}, SensorCone({-0.5, 0.3, 1}, {1, 0.3, 0}, half), "half-space " + std::to_string(half));
  check({{0.14552891600367607, -0.43212027562658872},
         {0.036854344631036595, 0.76190537006533376},
         {0.3655939869796756, 0.40798200117654115}},
        SensorCone({-0.021625961881128589, -0.36495380677532108, 0.40798200117341965},
                   {-0.86439363154108828, 0.049606397178388217, -0.77475791127776594}, 0.60708883669103886),
        "apex 3e-12 from a vertex circle");
  check({{0.95790735096746937, -0.70391586628477054},
         {0.48378546296930086, -0.54217649830342918},
         {0.90991079177072554, 0.60554290915312481}},
        SensorCone({0.4618378516515812, 0.14406308674420479, -0.5421764983034274},
                   {-0.61918548284225028, -0.07241694012195854, -0.040998069690494132}, 0.76740873225440387),
        "apex 5e-15 from a vertex circle (on it, to rounding)");
  // Triangles: the apex 1.4e-9 from an edge, the cone turned away from the triangle: nothing
  // inside it; and a half-space crossing an edge.
  for (const double offset : {1e-15, 1e-12, 1e-9}) {
    ConeNearest found;
    app::nearestOnTriangle({Vec3d{-1, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}},
                           SensorCone({0.3, -offset, -offset}, {0.3, -1, -0.2}, 0.5), found);
    // Within the rounding of a crossing's computation (2^-40 of the coordinates, SensorCone::
    // onBoundary) of the apex, the edge's points count as on the boundary: a reading of that size.
    if (offset * std::sqrt(2.0) > 0x1p-40 * 0.3) {
      EXPECT_EQ(found.distance, INFINITY) << "offset " << offset << ": found " << found.distance;
    } else {
      EXPECT_LE(found.distance, 0x1p-40 * 0.3) << "offset " << offset;
    }
  }
  ConeNearest found;
  const std::array<Vec3d, 3> triangle{Vec3d{0.62075679021106067, -0.84118328980252999, 0},
                                      Vec3d{0.51704533789639728, 0.66174118715128749, 0},
                                      Vec3d{-0.44712149640939658, -0.37691256827567687, 0}};
  const SensorCone halfSpace({0.84103382455102582, 0.23653161791384725, 0.8085747768979934},
                             {0.77489702532187432, -0.72497001664501926, -0.20844700456343021}, kPi / 2);
  app::nearestOnTriangle(triangle, halfSpace, found);
  // The half-space's plane crosses edges 0-1 and 1-2; the nearest point inside it, by dense search.
  constexpr int kSteps = 2000;
  const long double sampled = sampleTriangle(triangle, halfSpace, kSteps);
  ASSERT_TRUE(std::isfinite(sampled));
  EXPECT_LE(found.distance, double(sampled) + kExact);
  EXPECT_GE(found.distance, double(sampled) - 2.0 / kSteps);
}

TEST(ConeNearest, ThinConesAndTheFarHalfOfACircle) {
  // A second review's cases. A cone of half-angle 1e-6 beside a triangle's edge and a disc's rim
  // 3e-5 off its axis: nothing inside it (a boundary test by the angle, not by cosines that a thin
  // cone cannot tell apart).
  for (const double half : {1e-6, 1e-7}) {
    ConeNearest found;
    app::nearestOnTriangle({Vec3d{-1, 3e-5, 1}, Vec3d{1, 3e-5, 1}, Vec3d{0, 1, 1}},
                           SensorCone({0, 0, 0}, {0, 0, 1}, half), found);
    EXPECT_EQ(found.distance, INFINITY) << half;
    EXPECT_EQ(nearestOnRevolution({{1, 1}, {2, 1}}, SensorCone({0, 0, 0}, {1 - 3e-5, 0, 1}, half)).distance, INFINITY)
        << half;
  }
  // The nearest point on a rim circle's half away from the apex's meridian (a large annulus far from
  // the origin): the crossing of the circle with the boundary, where the dense search puts it.
  const std::vector<Point2> annulus{{1443.2317527276505, 1176.5723620926933}, {665.29212409195759, 1176.5723620926933}};
  const SensorCone cone({1208.2157525009984, -2462.8973761483808, -137.4615540604407},
                        {-1822.4224502815041, 1974.1601497701906, 0}, 0.32481863266865385);
  const ConeNearest found = nearestOnRevolution(annulus, cone);
  const Sampled sampled = sampleRevolution(annulus, cone, 1 << 16, 64);
  ASSERT_TRUE(std::isfinite(sampled.distance));
  EXPECT_LE(found.distance, double(sampled.distance) + kExact * 4000);
  EXPECT_GE(found.distance, double(sampled.distance) - sampled.spacing);
  expectValidPoint(found, cone, 4000,
                   meridianDistance(annulus, std::hypot(found.point[0], found.point[1]), found.point[2]), "far half");
}

TEST(ConeNearest, RandomTrianglesAgainstADenseSearch) {
  for (const std::uint64_t seed : testing::testSeeds({4, 5, 6})) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int trial = 0; trial < 40; ++trial) {
      const std::array<Vec3d, 3> triangle{Vec3d{unit(random), unit(random), 0.5 + unit(random)},
                                          Vec3d{unit(random), unit(random), 0.5 + unit(random)},
                                          Vec3d{unit(random), unit(random), 0.5 + unit(random)}};
      const SensorCone cone = randomCone(random, 1.0);
      ConeNearest found;
      app::nearestOnTriangle(triangle, cone, found);
      // Samples on a barycentric grid.
      constexpr int kSteps = 600;
      double spacing = 0;
      for (int k = 0; k < 3; ++k) {
        const Vec3d e = app::minus(triangle[std::size_t((k + 1) % 3)], triangle[std::size_t(k)]);
        spacing = std::max(spacing, std::sqrt(app::dot(e, e)) / kSteps);
      }
      const long double sampled = sampleTriangle(triangle, cone, kSteps);
      const std::string what = "seed " + std::to_string(seed) + ", trial " + std::to_string(trial);
      if (std::isfinite(sampled)) {
        ASSERT_TRUE(std::isfinite(found.distance)) << what;
        EXPECT_LE(found.distance, double(sampled) + kExact) << what << ": a sample is nearer";
        EXPECT_GE(found.distance, double(sampled) - 2 * spacing) << what;
      }
      if (std::isfinite(found.distance)) {
        const Vec3d n = app::cross(app::minus(triangle[1], triangle[0]), app::minus(triangle[2], triangle[0]));
        const double offPlane = std::abs(app::dot(n, app::minus(found.point, triangle[0]))) / std::sqrt(app::dot(n, n));
        expectValidPoint(found, cone, 1.0, offPlane, what);
      }
    }
  }
}

}  // namespace
}  // namespace revolve
