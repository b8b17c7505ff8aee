// Spline shapes traced exactly: against closed forms (a sphere and a torus made of cubic arcs, whose
// distance from the true surface is known), against the long-double oracle (support/curve_reference),
// and through the hard cases of the polyline kernel (seams, apexes, rays along and across the axis,
// tangent and nearly horizontal rays, far origins, every hit on the surface), for every search.
// Each property test prints "spline case | search | rays | wrong" for README's table.
#include "support/curve_reference.h"
#include "support/hard_profiles.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"
#include "support/test_scale.h"

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace revolve {
namespace {

constexpr double kFloatRoundoff = 0x1p-24;

struct Variant {
  const char* name;
  BuildOptions options;
};

const Variant kVariants[] = {
    {"mibit (wide, the default)", {}},
    {"mibit/cylinder/binary", {.method = Method::mibit, .shell = ShellKind::cylinder, .wideNodes = false}},
    {"mibit/hybrid", {.method = Method::mibit, .shell = ShellKind::hybrid}},
    {"mibit/cone", {.method = Method::mibit, .shell = ShellKind::cone}},
    {"mibit/no split", {.method = Method::mibit, .shell = ShellKind::cylinder, .monotoneSplit = false}},
    {"linear", {.method = Method::linear}},
};

// The costliest property tests (an oracle distance per hit) run on the default search; every
// other search gives the same hits bit for bit (SplineAgreementTest).
const Variant kDefaultOnly[] = {kVariants[0]};

reference::RefRay toRef(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

double norm(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

void report(const char* hardCase, const char* variant, std::size_t rays, std::size_t wrong) {
  std::printf("spline case | %s | %s | %zu rays | %zu wrong\n", hardCase, variant, rays, wrong);
}

struct Built {
  testing::NamedSpline named;
  Spline spline;
};

std::vector<Built> closedSplines() {
  std::vector<Built> built;
  for (const testing::NamedSpline& named : testing::closedSplines())
    built.push_back({named, Spline(named.kind, named.points)});
  return built;
}

// ---------------------------------------------------------------------------------------------
// Closed forms.

// First root t >= 0 of |o + t d - c|^2 = R^2 (long double), or -1.
long double sphereHit(const Ray& ray, long double radius) {
  const long double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
  const long double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  const long double a = dx * dx + dy * dy + dz * dz, b = ox * dx + oy * dy + oz * dz,
                    c = ox * ox + oy * oy + oz * oz - radius * radius;
  const long double disc = b * b - a * c;
  if (disc < 0) return -1;
  const long double t0 = (-b - std::sqrt(disc)) / a, t1 = (-b + std::sqrt(disc)) / a;
  return t0 >= 0 ? t0 : t1 >= 0 ? t1 : -1;
}

TEST(SplineAnalyticTest, CubicArcSphereLiesBetweenTheSphereAndItsKnownOffset) {
  // Each 180/n-degree cubic arc lies outside its circle by at most arcError (Goldapp 1991). So a ray
  // meeting the inner sphere meets the surface, one missing the outer sphere misses it, and a hit
  // lies between the two spheres, its normal within the arc's turning error of the radial one.
  std::mt19937_64 random(41);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const double radius = 0.5;
  for (const int pieces : {2, 4, 8}) {
    const double error = testing::arcError(radius, std::numbers::pi / pieces);
    for (const Variant& variant : kVariants) {
      const Shape shape(Spline(SplineKind::bezier, testing::bezierSphere(radius, pieces)), variant.options);
      std::size_t fired = 0, wrong = 0;
      for (int i = 0; i < 20000; ++i) {
        const Vec3 o{2 * u(random), 2 * u(random), 2 * u(random)};
        const Vec3 target{0.6f * u(random), 0.6f * u(random), 0.6f * u(random)};
        const Ray ray{o, {target.x - o.x, target.y - o.y, target.z - o.z}};
        if (norm(ray.origin) < radius + error + 1e-3) continue;  // from outside
        ++fired;
        const std::optional<Hit> hit = intersect(shape, ray);
        const long double inner = sphereHit(ray, radius), outer = sphereHit(ray, radius + error);
        const double slack = 4 * kFloatRoundoff;  // the float point and t, at distance ~2
        bool ok;
        if (!hit) {
          ok = inner < 0;
        } else {
          const double distance = norm(hit->point) - radius;
          const double dn = norm(ray.direction);
          ok = outer >= 0 && distance >= -slack && distance <= error + slack && (hit->t - outer) * dn >= -slack &&
               (inner < 0 || (inner - hit->t) * dn >= -slack);
          // The normal against the radial direction: the arc's radial error e(phi) is at most `error`
          // and its slope at most about 6 error / (theta / 2), which tilts the normal by that angle.
          // Measured by the sine (the cross product), which float rounding disturbs by ~1e-7 only.
          const Vec3 n = hit->normal, p = hit->point;
          const double sine = norm({n.y * p.z - n.z * p.y, n.z * p.x - n.x * p.z, n.x * p.y - n.y * p.x}) / norm(p);
          ok = ok && sine <= 12 * error / (radius * std::numbers::pi / pieces) + 1e-6;
        }
        if (!ok && ++wrong <= 3)
          ADD_FAILURE() << variant.name << ", " << pieces << " arcs: hit " << (hit ? hit->t : -1.0f);
      }
      EXPECT_EQ(wrong, 0u) << variant.name;
      if (pieces == 4) report("cubic-arc sphere between its closed-form bounds", variant.name, fired, wrong);
    }
  }
}

TEST(SplineAnalyticTest, CubicArcTorusLiesBetweenTheTorusAndItsKnownOffset) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const double major = 0.6, minor = 0.25;
  const int pieces = 8;
  const double error = testing::arcError(minor, 2 * std::numbers::pi / pieces);
  for (const Variant& variant : kVariants) {
    const Shape shape(Spline(SplineKind::bezier, testing::bezierTorus(major, minor, pieces)), variant.options);
    std::size_t fired = 0, wrong = 0;
    for (int i = 0; i < 8000; ++i) {
      const Vec3 o{2 * u(random), 2 * u(random), 2 * u(random)};
      const Vec3 target{0.9f * u(random), 0.9f * u(random), 0.3f * u(random)};
      const Ray ray{o, {target.x - o.x, target.y - o.y, target.z - o.z}};
      const reference::RefRay ref = toRef(ray);
      if (std::hypot(std::hypot(double(o.x), double(o.y)) - major, double(o.z)) < minor + error + 1e-3)
        continue;  // from outside
      ++fired;
      const std::optional<Hit> hit = intersect(shape, ray);
      const auto inner = reference::intersectTorus(major, minor, ref),
                 outer = reference::intersectTorus(major, minor + error, ref);
      const double slack = 4 * kFloatRoundoff;
      bool ok;
      if (!hit) {
        ok = !inner.has_value();
      } else {
        const double rho = std::hypot(double(hit->point.x), double(hit->point.y));
        const double distance = std::hypot(rho - major, double(hit->point.z)) - minor;
        const double dn = norm(ray.direction);
        ok = outer.has_value() && distance >= -slack && distance <= error + slack &&
             (hit->t - double(outer->t)) * dn >= -slack && (!inner || (double(inner->t) - hit->t) * dn >= -slack);
      }
      if (!ok && ++wrong <= 3) {
        ADD_FAILURE() << variant.name << ": hit " << (hit ? hit->t : -1.0f) << ", torus "
                      << (inner ? double(inner->t) : -1.0) << ", offset torus " << (outer ? double(outer->t) : -1.0);
      }
    }
    report("cubic-arc torus between its closed-form bounds", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u) << variant.name;
  }
}

// ---------------------------------------------------------------------------------------------
// The long-double oracle.

// Rays for each closed spline, with the oracle's answers computed once and shared by every search.
struct OracleCase {
  const Built* built;
  std::vector<Ray> rays;
  std::vector<std::optional<reference::RefHit>> expected;
  std::vector<int> fragile;  // -1 unknown, else whether a 1e-9 nudge changes the oracle's verdict
  double size;
};

template <class MakeRays>
std::vector<OracleCase> oracleCases(const std::vector<Built>& splines, MakeRays&& makeRays) {
  std::vector<OracleCase> cases;
  for (const Built& s : splines) {
    const Shape shape(s.spline);
    OracleCase c{&s, makeRays(shape), {}, {}, norm(shape.bounds().upper)};
    for (const Ray& ray : c.rays) c.expected.push_back(reference::intersectCurve(s.spline.bezier(), toRef(ray)));
    c.fragile.assign(c.rays.size(), -1);
    cases.push_back(std::move(c));
  }
  return cases;
}

// Every search against the oracle: disagreements that a 1e-9 nudge of the ray does not explain.
void checkAgainstOracle(const char* name, std::vector<OracleCase>& cases) {
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (OracleCase& c : cases) {
      SCOPED_TRACE(std::string(variant.name) + ", " + c.built->named.name);
      const Shape shape(c.built->spline, variant.options);
      for (std::size_t i = 0; i < c.rays.size(); ++i) {
        const Ray& ray = c.rays[i];
        const std::optional<Hit> got = intersect(shape, ray);
        const std::optional<reference::RefHit>& expected = c.expected[i];
        const double dn = norm(ray.direction);
        ++fired;
        if (got.has_value() == expected.has_value() &&
            (!got || std::abs(got->t - double(expected->t)) * dn <= 0x1p-22 * (std::abs(got->t) * dn + c.size))) {
          continue;
        }
        if (c.fragile[i] < 0)
          c.fragile[i] = reference::curveVerdictIsFragile(c.built->spline.bezier(), toRef(ray), 1e-9L * c.size, c.size);
        if (c.fragile[i] == 1) continue;
        if (++wrong <= 3) {
          ADD_FAILURE() << "o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                        << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << "): library "
                        << (got ? got->t : -1.0f) << ", oracle " << (expected ? double(expected->t) : -1.0);
        }
      }
    }
    report(name, variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u) << variant.name;
  }
}

TEST(SplineOracleTest, IncoherentRaysAgreeWithTheLongDoubleOracle) {
  std::mt19937_64 random(43);
  const std::vector<Built> splines = closedSplines();
  std::vector<OracleCase> cases = oracleCases(
      splines, [&](const Shape& shape) { return testing::incoherentRays(shape, random, testing::scaledRays(1000)); });
  checkAgainstOracle("incoherent rays against the long-double oracle", cases);
}

TEST(SplineOracleTest, AxisAlignedRaysAgreeWithTheLongDoubleOracle) {
  // Along the axis, through it, perpendicular to it (in the planes of the parts' ends half the time).
  std::mt19937_64 random(44);
  const std::vector<Built> splines = closedSplines();
  std::vector<OracleCase> cases = oracleCases(
      splines, [&](const Shape& shape) { return testing::axisAlignedRays(shape, random, testing::scaledRays(600)); });
  checkAgainstOracle("rays along, through and perpendicular to the axis", cases);
}

TEST(SplineOracleTest, NearlyHorizontalRaysAgreeWithTheLongDoubleOracle) {
  // |dz| from 1e-15 to 1e-3: the ray's stretch in a part's slab is up to 10^15 times the shape,
  // which the kernel restricts to the bounding sphere before solving (curve_hits.h).
  std::mt19937_64 random(45);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-15.0, -3.0);
  const std::vector<Built> splines = closedSplines();
  std::vector<OracleCase> cases = oracleCases(splines, [&](const Shape& shape) {
    const Bounds box = shape.bounds();
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < testing::scaledRays(120); ++i) {
      const double phi = std::numbers::pi * unit(random), offset = box.upper.x * unit(random);
      const double height = box.lower.z + (box.upper.z - box.lower.z) * 0.5 * (1 + unit(random));
      const float dz = float(std::pow(10.0, exponent(random)) * (unit(random) < 0 ? -1 : 1));
      const double c = std::cos(phi), sn = std::sin(phi);
      rays.push_back(
          {{float(3 * c - offset * sn), float(3 * sn + offset * c), float(height)}, {float(-c), float(-sn), dz}});
    }
    return rays;
  });
  checkAgainstOracle("nearly horizontal rays (|dz| 1e-15 to 1e-3)", cases);
}

