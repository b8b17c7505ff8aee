// Tests of the test oracle itself, the long-double brute-force reference tracer (tests/support/reference.h),
// against things known independently: hand-computed hits, the closed-form primitives, inscribed polylines of
// curved surfaces and sphere tracing of an exact distance function.
//
// Tolerances. Every bound below comes from an error budget stated in `Budget`: a hit is found in
// long double (unit roundoff u = 2^-64) as the root of an implicit function F of the point. Random
// tests use a fixed seed per test (printed on failure); set REVOLVE_TEST_SEED to replay or to
// explore other seeds (support/test_seeds.h).
#include "support/reference.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using revolve::Point2;
using namespace revolve::reference;
using Real = long double;

constexpr Real kUnitRoundoff = std::numeric_limits<Real>::epsilon() / 2;
constexpr Real kDoubleUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
constexpr Real kInf = std::numeric_limits<Real>::infinity();
constexpr Real kPi = std::numbers::pi_v<Real>;

// A generous count of roundings in one oracle formula: forming an implicit equation's coefficients
// and solving it takes under 30 basic operations, each with relative error <= u; 64 leaves a factor
// 2 for products of those errors. Every budget below scales with it.
constexpr Real kRoundings = 64;

struct V3 {
  Real x, y, z;
};

Real dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Real norm(V3 a) { return std::sqrt(dot(a, a)); }

RefRay makeRay(V3 o, V3 d, Real tnear = 0, Real tfar = kInf) { return {o.x, o.y, o.z, d.x, d.y, d.z, tnear, tfar}; }
V3 originOf(const RefRay& ray) { return {ray.ox, ray.oy, ray.oz}; }
V3 directionOf(const RefRay& ray) { return {ray.dx, ray.dy, ray.dz}; }
Real speed(const RefRay& ray) { return norm(directionOf(ray)); }
V3 pointAt(const RefRay& ray, Real t) { return {ray.ox + t * ray.dx, ray.oy + t * ray.dy, ray.oz + t * ray.dz}; }
V3 normalOf(const RefHit& hit) { return {hit.nx, hit.ny, hit.nz}; }
Real rhoAt(const RefRay& ray, const RefHit& hit) {
  const V3 p = pointAt(ray, hit.t);
  return std::hypot(p.x, p.y);
}
// |cos| of the angle between the ray and the surface normal at the hit.
Real cosIncidence(const RefRay& ray, const RefHit& hit) {
  return std::fabs(dot(normalOf(hit), directionOf(ray))) / speed(ray);
}
// Size of the coordinates the ray contributes up to the hit.
Real reach(const RefRay& ray, const RefHit& hit) { return norm(originOf(ray)) + std::fabs(hit.t) * speed(ray); }

std::string describe(const RefRay& ray) {
  std::ostringstream out;
  out << std::setprecision(21) << "ray o=(" << ray.ox << ", " << ray.oy << ", " << ray.oz << ") d=(" << ray.dx << ", "
      << ray.dy << ", " << ray.dz << ") t in [" << ray.tnear << ", " << ray.tfar << "]";
  return out.str();
}

std::string describe(const std::optional<RefHit>& hit) {
  if (!hit) return "miss";
  std::ostringstream out;
  out << std::setprecision(21) << "t=" << hit->t << " n=(" << hit->nx << ", " << hit->ny << ", " << hit->nz
      << ") segment " << hit->segment;
  return out.str();
}

// ---------------------------------------------------------------------------------------------
// Error budget of one oracle hit.
//
// F is a polynomial of degree `degree` in coordinates and lengths of size <= `magnitude`. Forming
// and solving its equation along the ray is backward stable: the computed root is an exact root of
// F perturbed by <= kRoundings u magnitude^degree. Moving the point a distance delta along the
// normal changes F by |grad F| delta, so the computed point is off the surface by
//   offset <= kRoundings u magnitude^degree / |grad F| + 4 u magnitude,
// the last term for rounding the point O + t d itself (and bisection stopping at adjacent long
// doubles). Along the ray that is offset / (|d| |cos incidence|) in t. The normal, computed from
// the point, turns by <= 4 * (point error) / leverArm, leverArm being the shortest length the
// point's error is divided by in that computation (e.g. the distance from the axis for the angle
// phi), plus its own roundings.

struct Budget {
  Real magnitude;
  int degree;
  Real gradient;  // lower bound on |grad F| at the hit
  Real leverArm;  // infinite when the normal does not depend on the point
};
using BudgetOf = std::function<Budget(const RefHit&)>;

Real surfaceOffset(const Budget& b) {
  return kRoundings * kUnitRoundoff * std::pow(b.magnitude, b.degree) / b.gradient + 4 * kUnitRoundoff * b.magnitude;
}
Real tError(const Budget& b, const RefRay& ray, const RefHit& hit) {
  return surfaceOffset(b) / (speed(ray) * cosIncidence(ray, hit));
}
Real pointError(const Budget& b, const RefRay& ray, const RefHit& hit) {
  return tError(b, ray, hit) * speed(ray) + 4 * kUnitRoundoff * b.magnitude;
}
Real normalError(const Budget& b, const RefRay& ray, const RefHit& hit) {
  return 4 * pointError(b, ray, hit) / b.leverArm + kRoundings * kUnitRoundoff;
}

// Profile oracle: F = x^2 + y^2 - (a0 + a1 t)^2 with |slope| = |dr/dz| scaling the radius terms,
// |grad F| = 2 rho sqrt(1 + slope^2) on the surface; horizontal segments are the plane z = z0.
BudgetOf profileBudget(std::span<const Point2> profile, const RefRay& ray) {
  return [profile, ray](const RefHit& hit) {
    const Point2 a = profile[hit.segment];
    const Point2 b = profile[hit.segment + 1];
    const Real size = reach(ray, hit) + a.r + std::fabs(a.z) + b.r + std::fabs(b.z);
    if (a.z == b.z) return Budget{size, 1, 1, kInf};
    const Real slope = std::fabs((Real(b.r) - a.r) / (Real(b.z) - a.z));
    const Real rho = rhoAt(ray, hit);
    return Budget{size * (1 + slope), 2, 2 * rho * std::sqrt(1 + slope * slope), rho};
  };
}

// Cylinder: F = x^2 + y^2 - R^2, |grad F| = 2R; the normal's angle is divided by R.
BudgetOf cylinderBudget(Real radius, Real z0, Real z1, const RefRay& ray) {
  return [=](const RefHit& hit) {
    return Budget{reach(ray, hit) + radius + std::fabs(z0) + std::fabs(z1), 2, 2 * radius, radius};
  };
}

// Apex form of a cone with half angle theta: |grad F| = 2 rho cos(theta) on the surface; its
// normalised gradient turns by <= 4 delta / (rho cos(theta)) for a point error delta.
BudgetOf coneBudget(Real r0, Real z0, Real r1, Real z1, const RefRay& ray) {
  return [=](const RefHit& hit) {
    const Real apexZ = z0 - r0 * (z1 - z0) / (r1 - r0);
    const Real cosTheta = std::fabs(z1 - z0) / std::hypot(z1 - z0, r1 - r0);
    const Real rho = rhoAt(ray, hit);
    const Real size = reach(ray, hit) + std::fabs(apexZ) + r0 + r1 + std::fabs(z0) + std::fabs(z1);
    return Budget{size, 2, 2 * rho * cosTheta, rho * cosTheta};
  };
}