TEST(SplineAgreementTest, EverySearchGivesTheSameHitBitForBit) {
  // Every part's hits are computed over the same range whatever the search, and ties go to the
  // lower part: the nearest hit cannot depend on the search.
  std::mt19937_64 random(54);
  const std::vector<Built> splines = closedSplines();
  std::size_t fired = 0, wrong = 0;
  for (const Built& s : splines) {
    const Shape reference(s.spline);
    std::vector<Ray> rays = testing::incoherentRays(reference, random, testing::scaledRays(4000));
    const std::vector<Ray> awkward = testing::axisAlignedRays(reference, random, testing::scaledRays(2000));
    rays.insert(rays.end(), awkward.begin(), awkward.end());
    for (const Variant& variant : kVariants) {
      const Shape shape(s.spline, variant.options);
      for (const Ray& ray : rays) {
        const std::optional<Hit> a = intersect(reference, ray), b = intersect(shape, ray);
        ++fired;
        const bool same =
            a.has_value() == b.has_value() &&
            (!a || (a->t == b->t && a->normal.x == b->normal.x && a->normal.y == b->normal.y &&
                    a->normal.z == b->normal.z && a->u == b->u && a->v == b->v && a->segment == b->segment));
        const bool anySame = occluded(shape, ray) == a.has_value();
        if ((!same || !anySame) && ++wrong <= 3) ADD_FAILURE() << s.named.name << ", " << variant.name;
      }
    }
  }
  std::printf("spline searches agree bit for bit: %zu rays, %zu differ\n", fired, wrong);
  EXPECT_EQ(wrong, 0u);
}