BudgetOf discBudget(Real z, Real rInner, Real rOuter, const RefRay& ray) {
  return [=](const RefHit& hit) { return Budget{reach(ray, hit) + std::fabs(z) + rInner + rOuter, 1, 1, kInf}; };
}

// Sphere: F = |P - C|^2 - R^2, |grad F| = 2R; the normal is (P - C) / R.
BudgetOf sphereBudget(Real centerZ, Real radius, const RefRay& ray) {
  return [=](const RefHit& hit) {
    return Budget{reach(ray, hit) + std::fabs(centerZ) + radius, 2, 2 * radius, radius};
  };
}

// Torus: F = (|P|^2 + R^2 - rho^2)^2 - 4 R^2 (x^2 + y^2), |grad F| = 8 R rho rhoXY on the surface.
// The normal is (P - core) / rho with core = R (x, y, 0) / rhoXY, which moves by R delta / rhoXY.
BudgetOf torusBudget(Real major, Real minor, const RefRay& ray) {
  return [=](const RefHit& hit) {
    const Real rhoXY = rhoAt(ray, hit);
    return Budget{reach(ray, hit) + major + minor, 4, 8 * major * minor * rhoXY, minor * rhoXY / (rhoXY + major)};
  };
}

// ---------------------------------------------------------------------------------------------
// Assertions.

testing::AssertionResult sameHit(const RefRay& ray, const std::optional<RefHit>& a, const BudgetOf& budgetA,
                                 const std::optional<RefHit>& b, const BudgetOf& budgetB) {
  if (a.has_value() != b.has_value()) {
    return testing::AssertionFailure() << describe(ray) << ": " << describe(a) << " vs " << describe(b);
  }
  if (!a) return testing::AssertionSuccess();
  const Budget ba = budgetA(*a);
  const Budget bb = budgetB(*b);
  const Real tBound = tError(ba, ray, *a) + tError(bb, ray, *b);
  const Real nBound = normalError(ba, ray, *a) + normalError(bb, ray, *b);
  const bool tClose = std::fabs(a->t - b->t) <= tBound;
  const bool nClose =
      std::fabs(a->nx - b->nx) <= nBound && std::fabs(a->ny - b->ny) <= nBound && std::fabs(a->nz - b->nz) <= nBound;
  if (tClose && nClose && a->segment == b->segment) return testing::AssertionSuccess();
  return testing::AssertionFailure() << describe(ray) << ": " << describe(a) << " vs " << describe(b)
                                     << std::setprecision(6) << " (t bound " << tBound << ", normal bound " << nBound
                                     << ")";
}

testing::AssertionResult hitIs(const RefRay& ray, const std::optional<RefHit>& hit, const BudgetOf& budget, Real t,
                               V3 normal, std::size_t segment = 0) {
  if (!hit) return testing::AssertionFailure() << describe(ray) << ": miss, expected t=" << double(t);
  const Budget b = budget(*hit);
  const Real tBound = tError(b, ray, *hit);
  const Real nBound = normalError(b, ray, *hit);
  const bool ok = std::fabs(hit->t - t) <= tBound && std::fabs(hit->nx - normal.x) <= nBound &&
                  std::fabs(hit->ny - normal.y) <= nBound && std::fabs(hit->nz - normal.z) <= nBound &&
                  hit->segment == segment;
  if (ok) return testing::AssertionSuccess();
  return testing::AssertionFailure() << describe(ray) << ": " << describe(hit) << ", expected t=" << double(t) << " n=("
                                     << double(normal.x) << ", " << double(normal.y) << ", " << double(normal.z)
                                     << ") segment " << segment;
}

// ---------------------------------------------------------------------------------------------
// Random rays.

std::uint64_t seedFor(std::uint64_t fallback) { return revolve::testing::testSeeds({fallback}).front(); }

#define TRACE_SEED(seed) SCOPED_TRACE(revolve::testing::seedTrace(seed))

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  Real uniform(Real lo, Real hi) { return std::uniform_real_distribution<double>(double(lo), double(hi))(engine_); }
  bool chance(double p) { return std::bernoulli_distribution(p)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  V3 inBox(V3 lo, V3 hi) { return {uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z)}; }

 private:
  std::mt19937_64 engine_;
};

struct Box {
  V3 lo, hi;
};

// A ray from a random point of a cube of half size `reach` about the origin towards a random point
// of `target` (so that most rays hit), with a direction of random length (not unit). A quarter of
// the rays get a random [tnear, tfar] around the target instead of [0, inf).
RefRay randomRay(Random& random, Real reachOfOrigins, const Box& target) {
  const V3 origin = random.inBox({-reachOfOrigins, -reachOfOrigins, -reachOfOrigins},
                                 {reachOfOrigins, reachOfOrigins, reachOfOrigins});
  const V3 aim = random.inBox(target.lo, target.hi);
  const Real scale = random.uniform(0.25, 4);
  const V3 direction{(aim.x - origin.x) * scale, (aim.y - origin.y) * scale, (aim.z - origin.z) * scale};
  RefRay ray = makeRay(origin, direction);
  if (random.chance(0.25)) {
    const Real tAim = 1 / scale;  // the ray reaches `aim` at this t
    ray.tnear = random.uniform(-tAim, tAim);
    ray.tfar = ray.tnear + random.uniform(0, 2 * tAim);
  }
  return ray;
}

Box boxOf(Real rMax, Real zMin, Real zMax) { return {{-rMax, -rMax, zMin}, {rMax, rMax, zMax}}; }

// The surface of one profile segment as the matching closed-form primitive.
std::optional<RefHit> primitiveHit(Point2 a, Point2 b, const RefRay& ray) {
  if (a.z == b.z) return intersectDisc(a.z, a.r, b.r, ray);
  if (a.r == b.r) return intersectCylinder(a.r, a.z, b.z, ray);
  return intersectCone(a.r, a.z, b.r, b.z, ray);
}

BudgetOf primitiveBudget(Point2 a, Point2 b, const RefRay& ray) {
  if (a.z == b.z) return discBudget(a.z, a.r, b.r, ray);
  if (a.r == b.r) return cylinderBudget(a.r, a.z, b.z, ray);
  return coneBudget(a.r, a.z, b.r, b.z, ray);
}

// The nearest hit over the profile's segments, each as a primitive; ties go to the lower index.
std::optional<RefHit> nearestPrimitiveHit(std::span<const Point2> profile, const RefRay& ray) {
  std::optional<RefHit> best;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    std::optional<RefHit> hit = primitiveHit(profile[i], profile[i + 1], ray);
    if (!hit || (best && hit->t >= best->t)) continue;
    hit->segment = i;
    best = hit;
  }
  return best;
}