// ---------------------------------------------------------------------------------------------
// Seams and apexes.

TEST(SplineHardCasesTest, RaysFromInsideAimedAtPartEndsNeverLeak) {
  // The circles where parts meet (the knots, including the splits at r and z extrema, the pinch
  // and the poles on the axis): a ray from inside the solid aimed at one must be reported leaving.
  constexpr std::uint64_t kSeed = 0x5b1e;
  std::mt19937_64 random(kSeed);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  const std::vector<Built> splines = closedSplines();
  for (const Variant& variant : kVariants) {
    const std::size_t perSpline =
        testing::scaledRays(variant.options.method == Method::mibit && variant.options.wideNodes &&
                                    variant.options.shell == ShellKind::cylinder && variant.options.monotoneSplit
                                ? 50'000
                                : 10'000);
    std::size_t fired = 0, leaks = 0;
    for (const Built& s : splines) {
      SCOPED_TRACE(std::string(variant.name) + ", " + s.named.name + ", seed " + std::to_string(kSeed));
      const Shape shape(s.spline, variant.options);
      const std::vector<Point2> outline = testing::densePolyline(s.spline.bezier(), 256);
      const std::vector<Vec3> origins = testing::interiorPoints(outline, random, 256, 1e-3);
      const std::span<const Point2> knots = shape.profile().points();
      for (std::size_t i = 0; i < perSpline; ++i) {
        const Point2 knot = knots[random() % knots.size()];
        const double phi = angle(random);
        const Vec3 target{float(knot.r * std::cos(phi)), float(knot.r * std::sin(phi)), float(knot.z)};
        const Vec3 o = origins[i % origins.size()];
        const Ray ray{o, {target.x - o.x, target.y - o.y, target.z - o.z}};
        ++fired;
        if (intersect(shape, ray)) continue;
        if (++leaks <= 3) {
          ADD_FAILURE() << "leak: o=(" << o.x << ", " << o.y << ", " << o.z << ") d=(" << ray.direction.x << ", "
                        << ray.direction.y << ", " << ray.direction.z << ")";
        }
      }
    }
    report("seams: rays from inside at the parts' end circles", variant.name, fired, leaks);
    EXPECT_EQ(leaks, 0u);
  }
}

TEST(SplineHardCasesTest, RaysThroughAnApexHitIt) {
  // Rays exactly through a point of the curve on the axis (the sphere's smooth poles, the
  // hourglass's pinch and its flat ends' centres), in every direction: the first hit is there or before.
  std::mt19937_64 random(46);
  std::uniform_int_distribution<int> sixteenths(-32, 32);
  struct ApexCase {
    const char* name;
    SplineKind kind;
    std::vector<Point2> points;
    Vec3 apex;
  };
  std::vector<ApexCase> cases = {
      {"sphere, south pole", SplineKind::bezier, testing::bezierSphere(0.5, 4), {0, 0, -0.5f}},
      {"sphere, north pole", SplineKind::bezier, testing::bezierSphere(0.5, 4), {0, 0, 0.5f}}};
  for (const testing::NamedSpline& s : testing::closedSplines()) {
    if (s.name.find("hourglass") != std::string::npos)
      cases.push_back({"hourglass pinch", s.kind, s.points, {0, 0, 0}});
  }
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (const ApexCase& c : cases) {
      const Shape shape(Spline(c.kind, c.points), variant.options);
      for (int i = 0; i < 3000; ++i) {
        const Vec3 d{sixteenths(random) / 16.0f, sixteenths(random) / 16.0f, sixteenths(random) / 16.0f};
        if (norm(d) == 0.0) continue;
        const Vec3 origin{c.apex.x - 2 * d.x, c.apex.y - 2 * d.y, c.apex.z - 2 * d.z};
        const std::optional<Hit> hit = intersect(shape, {origin, d});
        ++fired;
        if (!hit || hit->t > 2.0f * (1 + 4 * float(kFloatRoundoff))) {
          if (++wrong <= 3)
            ADD_FAILURE() << variant.name << ", " << c.name << ": d=(" << d.x << ", " << d.y << ", " << d.z << ")";
        }
      }
    }
    report("apex: rays through a point on the axis hit it", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(SplineHardCasesTest, NearlyHorizontalRaysGrazingThePinchStayOnTheSurface) {
  std::mt19937_64 random(47);
  std::uniform_real_distribution<double> u(-1.0, 1.0), exponent(-13.0, -9.0);
  std::vector<Point2> hourglass;
  for (const testing::NamedSpline& s : testing::closedSplines()) {
    if (s.name.find("hourglass") != std::string::npos) hourglass = s.points;
  }
  const Spline spline(SplineKind::bezier, hourglass);
  for (const Variant& variant : kDefaultOnly) {
    const Shape shape(spline, variant.options);
    std::size_t fired = 0, wrong = 0;
    for (int i = 0; i < 5000; ++i) {
      const float dz = float(std::pow(10.0, exponent(random)) * (u(random) < 0 ? -1 : 1));
      const Ray ray{{-3.0f, float(2e-15 * u(random)), float(2e-15 * u(random)) - 3.0f * dz}, {1.0f, 0.0f, dz}};
      ++fired;
      const std::optional<Hit> hit = intersect(shape, ray);
      if (!hit) continue;
      const long double x = ray.origin.x + (long double)hit->t * ray.direction.x,
                        y = ray.origin.y + (long double)hit->t * ray.direction.y,
                        z = ray.origin.z + (long double)hit->t * ray.direction.z;
      const double residual = double(reference::curveMeridianDistance(spline.bezier(), x, y, z));
      if (residual > 8 * kFloatRoundoff * 3.0 && ++wrong <= 3)
        ADD_FAILURE() << "dz " << dz << ": residual " << residual;
    }
    report("apex: nearly horizontal rays grazing the pinch stay on the surface", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Grazing rays, far origins, and every hit's accuracy.

TEST(SplineHardCasesTest, TangentRaysGiveNoNaNAndNoHitOffTheSurface) {
  std::mt19937_64 random(48);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::vector<Built> splines = closedSplines();
  for (const Variant& variant : kDefaultOnly) {
    std::size_t fired = 0, wrong = 0;
    for (const Built& s : splines) {
      const Shape shape(s.spline, variant.options);
      const double size = norm(shape.bounds().upper);
      for (int i = 0; i < 600; ++i) {
        const std::size_t piece = random() % s.spline.pieceCount();
        const double t = unit(random), phi = 2 * std::numbers::pi * unit(random);
        const Point2 p = s.spline.at(piece, t);
        const Point2 a = s.spline.at(piece, std::max(0.0, t - 1e-7)), b = s.spline.at(piece, std::min(1.0, t + 1e-7));
        const double len = std::hypot(b.r - a.r, b.z - a.z);
        if (!(len > 0)) continue;
        const double er = (b.r - a.r) / len, ez = (b.z - a.z) / len;  // the curve's tangent
        const double w = 2 * unit(random) - 1, tphi = std::sqrt(std::max(0.0, 1 - w * w));
        const Vec3 d{float(w * er * std::cos(phi) - tphi * std::sin(phi)),
                     float(w * er * std::sin(phi) + tphi * std::cos(phi)), float(w * ez)};
        const Vec3 q{float(p.r * std::cos(phi)), float(p.r * std::sin(phi)), float(p.z)};
        const Ray ray{{q.x - d.x * float(size), q.y - d.y * float(size), q.z - d.z * float(size)}, d};
        ++fired;
        const std::optional<Hit> hit = intersect(shape, ray);
        if (!hit) continue;
        const bool finite = std::isfinite(hit->t) && std::isfinite(hit->normal.x) && std::isfinite(hit->normal.y) &&
                            std::isfinite(hit->normal.z) && std::isfinite(hit->u) && std::isfinite(hit->v);
        const double residual =
            double(reference::curveMeridianDistance(s.spline.bezier(), hit->point.x, hit->point.y, hit->point.z));
        if (!finite || residual > 4 * kFloatRoundoff * (norm(hit->point) + size)) {
          if (++wrong <= 3) ADD_FAILURE() << s.named.name << ", " << variant.name << ": residual " << residual;
        }
      }
    }
    report("grazing and tangent rays: NaN or hit off the surface", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(SplineHardCasesTest, FarOriginsAndExtremeScalesKeepTheInputsPrecision) {
  std::mt19937_64 random(49);
  std::normal_distribution<double> gauss;
  struct Setting {
    double scale, lift, distance;
  };
  const Setting settings[] = {{1, 0, 1e4}, {1e-3, 0, 1e4}, {1e3, 0, 1e4}, {1e-3, 1.0, 10}, {1e3, 1e6, 10}};
  std::vector<Point2> base;
  for (const testing::NamedSpline& s : testing::closedSplines()) {
    if (s.name.find("bottle") != std::string::npos) base = s.points;
  }
  for (const Variant& variant : kDefaultOnly) {
    std::size_t fired = 0, wrong = 0;
    for (const Setting& setting : settings) {
      std::vector<Point2> points;
      for (const Point2& p : base) points.push_back({p.r * setting.scale, p.z * setting.scale + setting.lift});
      const Spline spline(SplineKind::bezier, points);
      const Shape shape(spline, variant.options);
      const Bounds box = shape.bounds();
      const double size = norm({box.upper.x, box.upper.y, 0.5f * (box.upper.z - box.lower.z)});
      const double cz = 0.5 * (double(box.lower.z) + box.upper.z);
      std::uniform_real_distribution<double> inBox(0.0, 1.0);
      for (int i = 0; i < 1000; ++i) {
        const double gx = gauss(random), gy = gauss(random), gz = gauss(random),
                     g = std::sqrt(gx * gx + gy * gy + gz * gz);
        const double reach = setting.distance * size;
        const Vec3 origin{float(reach * gx / g), float(reach * gy / g), float(cz + reach * gz / g)};
        const Vec3 target{float(box.lower.x + inBox(random) * (box.upper.x - box.lower.x)),
                          float(box.lower.y + inBox(random) * (box.upper.y - box.lower.y)),
                          float(box.lower.z + inBox(random) * (box.upper.z - box.lower.z))};
        const Ray ray{origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}};
        ++fired;
        const std::optional<Hit> got = intersect(shape, ray);
        const auto expected = reference::intersectCurve(spline.bezier(), toRef(ray));
        const double dn = norm(ray.direction);
        const double resolution = kFloatRoundoff * (norm(origin) + size);
        bool ok = got.has_value() == expected.has_value();
        if (ok && got) {
          const double cosine = std::abs(double(expected->nx * ray.direction.x + expected->ny * ray.direction.y +
                                                expected->nz * ray.direction.z)) /
                                dn;
          ok = std::abs(got->t - double(expected->t)) * dn <=
               2 * kFloatRoundoff * got->t * dn + 4 * resolution / std::max(cosine, 1e-3);
          const double residual =
              double(reference::curveMeridianDistance(spline.bezier(), got->point.x, got->point.y, got->point.z));
          ok = ok && residual <= 4 * kFloatRoundoff * (norm(got->point) + size);
        }
        if (!ok) {
          bool fragile = false;
          for (int axis = 0; axis < 3 && !fragile; ++axis) {
            for (double sign : {-1.0, 1.0}) {
              reference::RefRay moved = toRef(ray);
              (axis == 0 ? moved.ox : axis == 1 ? moved.oy : moved.oz) += sign * resolution;
              fragile |= reference::intersectCurve(spline.bezier(), moved).has_value() != expected.has_value();
            }
          }
          if (!fragile && ++wrong <= 3) {
            ADD_FAILURE() << "scale " << setting.scale << ": oracle " << (expected ? double(expected->t) : -1.0)
                          << ", library " << (got ? got->t : -1.0f);
          }
        }
      }
    }
    report("far origins (1e4 sizes), sizes 1e-3..1e3, objects far from the origin", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(SplineHardCasesTest, EveryHitLiesOnTheSurfaceWithAUnitConsistentNormal) {
  // Every hit within a few float ulps of the curve's surface (the oracle's distance), its normal
  // unit and that of the oracle's hit, v within the part's range and the same from the other side.
  std::mt19937_64 random(50);
  const std::vector<Built> splines = closedSplines();
  for (const Variant& variant : kDefaultOnly) {
    std::size_t fired = 0, wrong = 0;
    for (const Built& s : splines) {
      SCOPED_TRACE(std::string(variant.name) + ", " + s.named.name);
      const Shape shape(s.spline, variant.options);
      const double size = norm(shape.bounds().upper);
      for (const Ray& ray : testing::incoherentRays(shape, random, testing::scaledRays(500))) {
        const std::optional<Hit> hit = intersect(shape, ray);
        if (!hit) continue;
        ++fired;
        const double residual =
            double(reference::curveMeridianDistance(s.spline.bezier(), hit->point.x, hit->point.y, hit->point.z));
        const auto expected = reference::intersectCurve(s.spline.bezier(), toRef(ray));
        bool sameNormal = true;
        if (expected && std::abs(double(expected->t) - hit->t) * norm(ray.direction) < 1e-5 * size) {
          sameNormal = norm({float(hit->normal.x - double(expected->nx)), float(hit->normal.y - double(expected->ny)),
                             float(hit->normal.z - double(expected->nz))}) < 1e-5;
        }
        const std::span<const double> arc = shape.profile().arcLength();
        const double v0 = arc[hit->segment] / arc.back(), v1 = arc[hit->segment + 1] / arc.back();
        const bool vInPart = hit->v >= float(v0) - 1e-6f && hit->v <= float(v1) + 1e-6f;
        const bool ok = residual <= 4 * kFloatRoundoff * (norm(hit->point) + size) &&
                        std::abs(norm(hit->normal) - 1.0) <= 4 * kFloatRoundoff && sameNormal && vInPart;
        if (!ok && ++wrong <= 3) {
          ADD_FAILURE() << "residual " << residual << ", |n| " << norm(hit->normal) << ", same normal " << sameNormal
                        << ", v " << hit->v << " in [" << v0 << ", " << v1 << "]";
        }
      }
    }
    report("every hit: on the surface, unit normal (the oracle's), v in its part", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(SplineHardCasesTest, VIsTheNormalisedArcLength) {
  // v along the sphere's meridian from the south pole: the arc's angle over pi, to the arcs' error.
  const double radius = 0.5;
  const Shape shape{Spline(SplineKind::bezier, testing::bezierSphere(radius, 8))};
  const double error = testing::arcError(radius, std::numbers::pi / 8);
  for (int i = 1; i < 200; ++i) {
    const double theta = std::numbers::pi * i / 200 - std::numbers::pi / 2;  // latitude
    const Ray ray{{float(3 * std::cos(theta)), 0.0f, float(3 * std::sin(theta))},
                  {float(-std::cos(theta)), 0.0f, float(-std::sin(theta))}};
    const std::optional<Hit> hit = intersect(shape, ray);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->v, (theta + std::numbers::pi / 2) / std::numbers::pi, 20 * error + 1e-6) << theta;
  }
}

TEST(SplineHardCasesTest, VIsTheCurvesNormalisedArcLength) {
  // v at every hit against the arc length of the curve up to the hit's point, summed here over
  // chords of 20,000 steps a piece (their shortfall ~1e-10 of the length), over the total.
  std::mt19937_64 random(55);
  std::size_t hits = 0, wrong = 0;
  for (const Built& s : closedSplines()) {
    const std::span<const Point2> c = s.spline.bezier();
    const std::size_t pieces = s.spline.pieceCount();
    constexpr int kSteps = 20000;
    std::vector<double> cumulative{0.0};  // at every step of every piece
    for (std::size_t i = 0; i < pieces; ++i) {
      Point2 previous = s.spline.at(i, 0.0);
      for (int k = 1; k <= kSteps; ++k) {
        const Point2 p = s.spline.at(i, double(k) / kSteps);
        cumulative.push_back(cumulative.back() + std::hypot(p.r - previous.r, p.z - previous.z));
        previous = p;
      }
    }
    const Shape shape(s.spline);
    for (const Ray& ray : testing::incoherentRays(shape, random, 400)) {
      const std::optional<Hit> hit = intersect(shape, ray);
      if (!hit) continue;
      ++hits;
      // The curve's nearest sample to the hit point, on the hit's own Bezier piece, then the point's
      // projection on the step from it towards the nearer neighbour.
      const double rho = std::hypot(double(hit->point.x), double(hit->point.y)), z = hit->point.z;
      const std::size_t piece = shape.splinePiece(hit->segment);
      double best = INFINITY;
      int nearest = 0;
      for (int k = 0; k <= kSteps; ++k) {
        const Point2 p = s.spline.at(piece, double(k) / kSteps);
        const double d = std::hypot(p.r - rho, p.z - z);
        if (d < best) best = d, nearest = k;
      }
      double expected = cumulative[piece * kSteps + nearest];
      for (const int next : {nearest - 1, nearest + 1}) {
        if (next < 0 || next > kSteps) continue;
        const Point2 a = s.spline.at(piece, double(nearest) / kSteps), b = s.spline.at(piece, double(next) / kSteps);
        const double length = std::hypot(b.r - a.r, b.z - a.z);
        const double along = ((rho - a.r) * (b.r - a.r) + (z - a.z) * (b.z - a.z)) / length;
        if (along > 0) expected += (next > nearest ? 1 : -1) * std::min(along, length);
      }
      expected /= cumulative.back();
      if (std::abs(hit->v - expected) > 1e-6 && ++wrong <= 3) {
        ADD_FAILURE() << s.named.name << ": v " << hit->v << ", arc length " << expected << " (c " << c.size() << ")";
      }
    }
  }
  std::printf("v against the curve's arc length: %zu hits, %zu off by more than 1e-6\n", hits, wrong);
  EXPECT_EQ(wrong, 0u);
}

// ---------------------------------------------------------------------------------------------
// Closest points and clearance on a curve.

TEST(SplineClosestPointTest, MatchesTheOraclesDistanceToTheCurve) {
  std::mt19937_64 random(51);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  for (const Built& s : closedSplines()) {
    const Shape shape(s.spline);
    for (int i = 0; i < 300; ++i) {
      const Vec3 p{u(random), u(random), u(random)};
      const SurfacePoint closest = closestPoint(shape, p);
      const double expected = double(reference::curveMeridianDistance(s.spline.bezier(), p.x, p.y, p.z));
      EXPECT_NEAR(closest.distance, expected, 1e-6 * (1 + expected)) << s.named.name;
      // The point it names lies on the surface, at that distance.
      EXPECT_LE(double(reference::curveMeridianDistance(s.spline.bezier(), closest.point.x, closest.point.y,
                                                        closest.point.z)),
                1e-6);
      const MeridianPoint m = closestMeridianPoint(shape, {std::hypot(double(p.x), double(p.y)), double(p.z)});
      EXPECT_NEAR(m.distance, expected, 1e-9 * (1 + expected)) << s.named.name;
    }
  }
}

TEST(SplineClosestPointTest, CylinderClearanceMatchesDenseSampling) {
  // The signed distance from the cylinder's rectangle to the curve, against the least over 20,000
  // points a piece (the sampling's own error is below the tolerance).
  std::mt19937_64 random(52);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Built& s : closedSplines()) {
    const Shape shape(s.spline);
    for (int i = 0; i < 40; ++i) {
      const UprightCylinder cylinder{1.2 * u(random), 0.3 * u(random), -0.6 + 1.2 * u(random), 0.0};
      UprightCylinder c = cylinder;
      c.zMax = c.zMin + 0.4 * u(random);
      const CylinderClearance got = cylinderClearance(shape, c);
      double best = INFINITY;
      for (std::size_t piece = 0; piece < s.spline.pieceCount(); ++piece) {
        for (int k = 0; k <= 20000; ++k) {
          const Point2 p = s.spline.at(piece, k / 20000.0);
          const double dr = std::max(c.axisDistance - c.radius - p.r, p.r - c.axisDistance - c.radius);
          const double dz = std::max(c.zMin - p.z, p.z - c.zMax);
          const double d = dr <= 0 && dz <= 0 ? std::max(dr, dz) : std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
          best = std::min(best, d);
        }
      }
      EXPECT_LE(got.clearance, best + 1e-12) << s.named.name;  // never more than a point realises
      EXPECT_NEAR(got.clearance, best, 2e-4) << s.named.name;  // the sampling's spacing bounds its own error
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Embree.

TEST(SplineEmbreeTest, EveryEmbreePathAnswersLikeThePureQuery) {
  RTCDevice device = rtcNewDevice(nullptr);
  std::mt19937_64 random(53);
  for (const Built& s : closedSplines()) {
    SCOPED_TRACE(s.named.name);
    const Shape shape(s.spline);
    Geometry geometry(device, shape);
    RTCScene scene = rtcNewScene(device);
    rtcAttachGeometry(scene, geometry.handle());
    rtcCommitScene(scene);
    const std::vector<Ray> rays = testing::incoherentRays(shape, random, 256);
    embree::RayQuery query;
    for (std::size_t first = 0; first < rays.size(); first += 8) {
      RTCRayHit8 packet{};
      alignas(32) int valid[8];
      for (int i = 0; i < 8; ++i) {
        const Ray& ray = rays[first + i];
        valid[i] = -1;
        packet.ray.org_x[i] = ray.origin.x, packet.ray.org_y[i] = ray.origin.y, packet.ray.org_z[i] = ray.origin.z;
        packet.ray.dir_x[i] = ray.direction.x, packet.ray.dir_y[i] = ray.direction.y,
        packet.ray.dir_z[i] = ray.direction.z;
        packet.ray.tnear[i] = ray.tnear, packet.ray.tfar[i] = ray.tfar, packet.ray.mask[i] = ~0u;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      }
      query.intersect(valid, scene, packet);
      for (int i = 0; i < 8; ++i) {
        const Ray& ray = rays[first + i];
        const std::optional<Hit> expected = intersect(shape, ray);
        RTCRayHit one{};
        one.ray = {ray.origin.x,
                   ray.origin.y,
                   ray.origin.z,
                   ray.tnear,
                   ray.direction.x,
                   ray.direction.y,
                   ray.direction.z,
                   0.0f,
                   ray.tfar,
                   ~0u,
                   0u,
                   0u};
        one.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        query.intersect(scene, one);
        RTCRay shadow = one.ray;
        shadow.tfar = ray.tfar;
        query.occluded(scene, shadow);
        ASSERT_EQ(expected.has_value(), packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID);
        ASSERT_EQ(expected.has_value(), one.hit.geomID != RTC_INVALID_GEOMETRY_ID);
        EXPECT_EQ(expected.has_value(), shadow.tfar == -INFINITY);
        if (!expected) continue;
        for (const auto& [t, nx, nz, u, v, prim] :
             {std::tuple{packet.ray.tfar[i], packet.hit.Ng_x[i], packet.hit.Ng_z[i], packet.hit.u[i], packet.hit.v[i],
                         packet.hit.primID[i]},
              std::tuple{one.ray.tfar, one.hit.Ng_x, one.hit.Ng_z, one.hit.u, one.hit.v, one.hit.primID}}) {
          EXPECT_EQ(t, expected->t);
          EXPECT_EQ(nx, expected->normal.x);
          EXPECT_EQ(nz, expected->normal.z);
          EXPECT_EQ(u, expected->u);
          EXPECT_EQ(v, expected->v);
          EXPECT_EQ(prim, expected->segment);
        }
      }
    }
    rtcReleaseScene(scene);
  }
  rtcReleaseDevice(device);
}

}  // namespace
}  // namespace revolve