BudgetOf nearestPrimitiveBudget(std::span<const Point2> profile, const RefRay& ray) {
  return [profile, ray](const RefHit& hit) {
    return primitiveBudget(profile[hit.segment], profile[hit.segment + 1], ray)(hit);
  };
}

// ---------------------------------------------------------------------------------------------
// Vertical segments: cylinders.

TEST(OracleTest, VerticalSegmentHandCases) {
  const std::vector<Point2> up{{1, 0}, {1, 2}};
  const RefRay across = makeRay({-5, 0, 0.5}, {2, 0, 0});  // meets x = -1 at t = 2, x = 1 at t = 3
  EXPECT_TRUE(hitIs(across, intersectProfile(up, across), profileBudget(up, across), 2, {-1, 0, 0}));
  const std::vector<RefHit> both = allHits(up, across);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_TRUE(hitIs(across, both[1], profileBudget(up, across), 3, {1, 0, 0}));

  // Listed downwards, the normal points to the axis.
  const std::vector<Point2> down{{1, 2}, {1, 0}};
  EXPECT_TRUE(hitIs(across, intersectProfile(down, across), profileBudget(down, across), 2, {1, 0, 0}));

  // Above the segment, and parallel to the axis: misses.
  EXPECT_FALSE(intersectProfile(up, makeRay({-5, 0, 2.5}, {1, 0, 0})));
  EXPECT_FALSE(intersectProfile(up, makeRay({0.5, 0, -1}, {0, 0, 1})));
  // Diagonal in the xy plane: from (-3, -4) towards the origin, |o| = 5, meets rho = 1 at t = 4/5.
  const RefRay diagonal = makeRay({-3, -4, 1}, {3, 4, 0});
  EXPECT_TRUE(hitIs(diagonal, intersectProfile(up, diagonal), profileBudget(up, diagonal), 0.8L, {-0.6L, -0.8L, 0}));
}

TEST(OracleTest, VerticalSegmentMatchesCylinder) {
  const std::uint64_t seed = seedFor(0x5eed0001);
  TRACE_SEED(seed);
  Random random(seed);
  for (int i = 0; i < 20000; ++i) {
    const double radius = double(random.uniform(0.1, 3));
    double z0 = double(random.uniform(-2, 2));
    double z1 = double(random.uniform(-2, 2));
    if (z0 == z1) continue;
    const std::vector<Point2> profile{{radius, z0}, {radius, z1}};
    const RefRay ray = randomRay(random, 6, boxOf(radius, std::min(z0, z1), std::max(z0, z1)));
    ASSERT_TRUE(sameHit(ray, intersectProfile(profile, ray), profileBudget(profile, ray),
                        intersectCylinder(radius, z0, z1, ray), cylinderBudget(radius, z0, z1, ray)))
        << "ray " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Oblique segments: cones.

TEST(OracleTest, ObliqueSegmentHandCases) {
  const Real h = 1 / std::sqrt(Real(2));
  // The 45-degree cone r = z for z in [0, 1], apex at the origin: meridian normal (1, -1) / sqrt 2.
  const std::vector<Point2> cone{{0, 0}, {1, 1}};

  // Parallel to the axis at x = 0.5: meets r = z at z = 0.5, t = 1.5.
  const RefRay parallel = makeRay({0.5, 0, -1}, {0, 0, 1});
  EXPECT_TRUE(hitIs(parallel, intersectProfile(cone, parallel), profileBudget(cone, parallel), 1.5L, {h, 0, -h}));

  // Perpendicular to the axis at z = 0.5: x = -0.5 at t = 2.5 and x = 0.5 at t = 3.5.
  const RefRay perpendicular = makeRay({-3, 0, 0.5}, {1, 0, 0});
  const std::vector<RefHit> across = allHits(cone, perpendicular);
  ASSERT_EQ(across.size(), 2u);
  EXPECT_TRUE(hitIs(perpendicular, across[0], profileBudget(cone, perpendicular), 2.5L, {-h, 0, -h}));
  EXPECT_TRUE(hitIs(perpendicular, across[1], profileBudget(cone, perpendicular), 3.5L, {h, 0, -h}));
  EXPECT_TRUE(hitIs(perpendicular, intersectCone(0, 0, 1, 1, perpendicular), coneBudget(0, 0, 1, 1, perpendicular),
                    2.5L, {-h, 0, -h}));

  // Along the axis: only the apex (a double root), once, with the normal at phi = 0.
  const RefRay axis = makeRay({0, 0, -1}, {0, 0, 1});
  const std::vector<RefHit> apex = allHits(cone, axis);
  ASSERT_EQ(apex.size(), 1u);
  EXPECT_EQ(apex[0].t, 1);  // the quadratic -t^2 + 2t - 1: exact coefficients, exact double root
  EXPECT_NEAR(apex[0].nx, h, kRoundings * kUnitRoundoff);
  EXPECT_EQ(apex[0].ny, 0);
  EXPECT_NEAR(apex[0].nz, -h, kRoundings * kUnitRoundoff);

  // The mirror nappe r = -z (z < 0) solves the same quadratic but is not the surface.
  EXPECT_TRUE(allHits(cone, makeRay({-3, 0, -0.5}, {1, 0, 0})).empty());
  EXPECT_FALSE(intersectCone(0, 0, 1, 1, makeRay({-3, 0, -0.5}, {1, 0, 0})));

  // A cone narrowing upwards, r = 2 - z for z in [0, 1], listed upwards: normal (1, 1) / sqrt 2.
  const std::vector<Point2> narrowing{{2, 0}, {1, 1}};
  const RefRay side = makeRay({-5, 0, 0.5}, {1, 0, 0});  // meets r = 1.5 at x = -1.5, t = 3.5
  EXPECT_TRUE(hitIs(side, intersectProfile(narrowing, side), profileBudget(narrowing, side), 3.5L, {-h, 0, h}));
  EXPECT_TRUE(hitIs(side, intersectCone(2, 0, 1, 1, side), coneBudget(2, 0, 1, 1, side), 3.5L, {-h, 0, h}));
}

TEST(OracleTest, ObliqueSegmentMatchesCone) {
  const std::uint64_t seed = seedFor(0x5eed0002);
  TRACE_SEED(seed);
  Random random(seed);
  for (int i = 0; i < 20000; ++i) {
    // Every other cone reaches the axis (an apex on the surface).
    const double r0 = random.chance(0.5) ? 0.0 : double(random.uniform(0, 2));
    const double r1 = double(random.uniform(0, 2));
    const double z0 = double(random.uniform(-2, 2));
    const double z1 = double(random.uniform(-2, 2));
    if (r0 == r1 || z0 == z1) continue;
    const std::vector<Point2> profile{{r0, z0}, {r1, z1}};
    const RefRay ray = randomRay(random, 6, boxOf(std::max(r0, r1), std::min(z0, z1), std::max(z0, z1)));
    ASSERT_TRUE(sameHit(ray, intersectProfile(profile, ray), profileBudget(profile, ray),
                        intersectCone(r0, z0, r1, z1, ray), coneBudget(r0, z0, r1, z1, ray)))
        << "ray " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Horizontal segments: discs and annuli.

TEST(OracleTest, HorizontalSegmentHandCases) {
  const std::vector<Point2> disc{{0, 1}, {2, 1}};  // listed outwards: normal -z
  const RefRay down = makeRay({0.5, 0, 3}, {0, 0, -2});
  EXPECT_TRUE(hitIs(down, intersectProfile(disc, down), profileBudget(disc, down), 1, {0, 0, -1}));
  EXPECT_TRUE(hitIs(down, intersectDisc(1, 0, 2, down), discBudget(1, 0, 2, down), 1, {0, 0, -1}));

  const std::vector<Point2> inwards{{2, 1}, {0, 1}};  // listed inwards: normal +z
  EXPECT_TRUE(hitIs(down, intersectProfile(inwards, down), profileBudget(inwards, down), 1, {0, 0, 1}));
  EXPECT_TRUE(hitIs(down, intersectDisc(1, 2, 0, down), discBudget(1, 2, 0, down), 1, {0, 0, 1}));

  // The annulus 1 <= rho <= 2: the hole and beyond the rim miss; the ray in the plane misses.
  const std::vector<Point2> annulus{{1, 1}, {2, 1}};
  EXPECT_FALSE(intersectProfile(annulus, down));
  EXPECT_FALSE(intersectDisc(1, 1, 2, down));
  EXPECT_FALSE(intersectProfile(annulus, makeRay({2.5, 0, 3}, {0, 0, -1})));
  EXPECT_FALSE(intersectProfile(annulus, makeRay({-5, 0, 1}, {1, 0, 0})));
  // Oblique: from (0, 0, 3) along (1, 1, -1) reaches z = 1 at t = 2, rho = 2 sqrt 2 > 2: a miss;
  // along (0.5, 0.5, -1) at t = 2, rho = sqrt 2: a hit.
  EXPECT_FALSE(intersectProfile(annulus, makeRay({0, 0, 3}, {1, 1, -1})));
  const RefRay oblique = makeRay({0, 0, 3}, {0.5, 0.5, -1});
  EXPECT_TRUE(hitIs(oblique, intersectProfile(annulus, oblique), profileBudget(annulus, oblique), 2, {0, 0, -1}));
}

TEST(OracleTest, HorizontalSegmentMatchesDisc) {
  const std::uint64_t seed = seedFor(0x5eed0003);
  TRACE_SEED(seed);
  Random random(seed);
  for (int i = 0; i < 20000; ++i) {
    const double r0 = random.chance(0.5) ? 0.0 : double(random.uniform(0, 2));
    const double r1 = double(random.uniform(0, 2));
    const double z = double(random.uniform(-2, 2));
    if (r0 == r1) continue;
    const std::vector<Point2> profile{{r0, z}, {r1, z}};
    const RefRay ray = randomRay(random, 6, boxOf(std::max(r0, r1), z, z));
    ASSERT_TRUE(sameHit(ray, intersectProfile(profile, ray), profileBudget(profile, ray), intersectDisc(z, r0, r1, ray),
                        discBudget(z, r0, r1, ray)))
        << "ray " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Several segments.

TEST(OracleTest, CappedCylinderMatchesUnionOfPieces) {
  const std::uint64_t seed = seedFor(0x5eed0004);
  TRACE_SEED(seed);
  Random random(seed);
  // Bottom disc (normal -z), side (outwards), top disc listed inwards (normal +z).
  const std::vector<Point2> capped{{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const RefRay ray = randomRay(random, 5, boxOf(1, 0, 2));
    const std::optional<RefHit> reference = intersectProfile(capped, ray);
    hits += reference.has_value();
    ASSERT_TRUE(sameHit(ray, reference, profileBudget(capped, ray), nearestPrimitiveHit(capped, ray),
                        nearestPrimitiveBudget(capped, ray)))
        << "ray " << i;
  }
  EXPECT_GT(hits, 10000);  // the rays aim at the cylinder's box: most must hit
}

TEST(OracleTest, RandomProfilesMatchUnionOfPrimitives) {
  const std::uint64_t seed = seedFor(0x5eed0005);
  TRACE_SEED(seed);
  Random random(seed);
  for (int p = 0; p < 500; ++p) {
    // Half the profiles are monotone in z with snapped (vertical, horizontal, on-axis) segments,
    // never two horizontal in a row, so no two segments overlap; half are unconstrained zigzags.
    const bool monotone = random.chance(0.5);
    std::vector<Point2> profile{{double(random.uniform(0, 2)), double(random.uniform(-2, -1))}};
    const int count = random.integer(2, 8);
    bool lastHorizontal = false;
    while (int(profile.size()) < count) {
      const Point2 last = profile.back();
      Point2 next{double(random.uniform(0, 2)), double(random.uniform(-2, 2))};
      if (monotone) {
        next.z = last.z + double(random.uniform(0, 0.7));
        if (random.chance(0.2)) next.r = last.r;
        if (random.chance(0.15)) next.r = 0;
        if (!lastHorizontal && random.chance(0.2)) next.z = last.z;
      }
      if (next.r == last.r && next.z == last.z) continue;
      lastHorizontal = next.z == last.z;
      profile.push_back(next);
    }
    for (int i = 0; i < 40; ++i) {
      const RefRay ray = randomRay(random, 6, boxOf(2, -2, 3));
      ASSERT_TRUE(sameHit(ray, intersectProfile(profile, ray), profileBudget(profile, ray),
                          nearestPrimitiveHit(profile, ray), nearestPrimitiveBudget(profile, ray)))
          << "profile " << p << " ray " << i;
      // Every root lies on the surface: its meridian distance is within the hit's offset bound
      // (plus the distance computation's own roundings, a few u times the coordinates).
      for (const RefHit& hit : allHits(profile, ray)) {
        const V3 q = pointAt(ray, hit.t);
        const Budget budget = profileBudget(profile, ray)(hit);
        ASSERT_LE(meridianDistance(profile, q.x, q.y, q.z),
                  surfaceOffset(budget) + kRoundings * kUnitRoundoff * budget.magnitude)
            << "profile " << p << " ray " << i << " " << describe(ray);
      }
    }
  }
}

TEST(OracleTest, RangeTiesAndInvalidRays) {
  const std::vector<Point2> capped{{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  const V3 o{-3, 0, 1};
  const V3 d{1, 0, 0};  // side at t = 2 and t = 4
  ASSERT_EQ(allHits(capped, makeRay(o, d)).size(), 2u);
  EXPECT_EQ(intersectProfile(capped, makeRay(o, d))->t, 2);
  EXPECT_EQ(intersectProfile(capped, makeRay(o, d, 2.5L))->t, 4);  // the legitimate re-hit
  EXPECT_EQ(intersectProfile(capped, makeRay(o, d, 2, 2))->t, 2);  // the range is closed
  EXPECT_EQ(intersectProfile(capped, makeRay(o, d, 0, 4))->t, 2);
  EXPECT_EQ(intersectProfile(capped, makeRay(o, d, 4, 4))->t, 4);
  EXPECT_FALSE(intersectProfile(capped, makeRay(o, d, 0, 1.5L)));
  EXPECT_FALSE(intersectProfile(capped, makeRay(o, d, 4.5L)));

  // Through the rim point (1, 0) (at x = -1, z = 0, t = 1): the bottom disc and the side both
  // contain it; the nearest goes to the lower index, and allHits lists it for both.
  const RefRay rim = makeRay({-2, 0, -1}, {1, 0, 1});
  // It leaves through the other rim, (1, 2) at x = 1, z = 2, t = 3: the side and the top disc.
  const std::vector<RefHit> rimHits = allHits(capped, rim);
  ASSERT_EQ(rimHits.size(), 4u);
  EXPECT_EQ(rimHits[0].t, 1);
  EXPECT_EQ(rimHits[0].segment, 0u);
  EXPECT_EQ(rimHits[1].t, 1);
  EXPECT_EQ(rimHits[1].segment, 1u);
  EXPECT_EQ(rimHits[2].t, 3);
  EXPECT_EQ(rimHits[2].segment, 1u);
  EXPECT_EQ(rimHits[3].t, 3);
  EXPECT_EQ(rimHits[3].segment, 2u);
  EXPECT_EQ(intersectProfile(capped, rim)->segment, 0u);

  // Rays the library rejects miss in the oracle too.
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_FALSE(intersectProfile(capped, makeRay(o, {0, 0, 0})));
  EXPECT_FALSE(intersectProfile(capped, makeRay(o, {kInf, 0, 0})));
  EXPECT_FALSE(intersectProfile(capped, makeRay({nan, 0, 1}, d)));
  EXPECT_FALSE(intersectProfile(capped, makeRay(o, d, 3, 1)));
  EXPECT_FALSE(intersectSphere(0, 1, makeRay(o, {0, 0, 0})));
  EXPECT_FALSE(intersectTorus(2, 0.5L, makeRay(o, d, nan)));
}

// ---------------------------------------------------------------------------------------------
// The library's rules for what rounding cannot decide.

TEST(OracleTest, HorizontalRaysFollowTheHalfOpenHeightRule) {
  // A segment owns the heights [zmin, zmax): in the plane of a vertex, the circles of the segments
  // continuing upwards from it. Along x from (-3, 0, z), the circle of radius 1 is met at t = 2
  // and t = 4 (the quadratic t^2 - 6t + 8, exact).
  const std::vector<Point2> capped{{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  const std::vector<RefHit> bottom = allHits(capped, makeRay({-3, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(bottom.size(), 2u);  // the side's circle; the bottom disc lies in the plane
  EXPECT_EQ(bottom[0].t, 2);
  EXPECT_EQ(bottom[0].segment, 1u);
  EXPECT_EQ(bottom[1].t, 4);
  EXPECT_TRUE(allHits(capped, makeRay({-3, 0, 2}, {1, 0, 0})).empty());  // the top rim: nothing above

  // The side split at z = 1: the segment above the vertex owns its height, the one below does not.
  const std::vector<Point2> split{{0, 0}, {1, 0}, {1, 1}, {1, 2}, {0, 2}};
  const std::vector<RefHit> middle = allHits(split, makeRay({-3, 0, 1}, {1, 0, 0}));
  ASSERT_EQ(middle.size(), 2u);
  EXPECT_EQ(middle[0].segment, 2u);
  EXPECT_EQ(middle[1].segment, 2u);

  // A vertex where the profile turns from down to up belongs to both segments; one where it turns
  // from up to down, to neither.
  const std::vector<RefHit> valley =
      allHits(std::vector<Point2>{{2, 1}, {1, 0}, {2, 2}}, makeRay({-3, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(valley.size(), 4u);
  EXPECT_EQ(valley[0].t, 2);
  EXPECT_EQ(valley[1].t, 2);
  EXPECT_TRUE(allHits(std::vector<Point2>{{1, 0}, {2, 1}, {1.5, 0}}, makeRay({-3, 0, 1}, {1, 0, 0})).empty());
}

TEST(OracleTest, RaysThroughAnApexTouchIt) {
  // The open cone from the apex (0, 0, 1) down to radius 0.5 at z = 0: its only segment meets the
  // axis at the apex.
  const std::vector<Point2> cone{{0, 1}, {0.5, 0}};
  // In the apex's plane: through the axis, a touch at t = 3; off it, nothing (the segment's
  // circle there has radius 0).
  const std::optional<RefHit> level = intersectProfile(cone, makeRay({-3, 0, 1}, {1, 0, 0}));
  ASSERT_TRUE(level.has_value());
  EXPECT_EQ(level->t, 3);
  EXPECT_FALSE(intersectProfile(cone, makeRay({-3, 0.25L, 1}, {1, 0, 0})));
  // Obliquely through the apex from outside: (-2, 0, 1.5) + t (2, 0, -0.5) passes it at t = 1, and
  // below it stays outside the cone (rho = 2 (t - 1) against the radius 0.25 (t - 1)).
  const std::optional<RefHit> oblique = intersectProfile(cone, makeRay({-2, 0, 1.5L}, {2, 0, -0.5L}));
  ASSERT_TRUE(oblique.has_value());
  EXPECT_EQ(oblique->t, 1);
  // Along the axis from below: into the cone's inside, out through the apex.
  const std::optional<RefHit> axis = intersectProfile(cone, makeRay({0, 0, -1}, {0, 0, 2}));
  ASSERT_TRUE(axis.has_value());
  EXPECT_EQ(axis->t, 1);
  // The hourglass's pinch joins two cones: the touch is listed for both, the lower index first.
  const std::vector<Point2> hourglass{{0, -1}, {0.8L, -1}, {0, 0}, {0.8L, 1}, {0, 1}};
  const std::vector<RefHit> pinch = allHits(hourglass, makeRay({-3, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(pinch.size(), 2u);
  EXPECT_EQ(pinch[0].t, 3);
  EXPECT_EQ(pinch[0].segment, 1u);
  EXPECT_EQ(pinch[1].segment, 2u);
}

// ---------------------------------------------------------------------------------------------
// Sphere.

TEST(OracleTest, SphereHandCases) {
  // Centre (0, 0, 1), radius 2.
  const RefRay up = makeRay({0, 0, -5}, {0, 0, 1});  // south pole z = -1 at t = 4, north z = 3 at t = 8
  EXPECT_TRUE(hitIs(up, intersectSphere(1, 2, up), sphereBudget(1, 2, up), 4, {0, 0, -1}));
  const RefRay upLater = makeRay({0, 0, -5}, {0, 0, 1}, 5);
  EXPECT_TRUE(hitIs(upLater, intersectSphere(1, 2, upLater), sphereBudget(1, 2, upLater), 8, {0, 0, 1}));
  const RefRay fromInside = makeRay({0, 0, 1}, {0.5, 0, 0});
  EXPECT_TRUE(hitIs(fromInside, intersectSphere(1, 2, fromInside), sphereBudget(1, 2, fromInside), 4, {1, 0, 0}));
  // Along (0, 3, 4) from (0, -3, -3), P - C = (0, 3 (s - 1), 4 (s - 1)): |P - C| = 2 where
  // 25 (s - 1)^2 = 4, first at s = 0.6: point (0, -1.2, -0.6), normal (0, -0.6, -0.8).
  const RefRay slanted = makeRay({0, -3, -3}, {0, 3, 4});
  EXPECT_TRUE(hitIs(slanted, intersectSphere(1, 2, slanted), sphereBudget(1, 2, slanted), 0.6L, {0, -0.6L, -0.8L}));
  // Tangent at (2, 0, 1): a double root, counted as a hit.
  const std::optional<RefHit> tangent = intersectSphere(1, 2, makeRay({2, -5, 1}, {0, 1, 0}));
  ASSERT_TRUE(tangent);
  EXPECT_EQ(tangent->t, 5);
  EXPECT_FALSE(intersectSphere(1, 2, makeRay({2.001L, -5, 1}, {0, 1, 0})));
  EXPECT_FALSE(intersectSphere(1, 2, makeRay({0, 0, -5}, {0, 0, -1})));  // pointing away
}

// The SoR of `arcPoints` inscribed in a circle of the meridian plane lies between the SoRs of two
// concentric circles: radius * cos(half the angle a segment spans) (a regular polygon's inradius)
// and radius, each widened by the rounding of the vertices to double (<= sqrt 2 u_double times the
// largest coordinate). A ray from outside the outer solid meets the polyline's surface no earlier
// than the outer surface and no later than the inner one.
struct Sandwich {
  Real inner, outer;
};

Sandwich sandwichOf(Real radius, Real halfAngle, Real largestCoordinate) {
  const Real vertexRounding = std::sqrt(Real(2)) * kDoubleUnitRoundoff * largestCoordinate;
  return {radius * std::cos(halfAngle) - vertexRounding, radius + vertexRounding};
}

testing::AssertionResult sandwiched(const RefRay& ray, const std::optional<RefHit>& outer, const BudgetOf& outerBudget,
                                    const std::optional<RefHit>& polyline, const BudgetOf& polylineBudget,
                                    const std::optional<RefHit>& inner, const BudgetOf& innerBudget) {
  auto fail = [&] {
    return testing::AssertionFailure() << describe(ray) << ": outer " << describe(outer) << ", polyline "
                                       << describe(polyline) << ", inner " << describe(inner);
  };
  if (polyline && !outer) return fail();
  if (inner && !polyline) return fail();
  if (!polyline) return testing::AssertionSuccess();
  const Real tPolyError = tError(polylineBudget(*polyline), ray, *polyline);
  if (outer->t > polyline->t + tPolyError + tError(outerBudget(*outer), ray, *outer)) return fail();
  if (inner && polyline->t > inner->t + tPolyError + tError(innerBudget(*inner), ray, *inner)) return fail();
  return testing::AssertionSuccess();
}

// The polyline's facet normal differs from the circle's normal at the radial projection of its
// hit point by at most the half angle a segment spans. Slack: the facet normal's error, and the
// circle normal's, computed from the hit point over the lever arm `circleLeverArm`.
testing::AssertionResult facetNormalClose(const RefRay& ray, const RefHit& polyline, const Budget& budget,
                                          V3 circleNormal, Real circleLeverArm, Real halfAngle) {
  const Real cosine = dot(normalOf(polyline), circleNormal);
  const Real slack = normalError(budget, ray, polyline) + 4 * pointError(budget, ray, polyline) / circleLeverArm +
                     kRoundings * kUnitRoundoff;
  if (cosine >= std::cos(halfAngle) - slack) return testing::AssertionSuccess();
  return testing::AssertionFailure() << describe(ray) << ": facet normal at "
                                     << double(std::acos(std::min<Real>(cosine, 1))) << " rad from the circle's, bound "
                                     << double(halfAngle);
}

// n + 1 points (centerR + radius cos a, centerZ + radius sin a), a from `from` to `to`.
std::vector<Point2> inscribedArc(Real centerR, Real centerZ, Real radius, Real from, Real to, int segments) {
  std::vector<Point2> points;
  for (int i = 0; i <= segments; ++i) {
    const Real a = from + (to - from) * i / segments;
    points.push_back({double(centerR + radius * std::cos(a)), double(centerZ + radius * std::sin(a))});
  }
  return points;
}

TEST(OracleTest, SphereMatchesInscribedPolyline) {
  const std::uint64_t seed = seedFor(0x5eed0006);
  TRACE_SEED(seed);
  Random random(seed);
  const Real centerZ = 0.5L;
  const Real radius = 1.5L;
  const int segments = 200;
  std::vector<Point2> polyline = inscribedArc(0, centerZ, radius, -kPi / 2, kPi / 2, segments);
  polyline.front().r = 0;  // the poles lie on the axis
  polyline.back().r = 0;
  const Real halfAngle = kPi / (2 * segments);
  const Sandwich sandwich = sandwichOf(radius, halfAngle, radius + centerZ);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    RefRay ray = randomRay(random, 5, boxOf(radius, centerZ - radius, centerZ + radius));
    ray.tnear = 0;
    ray.tfar = kInf;
    if (std::hypot(ray.ox, ray.oy, ray.oz - centerZ) <= sandwich.outer) continue;  // origins outside
    const std::optional<RefHit> poly = intersectProfile(polyline, ray);
    hits += poly.has_value();
    ASSERT_TRUE(sandwiched(ray, intersectSphere(centerZ, sandwich.outer, ray),
                           sphereBudget(centerZ, sandwich.outer, ray), poly, profileBudget(polyline, ray),
                           intersectSphere(centerZ, sandwich.inner, ray), sphereBudget(centerZ, sandwich.inner, ray)))
        << "ray " << i;
    if (!poly) continue;
    const V3 q = pointAt(ray, poly->t);
    const Real distance = std::hypot(q.x, q.y, q.z - centerZ);
    const V3 circleNormal{q.x / distance, q.y / distance, (q.z - centerZ) / distance};
    ASSERT_TRUE(facetNormalClose(ray, *poly, profileBudget(polyline, ray)(*poly), circleNormal, distance, halfAngle))
        << "ray " << i;
  }
  EXPECT_GT(hits, 2500);
}

// ---------------------------------------------------------------------------------------------
// Torus.

TEST(OracleTest, TorusHandCases) {
  const Real R = 2;
  const Real rho = 0.5L;
  // Along x through both tubes: x = -2.5, -1.5, 1.5, 2.5 at t = 2.5, 3.5, 6.5, 7.5.
  const V3 o{-5, 0, 0};
  const V3 d{1, 0, 0};
  const struct {
    Real tnear, t;
    V3 normal;
  } alongX[] = {{0, 2.5L, {-1, 0, 0}}, {3, 3.5L, {1, 0, 0}}, {4, 6.5L, {-1, 0, 0}}, {7, 7.5L, {1, 0, 0}}};
  for (const auto& expected : alongX) {
    const RefRay ray = makeRay(o, d, expected.tnear);
    EXPECT_TRUE(hitIs(ray, intersectTorus(R, rho, ray), torusBudget(R, rho, ray), expected.t, expected.normal));
  }
  EXPECT_FALSE(intersectTorus(R, rho, makeRay(o, d, 8)));
  // Non-unit direction: the same hits at half the t.
  const RefRay fast = makeRay(o, {2, 0, 0});
  EXPECT_TRUE(hitIs(fast, intersectTorus(R, rho, fast), torusBudget(R, rho, fast), 1.25L, {-1, 0, 0}));
  // From the centre outwards: the inner equator at x = 1.5.
  const RefRay outwards = makeRay({0, 0, 0}, {1, 0, 0});
  EXPECT_TRUE(hitIs(outwards, intersectTorus(R, rho, outwards), torusBudget(R, rho, outwards), 1.5L, {-1, 0, 0}));
  // Up through the tube at x = 2: z = -0.5 at t = 2.5.
  const RefRay upwards = makeRay({2, 0, -3}, {0, 0, 1});
  EXPECT_TRUE(hitIs(upwards, intersectTorus(R, rho, upwards), torusBudget(R, rho, upwards), 2.5L, {0, 0, -1}));
  // Obliquely through the tube centred at (0, 2, 0): along (0, 3, 4) / 5 from (0, 2 - 3, -4)
  // reaches the tube centre at t = 1 after 5 units; the surface is 0.5 before: t = 0.9, normal
  // (0, -0.6, -0.8).
  const RefRay oblique = makeRay({0, -1, -4}, {0, 3, 4});
  EXPECT_TRUE(hitIs(oblique, intersectTorus(R, rho, oblique), torusBudget(R, rho, oblique), 0.9L, {0, -0.6L, -0.8L}));
  // Through the hole along the axis, and above the torus: misses.
  EXPECT_FALSE(intersectTorus(R, rho, makeRay({0, 0, -5}, {0, 0, 1})));
  EXPECT_FALSE(intersectTorus(R, rho, makeRay({-5, 0, 0.6L}, {1, 0, 0})));

  // Tangent to the top, z = 0.5, at x = -2 (t = 3): a double root, q''(3) = 32. Its t is only
  // determined to sqrt(2 dq / q''), dq = kRoundings u L^4 (see TorusTangentToItsEquators).
  const RefRay tangent = makeRay({-5, 0, 0.5L}, {1, 0, 0});
  const std::optional<RefHit> touch = intersectTorus(R, rho, tangent);
  ASSERT_TRUE(touch);
  const Real size = 5 + 3 + R + rho;
  EXPECT_LE(std::fabs(touch->t - 3), std::sqrt(2 * kRoundings * kUnitRoundoff * std::pow(size, 4) / 32));
  EXPECT_THROW(intersectTorus(1, 1, tangent), std::invalid_argument);
}

// Lines tangent to the torus' equators at angles whose coordinates are not exact, so that the
// quartic at the double root is not exactly zero and the tangency rule must decide. Each line is
// p(s) = e + (s - 5) w, e on the equator of radius E, w = (-sin phi, cos phi, 0) unit: e is the
// line's point closest to the axis, so sigma = s - 5 and K = E^2 + R^2 - rho^2 - 2 R^2 = 2 R rho
// (outer, E = R + rho) or -2 R rho (inner, E = R - rho), and q''(5) = 4 K: |q''| = 8 R rho.
// A double root is ill-conditioned: q is computed with an error up to dq = kRoundings u L^4
// (L = |o| + |t| + R + rho), and q +- dq has its roots up to sqrt(2 dq / |q''|) from the tangent
// point, so the oracle may answer any t within that (about 1e-7 here; observed about 1e-9).
TEST(OracleTest, TorusTangentToItsEquators) {
  const Real R = 2;
  const Real rho = 0.5L;
  for (int k = 0; k < 24; ++k) {
    const Real phi = 2 * kPi * (k + 0.3L) / 24;
    const V3 radial{std::cos(phi), std::sin(phi), 0};
    const V3 w{-std::sin(phi), std::cos(phi), 0};
    const Real size = 5 + 5 + R + rho;
    const Real bound = std::sqrt(2 * kRoundings * kUnitRoundoff * std::pow(size, 4) / (8 * R * rho));
    // Moving the point along the equator (radius >= R - rho) by `bound` turns the normal by at most
    // bound / (R - rho); twice that for normalising, plus the normal's own roundings.
    const Real normalBound = 2 * bound / (R - rho) + kRoundings * kUnitRoundoff;
    SCOPED_TRACE(testing::Message() << "phi " << double(phi));

    // Outer equator: the line stays outside the tube and touches it at t = 5 (q has a minimum 0).
    const Real outer = R + rho;
    const RefRay touchOuter = makeRay({outer * radial.x - 5 * w.x, outer * radial.y - 5 * w.y, 0}, w);
    const std::optional<RefHit> a = intersectTorus(R, rho, touchOuter);
    ASSERT_TRUE(a);
    EXPECT_LE(std::fabs(a->t - 5), bound);
    EXPECT_NEAR(a->nx, radial.x, normalBound);
    EXPECT_NEAR(a->ny, radial.y, normalBound);

    // Inner equator: the line enters the tube at t = 3 (|p| = R + rho when (s - 5)^2 = 4),
    // touches the inner wall from inside at t = 5 (q has a maximum 0) and leaves at t = 7.
    const Real inner = R - rho;
    const RefRay touchInner = makeRay({inner * radial.x - 5 * w.x, inner * radial.y - 5 * w.y, 0}, w, 4);
    const std::optional<RefHit> b = intersectTorus(R, rho, touchInner);
    ASSERT_TRUE(b);
    EXPECT_LE(std::fabs(b->t - 5), bound);
    EXPECT_NEAR(b->nx, -radial.x, normalBound);
    EXPECT_NEAR(b->ny, -radial.y, normalBound);
  }
}

TEST(OracleTest, TorusMatchesInscribedPolyline) {
  const std::uint64_t seed = seedFor(0x5eed0007);
  TRACE_SEED(seed);
  Random random(seed);
  const Real R = 2;
  const Real rho = 0.6L;
  const int segments = 256;
  // The meridian circle counterclockwise (outward normals), closed: the last point is the first.
  std::vector<Point2> polyline = inscribedArc(R, 0, rho, 0, 2 * kPi, segments);
  polyline.back() = polyline.front();
  const Real halfAngle = kPi / segments;
  const Sandwich sandwich = sandwichOf(rho, halfAngle, R + rho);
  auto outsideOuter = [&](const RefRay& ray) {
    return std::hypot(std::hypot(ray.ox, ray.oy) - R, ray.oz) > sandwich.outer;
  };
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    RefRay ray = randomRay(random, 5, boxOf(R + rho, -rho, rho));
    ray.tnear = 0;
    ray.tfar = kInf;
    if (!outsideOuter(ray)) continue;
    const std::optional<RefHit> poly = intersectProfile(polyline, ray);
    hits += poly.has_value();
    ASSERT_TRUE(sandwiched(ray, intersectTorus(R, sandwich.outer, ray), torusBudget(R, sandwich.outer, ray), poly,
                           profileBudget(polyline, ray), intersectTorus(R, sandwich.inner, ray),
                           torusBudget(R, sandwich.inner, ray)))
        << "ray " << i;
    if (!poly) continue;
    const V3 q = pointAt(ray, poly->t);
    const Real rhoXY = std::hypot(q.x, q.y);
    const V3 fromCore{q.x - R * q.x / rhoXY, q.y - R * q.y / rhoXY, q.z};
    const Real distance = norm(fromCore);
    const V3 circleNormal{fromCore.x / distance, fromCore.y / distance, fromCore.z / distance};
    // (q - core) / distance, the core point moving R / rhoXY times as far as q.
    const Real leverArm = distance * rhoXY / (rhoXY + R);
    ASSERT_TRUE(facetNormalClose(ray, *poly, profileBudget(polyline, ray)(*poly), circleNormal, leverArm, halfAngle))
        << "ray " << i;
  }
  EXPECT_GT(hits, 1000);
}

// Sphere tracing with the torus' exact distance function D(P) = |P - core(P)| - rho, which is
// 1-Lipschitz: stepping by |D| from outside or inside never passes the first root. The trace stops
// within `stopDistance` of the surface; there, for a hit at incidence cosine c, the root is at
// most about stopDistance / c further along the ray (exactly so for a plane; the surface's
// curvature kappa adds a relative stopDistance kappa / c^2, below 1e-3 for the tori and rays kept,
// c >= 0.01, hence the factor 2). The stop distance only sets the test's cost: 2^-30 of the torus'
// size is far above rounding (~1e-18 of it) and far below its features.
struct TracedTorus {
  Real major, minor;
  Real reachOfOrigins;
};

TEST(OracleTest, TorusMatchesSphereTracing) {
  const std::uint64_t seed = seedFor(0x5eed0008);
  TRACE_SEED(seed);
  Random random(seed);
  const Real minCosine = 0.01L;
  // A middling torus, a thin one, a nearly horn one, and one seen from far away.
  for (const TracedTorus torus :
       {TracedTorus{1.5L, 0.7L, 4}, TracedTorus{1, 0.05L, 3}, TracedTorus{1, 0.95L, 4}, TracedTorus{1.5L, 0.7L, 200}}) {
    const Real R = torus.major;
    const Real rho = torus.minor;
    SCOPED_TRACE(testing::Message() << "torus R " << double(R) << " rho " << double(rho) << " origins within "
                                    << double(torus.reachOfOrigins));
    const Real stopDistance = std::ldexp(R + rho, -30);
    auto distance = [&](V3 p) { return std::hypot(std::hypot(p.x, p.y) - R, p.z) - rho; };
    int compared = 0;
    int skipped = 0;  // grazing or needing over a million steps
    for (int i = 0; i < 2000; ++i) {
      RefRay ray = randomRay(random, torus.reachOfOrigins, boxOf(R + rho, -rho, rho));
      // Half the rays start at the origin, half further on (maybe inside the tube, maybe past it).
      ray.tnear = random.chance(0.5) ? 0 : random.uniform(0, 1);
      ray.tfar = kInf;
      const Real v = speed(ray);
      Real s = ray.tnear * v;  // arc length from the origin
      if (std::fabs(distance(pointAt(ray, s / v))) <= stopDistance) continue;
      const std::optional<RefHit> hit = intersectTorus(R, rho, ray);
      if (hit && cosIncidence(ray, *hit) < minCosine) {
        ++skipped;
        continue;
      }
      // March; stop once past the sphere |P| = R + rho, which holds the torus: the line leaves it
      // before s = -O.u + (R + rho).
      const Real sExit = -dot(originOf(ray), directionOf(ray)) / v + (R + rho);
      std::optional<Real> stop;
      int steps = 0;
      for (; steps < 1000000 && s <= sExit; ++steps) {
        const Real d = std::fabs(distance(pointAt(ray, s / v)));
        if (d <= stopDistance) {
          stop = s / v;
          break;
        }
        s += d;
      }
      if (steps == 1000000) {
        ++skipped;
        continue;
      }
      ++compared;
      ASSERT_EQ(hit.has_value(), stop.has_value()) << "ray " << i << " " << describe(ray) << ": " << describe(hit);
      if (!hit) continue;
      const Real tBound = tError(torusBudget(R, rho, ray)(*hit), ray, *hit);
      ASSERT_GE(hit->t, *stop - tBound) << "ray " << i << " " << describe(ray);
      ASSERT_LE(hit->t - *stop, 2 * stopDistance / (v * cosIncidence(ray, *hit)) + tBound)
          << "ray " << i << " " << describe(ray);
    }
    EXPECT_GT(compared, 1500);
    EXPECT_LT(skipped, 50);
  }
}

// ---------------------------------------------------------------------------------------------
// Distance.

TEST(OracleTest, MeridianDistanceHandCases) {
  // Each answer is a hypot of differences of inputs below 8 (a projection and a clamp first): at
  // most 8 roundings, each <= u relative, of values below 8.
  const Real bound = 8 * kUnitRoundoff * 8;
  const std::vector<Point2> side{{1, 0}, {1, 2}};
  EXPECT_NEAR(meridianDistance(side, 3, 0, 1), 2, bound);
  EXPECT_NEAR(meridianDistance(side, 0, 0, 1), 1, bound);           // on the axis
  EXPECT_NEAR(meridianDistance(side, 3, 4, 1), 4, bound);           // rho = 5
  EXPECT_NEAR(meridianDistance(side, 0, -1, 3), 1, bound);          // beyond the end: to the point (1, 2)
  EXPECT_NEAR(meridianDistance(side, 0.6L, 0.8L, 0.5L), 0, bound);  // rho = 1 up to rounding
  EXPECT_NEAR(meridianDistance(side, 4, 0, 6), 5, bound);           // 3-4-5 to (1, 2)

  const std::vector<Point2> corner{{0, 0}, {2, 0}, {2, 2}};
  EXPECT_NEAR(meridianDistance(corner, 3, 0, 3), std::sqrt(Real(2)), bound);
  EXPECT_NEAR(meridianDistance(corner, 1, 0, 0.5L), 0.5L, bound);  // nearer the disc than the side
  EXPECT_NEAR(meridianDistance(corner, 0, 1.5L, 1), 0.5L, bound);  // nearer the side
  EXPECT_NEAR(meridianDistance(corner, 0, 0, -2), 2, bound);

  // The segment (0, 0) - (1, 1) of the cone r = z. (0, 1) projects inside it, at (0.5, 0.5);
  // (0, 2) projects past its end, so the nearest point is (1, 1); (2, -1) projects to (0.5, 0.5),
  // nearer than the apex (sqrt 5).
  const std::vector<Point2> cone{{0, 0}, {1, 1}};
  EXPECT_NEAR(meridianDistance(cone, 0, 0, 1), std::sqrt(Real(2)) / 2, bound);
  EXPECT_NEAR(meridianDistance(cone, 0, 0, 2), std::sqrt(Real(2)), bound);
  EXPECT_NEAR(meridianDistance(cone, 2, 0, -1), 1.5L * std::sqrt(Real(2)), bound);
  EXPECT_NEAR(meridianDistance(cone, 0, -3, -4), 5, bound);  // projects before the apex: to (0, 0)
}

}  // namespace
