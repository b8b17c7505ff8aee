// The places where ray/cone code goes wrong, each with its own seeded property test, run for every
// search (MIBIT with each shell kind, linear, Kajiya). Each test prints "hard case: rays, wrong"
// for README's table. Expected answers come from geometry or from the long-double oracle.
#include "support/hard_profiles.h"
#include "support/reference.h"
#include "support/test_profiles.h"
#include "support/test_scale.h"
#include "support/test_seeds.h"

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
    {"mibit/hybrid", {.method = Method::mibit, .shell = ShellKind::hybrid}},
    {"mibit/cylinder (wide, the default)", {.method = Method::mibit, .shell = ShellKind::cylinder}},
    {"mibit/cylinder/binary", {.method = Method::mibit, .shell = ShellKind::cylinder, .wideNodes = false}},
    {"mibit/cone", {.method = Method::mibit, .shell = ShellKind::cone}},
    {"linear", {.method = Method::linear}},
    {"kajiya", {.method = Method::kajiya}},
};

reference::RefRay toRef(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

double norm(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

void report(const char* hardCase, const char* variant, std::size_t rays, std::size_t wrong) {
  std::printf("hard case | %s | %s | %zu rays | %zu wrong\n", hardCase, variant, rays, wrong);
}

// ---------------------------------------------------------------------------------------------
// Apexes.

TEST(HardCasesTest, ApexMirrorNappeIsNeverHit) {
  // One segment from the apex (0, 0, 1) down to radius 0.5 at z = 0. Its cone's mirror nappe opens
  // upwards from the apex: rays that stay at z > 1 (origin above, dz >= 0) meet only the mirror
  // nappe, never the surface.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (const Variant& variant : kVariants) {
    const Shape shape(Profile(std::vector<Point2>{{0.0, 1.0}, {0.5, 0.0}}), variant.options);
    std::size_t wrong = 0, fired = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 origin{u(random), u(random), 1.0f + 0.001f + std::abs(u(random))};
      const Vec3 direction{u(random), u(random), std::abs(u(random))};
      if (norm(direction) == 0.0) continue;
      ++fired;
      wrong += intersect(shape, {origin, direction}).has_value();
    }
    report("apex: mirror nappe never hit", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u) << variant.name;
  }
}

TEST(HardCasesTest, RaysThroughAnApexHitIt) {
  // Rays through the apex exactly (o + 2 d = apex in float: d has few mantissa bits), in every
  // direction: those staying outside the cone touch it only there (a double root) and must still
  // hit at t = 2; those entering the cone hit at or before t = 2. Cones: the open cone (apex on
  // top) and both cones of the hourglass (apex at its pinch).
  std::mt19937_64 random(12);
  std::uniform_int_distribution<int> sixteenths(-32, 32);
  struct ApexCase {
    const char* name;
    std::vector<Point2> points;
    Vec3 apex;
  };
  const ApexCase cases[] = {{"open cone", {{0.0, 1.0}, {0.5, 0.0}}, {0, 0, 1}},
                            {"hourglass pinch", testing::hourglass(), {0, 0, 0}},
                            {"spindle tip", testing::spindle(200), {0, 0, 1}}};
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (const ApexCase& c : cases) {
      SCOPED_TRACE(std::string(variant.name) + ", " + c.name);
      const Shape shape(Profile(c.points), variant.options);
      for (int i = 0; i < 4000; ++i) {
        const Vec3 d{sixteenths(random) / 16.0f, sixteenths(random) / 16.0f, sixteenths(random) / 16.0f};
        if (norm(d) == 0.0) continue;
        const Vec3 origin{c.apex.x - 2 * d.x, c.apex.y - 2 * d.y, c.apex.z - 2 * d.z};
        const std::optional<Hit> hit = intersect(shape, {origin, d});
        ++fired;
        // The apex lies at t = 2; the first hit is there or before (float rounding of t allowed).
        if (!hit || hit->t > 2.0f * (1 + 4 * float(kFloatRoundoff))) {
          if (++wrong <= 3)
            ADD_FAILURE() << "d=(" << d.x << ", " << d.y << ", " << d.z << "): " << (hit ? hit->t : -1.0f);
        }
      }
    }
    report("apex: rays through the apex hit it", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(HardCasesTest, RaysAlongAGeneratorOfAConeHitWhereTheyFirstMeetIt) {
  // A ray along a generator of a cone lies on the surface from where it enters the segment's slab to
  // where it leaves: g vanishes identically and its computed coefficients are rounding noise. Its
  // first hit is the entry: the apex, coming from above, or the rim, coming from below. The apex is
  // at z = 1 and the rim at z = 0; a Pythagorean triple (a, b, c) and k = j / 64 give the generator
  // direction (a k, b k, -1) of the cone of rim radius c k, every coordinate exact in float.
  const int triples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}};
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (const auto& triple : triples) {
      for (int j = 1; j <= 24; ++j) {
        const float k = j / 64.0f;
        const Shape shape(Profile(std::vector<Point2>{{0.0, 1.0}, {triple[2] * k, 0.0}}), variant.options);
        for (int quadrant = 0; quadrant < 4; ++quadrant) {
          const float x = (quadrant & 1 ? -1.0f : 1.0f) * triple[0] * k;
          const float y = (quadrant & 2 ? -1.0f : 1.0f) * triple[1] * k;
          for (const bool fromAbove : {true, false}) {
            const Vec3 d = fromAbove ? Vec3{x, y, -1.0f} : Vec3{-x, -y, 1.0f};
            const Vec3 entry = fromAbove ? Vec3{0.0f, 0.0f, 1.0f} : Vec3{x, y, 0.0f};
            const Vec3 origin{entry.x - 2 * d.x, entry.y - 2 * d.y, entry.z - 2 * d.z};
            const std::optional<Hit> hit = intersect(shape, {origin, d});
            ++fired;
            if (!hit || hit->t > 2.0f * (1 + 4 * float(kFloatRoundoff))) {
              if (++wrong <= 3) {
                ADD_FAILURE() << variant.name << ", rim " << triple[2] * k << ", d=(" << d.x << ", " << d.y << ", "
                              << d.z << "): " << (hit ? hit->t : -1.0f) << ", expected 2";
              }
            }
          }
        }
      }
    }
    report("rays along a generator of a cone", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(HardCasesTest, NearlyHorizontalRaysGrazingAnApexStayOnTheSurface) {
  // A solid cone with its apex at the top (0, 0, 0); rays nearly parallel to the apex plane
  // (|dz| ~ 1e-13..1e-9) passing within ~2e-15 of the apex. A touch must be placed where the ray
  // is nearest the apex, not where it crosses the apex's plane (up to 1e-12 / dz away along the
  // ray): every reported hit lies on the surface.
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0), exponent(-13.0, -9.0);
  for (const Variant& variant : kVariants) {
    const std::vector<Point2> points{{0.0, -1.0}, {1.0, -1.0}, {0.0, 0.0}};
    const Shape shape(Profile(points), variant.options);
    std::size_t fired = 0, wrong = 0;
    for (int i = 0; i < 20000; ++i) {
      const float dz = float(std::pow(10.0, exponent(random)) * (u(random) < 0 ? -1 : 1));
      // Within the touch tolerance (a few u of the origin's distance, ~2e-15), so touches happen.
      const float height = float(2e-15 * u(random));
      const float sideways = float(2e-15 * u(random));
      const Ray ray{{-3.0f, sideways, height - 3.0f * dz}, {1.0f, 0.0f, dz}};
      ++fired;
      const std::optional<Hit> hit = intersect(shape, ray);
      if (!hit) continue;
      const double x = ray.origin.x + double(hit->t) * ray.direction.x,
                   y = ray.origin.y + double(hit->t) * ray.direction.y,
                   z = ray.origin.z + double(hit->t) * ray.direction.z;
      const double residual = double(reference::meridianDistance(points, x, y, z));
      if (residual > 8 * kFloatRoundoff * 3.0 && ++wrong <= 3) {
        ADD_FAILURE() << "dz " << dz << ": hit at t " << hit->t << " lies " << residual << " off the surface";
      }
    }
    report("apex: nearly horizontal rays grazing it stay on the surface", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Rays along, through and perpendicular to the axis; horizontal and vertical runs.

// Disagreements with the oracle. One is excused only where the exact answer is ambiguous at the
// rounding level: the oracle's own verdict changes under a 1e-9 nudge of the ray (a ray in a
// vertex's plane is nudged within it: there the half-open rule decides, and is compared). The
// excused are counted by where they lie, near an apex or elsewhere, for the callers to bound.
struct Disagreements {
  std::size_t wrong = 0, excusedNearApex = 0, excusedElsewhere = 0;
};

Disagreements disagreements(std::span<const Point2> points, const Shape& shape, const std::vector<Ray>& rays,
                            double size) {
  Disagreements found;
  for (const Ray& ray : rays) {
    const std::optional<Hit> got = intersect(shape, ray);
    const auto expected = reference::intersectProfile(points, toRef(ray));
    const double dn = norm(ray.direction);
    if (got.has_value() == expected.has_value() &&
        (!got || std::abs(got->t - double(expected->t)) * dn <= 0x1p-22 * (std::abs(got->t) * dn + size))) {
      continue;
    }
    if (!reference::verdictIsFragile(points, toRef(ray), 1e-9L * size, size)) {
      if (++found.wrong <= 3) {
        ADD_FAILURE() << "o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                      << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << "): oracle "
                      << (expected ? std::to_string(double(expected->t)) : "miss") << ", library "
                      << (got ? std::to_string(got->t) : "miss");
      }
    } else if (reference::passesNearAnApex(points, toRef(ray), 1e-9L * size)) {
      ++found.excusedNearApex;
    } else {
      ++found.excusedElsewhere;
    }
  }
  return found;
}

TEST(HardCasesTest, AxisAlignedRaysAgreeWithTheOracle) {
  const std::vector<std::pair<const char*, std::vector<Point2>>> profiles = {
      {"stairs", testing::stairs(10)},          {"cup", testing::cup()},
      {"hourglass", testing::hourglass()},      {"capped cylinder", testing::cappedCylinder(0.5, -0.75, 0.75)},
      {"sphere", testing::sphereLike(1.0, 64)}, {"hollow vase", testing::hollowVase()}};
  for (const std::uint64_t seed : testing::testSeeds({13})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    for (const Variant& variant : kVariants) {
      std::size_t fired = 0, wrong = 0;
      for (const auto& [name, points] : profiles) {
        SCOPED_TRACE(std::string(variant.name) + ", " + name);
        const Shape shape(Profile(points), variant.options);
        const std::vector<Ray> rays = testing::axisAlignedRays(shape, random, 8000);
        fired += rays.size();
        const Disagreements found = disagreements(points, shape, rays, norm(shape.bounds().upper));
        wrong += found.wrong;
        // Half of these rays lie in a vertex's plane or aim at a vertex's height on the axis, by
        // design; the excuses stay few. Elsewhere than at an apex (within 1e-9 of a silhouette
        // or rim) an axis-aligned ray lands by coincidence only: at most one a profile. At an
        // apex: the rays through the axis aimed at an apex's height pass it within the rounding
        // of their direction, often exactly, where the touch flips under a nudge (and the kernel
        // misses some exact touches at shallow slopes, see ReferenceAgreementTest). Measured: at
        // most 3 for a search and profile (the sphere's), over 37 seeds.
        EXPECT_LE(found.excusedElsewhere, 1u);
        EXPECT_LE(found.excusedNearApex, 6u);
        if (found.excusedNearApex + found.excusedElsewhere > 0) {
          std::printf("%s, %s: %zu disagreements excused near an apex, %zu elsewhere\n", variant.name, name,
                      found.excusedNearApex, found.excusedElsewhere);
        }
      }
      report("rays along, through and perpendicular to the axis", variant.name, fired, wrong);
      EXPECT_EQ(wrong, 0u);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Grazing and tangent rays.

TEST(HardCasesTest, TangentRaysGiveNoNaNAndNoHitOffTheSurface) {
  // Rays in the tangent plane of a random surface point: the silhouette may go either way, but a
  // reported hit must lie on the surface (meridian residual within rounding) and nothing may be NaN.
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (const testing::ClosedProfile& closed : testing::closedProfiles()) {
      if (closed.points.size() > 1000 && variant.options.method == Method::linear) continue;
      const Shape shape(Profile(closed.points), variant.options);
      const double size = norm(shape.bounds().upper);
      // The oracle's meridian distance is O(points) a call: fewer rays on the 20,001-point profile.
      const int count = closed.points.size() > 1000 ? 300 : 3000;
      for (int i = 0; i < count; ++i) {
        const std::size_t k = random() % (closed.points.size() - 1);
        const Point2 a = closed.points[k], b = closed.points[k + 1];
        const double s = unit(random), phi = 2 * std::numbers::pi * unit(random);
        const double r = a.r + s * (b.r - a.r), z = a.z + s * (b.z - a.z);
        const double len = std::hypot(b.r - a.r, b.z - a.z);
        const double nr = (b.z - a.z) / len, nz = -(b.r - a.r) / len;
        // Tangent directions: the azimuthal one and the one along the meridian, mixed.
        const double w = 2 * unit(random) - 1;
        const double tr = w * -nz, tz = w * nr, tphi = std::sqrt(std::max(0.0, 1 - w * w));
        const Vec3 d{float(tr * std::cos(phi) - tphi * std::sin(phi)), float(tr * std::sin(phi) + tphi * std::cos(phi)),
                     float(tz)};
        const Vec3 p{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)};
        const Ray ray{{p.x - d.x * float(size), p.y - d.y * float(size), p.z - d.z * float(size)}, d};
        ++fired;
        const std::optional<Hit> hit = intersect(shape, ray);
        if (!hit) continue;
        const bool finite = std::isfinite(hit->t) && std::isfinite(hit->normal.x) && std::isfinite(hit->normal.y) &&
                            std::isfinite(hit->normal.z) && std::isfinite(hit->u) && std::isfinite(hit->v);
        // The reported point, rounded from the double solution, lies within float rounding of the
        // surface: a few ulps of its own magnitude (tangent roots keep half of double's digits,
        // still below a float ulp).
        const double residual =
            double(reference::meridianDistance(closed.points, hit->point.x, hit->point.y, hit->point.z));
        if (!finite || residual > 4 * kFloatRoundoff * (norm(hit->point) + size)) {
          if (++wrong <= 3) ADD_FAILURE() << closed.name << ": residual " << residual << (finite ? "" : " (NaN)");
        }
      }
    }
    report("grazing and tangent rays: NaN or hit off the surface", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Far origins, large and small objects, objects far from the origin.

// A profile scaled by `scale` and lifted by `lift` along z.
std::vector<Point2> transformed(std::span<const Point2> points, double scale, double lift) {
  std::vector<Point2> out;
  for (const Point2& p : points) out.push_back({p.r * scale, p.z * scale + lift});
  return out;
}

TEST(HardCasesTest, FarOriginsAndExtremeScalesKeepTheInputsPrecision) {
  // Rays from `distance` object sizes away, for objects of size 1e-3 to 1e3, some 1e3 sizes away
  // from the world origin. The float ray's own resolution there is 2^-24 of its coordinates; the
  // hit distance must agree with the oracle's (on the same float ray) to that, and its point must
  // lie that close to the surface.
  std::mt19937_64 random(15);
  std::normal_distribution<double> gauss;
  struct Setting {
    double scale, lift, distance;
  };
  const Setting settings[] = {{1, 0, 1e4},     {1e-3, 0, 1e4}, {1e3, 0, 1e4},
                              {1e-3, 1.0, 10}, {1e3, 1e6, 10}, {1, 1e3, 1e2}};
  const std::vector<Point2> base = testing::hollowVase();
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (const Setting& setting : settings) {
      SCOPED_TRACE(std::string(variant.name) + ", scale " + std::to_string(setting.scale) + ", lift " +
                   std::to_string(setting.lift) + ", distance " + std::to_string(setting.distance));
      const std::vector<Point2> points = transformed(base, setting.scale, setting.lift);
      const Shape shape(Profile(points), variant.options);
      const Bounds box = shape.bounds();
      const double size = norm({box.upper.x, box.upper.y, 0.5f * (box.upper.z - box.lower.z)});
      const double cz = 0.5 * (double(box.lower.z) + box.upper.z);
      std::uniform_real_distribution<double> inBox(0.0, 1.0);
      for (int i = 0; i < 4000; ++i) {
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
        const auto expected = reference::intersectProfile(points, toRef(ray));
        const double dn = norm(ray.direction);
        const double resolution = kFloatRoundoff * (norm(origin) + size);  // the inputs' own
        bool ok = got.has_value() == expected.has_value();
        if (ok && got) {
          // t is a float: half an ulp of t d, plus the input resolution over the incidence.
          const double cosine = std::abs(double(expected->nx * ray.direction.x + expected->ny * ray.direction.y +
                                                expected->nz * ray.direction.z)) /
                                dn;
          ok = std::abs(got->t - double(expected->t)) * dn <=
               2 * kFloatRoundoff * got->t * dn + 4 * resolution / std::max(cosine, 1e-3);
          const double residual = double(reference::meridianDistance(points, got->point.x, got->point.y, got->point.z));
          ok = ok && residual <= 4 * kFloatRoundoff * (norm(got->point) + size);
        }
        if (!ok) {
          // Within the inputs' resolution of an edge or silhouette either verdict is right.
          bool fragile = false;
          for (int axis = 0; axis < 3 && !fragile; ++axis) {
            for (double sign : {-1.0, 1.0}) {
              reference::RefRay moved = toRef(ray);
              (axis == 0 ? moved.ox : axis == 1 ? moved.oy : moved.oz) += sign * resolution;
              fragile |= reference::intersectProfile(points, moved).has_value() != expected.has_value();
            }
          }
          if (!fragile && ++wrong <= 3) {
            ADD_FAILURE() << "oracle " << (expected ? double(expected->t) : -1.0) << ", library "
                          << (got ? got->t : -1.0f);
          }
        }
      }
    }
    report("far origins (1e4 sizes), sizes 1e-3..1e3, objects far from the origin", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Accuracy of every hit, and normals.

TEST(HardCasesTest, EveryHitLiesOnTheSurfaceWithAUnitConsistentNormal) {
  // For every hit of incoherent rays on every closed profile: the point (computed in double,
  // rounded to float) within a few float ulps of the surface; o + t d (what an Embree user has)
  // within the rounding of that expression; the normal of unit length; and a ray from the other
  // side through the same point gets the same normal (normals do not face the ray).
  std::mt19937_64 random(16);
  for (const Variant& variant : kVariants) {
    std::size_t fired = 0, wrong = 0;
    for (const testing::ClosedProfile& closed : testing::closedProfiles()) {
      if (closed.points.size() > 1000 && variant.options.method == Method::linear) continue;
      SCOPED_TRACE(std::string(variant.name) + ", " + closed.name);
      const Shape shape(Profile(closed.points), variant.options);
      const double size = norm(shape.bounds().upper);
      // The oracle's meridian distance is O(points) a call: fewer rays on the 20,001-point profile.
      for (const Ray& ray :
           testing::incoherentRays(shape, random, testing::scaledRays(closed.points.size() > 1000 ? 300 : 4000))) {
        const std::optional<Hit> hit = intersect(shape, ray);
        if (!hit) continue;
        ++fired;
        const double pointResidual =
            double(reference::meridianDistance(closed.points, hit->point.x, hit->point.y, hit->point.z));
        const double x = ray.origin.x + double(hit->t) * ray.direction.x,
                     y = ray.origin.y + double(hit->t) * ray.direction.y,
                     z = ray.origin.z + double(hit->t) * ray.direction.z;
        const double rayResidual = double(reference::meridianDistance(closed.points, x, y, z));
        const double unit = norm(hit->normal);
        // Reverse ray through the hit point: same point, approached from the other side.
        const Vec3 through{2 * hit->point.x - ray.origin.x, 2 * hit->point.y - ray.origin.y,
                           2 * hit->point.z - ray.origin.z};
        const Ray back{through, {-ray.direction.x, -ray.direction.y, -ray.direction.z}};
        const std::optional<Hit> other = intersect(shape, back);
        // Where the reverse ray meets the same point of the same segment, the normal is the same.
        bool sameNormal = true;
        if (other && other->segment == hit->segment &&
            norm({other->point.x - hit->point.x, other->point.y - hit->point.y, other->point.z - hit->point.z}) <
                1e-5 * size) {
          sameNormal = norm({other->normal.x - hit->normal.x, other->normal.y - hit->normal.y,
                             other->normal.z - hit->normal.z}) < 1e-5;
        }
        const bool ok = pointResidual <= 4 * kFloatRoundoff * (norm(hit->point) + size) &&
                        rayResidual <= 4 * kFloatRoundoff * (norm(ray.origin) + hit->t * norm(ray.direction) + size) &&
                        std::abs(unit - 1.0) <= 4 * kFloatRoundoff && sameNormal;
        if (!ok && ++wrong <= 3) {
          ADD_FAILURE() << "residuals " << pointResidual << " / " << rayResidual << ", |n| = " << unit;
        }
      }
    }
    report("every hit: on the surface, unit normal, same normal from both sides", variant.name, fired, wrong);
    EXPECT_EQ(wrong, 0u);
  }
}

// Hits so close to the axis that x^2 + y^2, or x and y themselves, are subnormal (found by fuzzing:
// (x, y) / sqrt(x^2 + y^2) was then not unit). Rays leave the axis at height 0, which re-centring
// (about the shape's middle height and the ray's closest approach) keeps exactly 0, from inside:
// - a needle, the cone r = 2e-160 (z + 1), -1 <= z <= 1: hits near 2e-160 from the axis, whose
//   squares are subnormal;
// - a double cone whose apex is at z = 4.9e-322 (r = |z - 4.9e-322|): hits of subnormal x and y.
// Both are far thinner than the rays' rounding (about 1e-17 of the object), so a miss is within
// rounding, and so is the azimuth of a hit (the radius of curvature is that small), and t is
// ill-conditioned for rays along the double cone's generators. What is not: a hit must lie on the
// surface (within a few float ulps of the object's size, as every hit), with a unit normal whose
// z part is the segment's, -er / length.
TEST(HardCasesTest, HitsWithinSubnormalDistancesOfTheAxisHaveUnitNormals) {
  struct Case {
    const char* name;
    std::vector<Point2> points;
  };
  constexpr double kApexZ = 4.9e-322;
  const Case cases[] = {
      {"a needle 2e-160 thick", {{0, -1}, {2e-160, 0}, {4e-160, 1}}},
      {"an apex 4.9e-322 above the origin", {{1, -1}, {0, kApexZ}, {1, 1}}},
  };
  std::mt19937_64 random(17);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (const Case& c : cases) {
    const Profile profile(c.points);
    for (const Variant& variant : kVariants) {
      const Shape shape(profile, variant.options);
      std::size_t fired = 0, hits = 0, wrong = 0;
      for (int i = 0; i < 20000; ++i) {
        const Ray ray{{0, 0, 0}, {unit(random), unit(random), unit(random)}};
        ++fired;
        const std::optional<Hit> hit = intersect(shape, ray);
        if (!hit) continue;
        ++hits;
        const Point2 p0 = c.points[hit->segment], p1 = c.points[hit->segment + 1];
        const double nz = -(p1.r - p0.r) / std::hypot(p1.r - p0.r, p1.z - p0.z);
        const double residual = double(reference::meridianDistance(c.points, hit->point.x, hit->point.y, hit->point.z));
        const bool ok = residual <= 4 * kFloatRoundoff * norm(shape.bounds().upper) &&
                        std::abs(norm(hit->normal) - 1.0) <= 4 * kFloatRoundoff &&
                        std::abs(hit->normal.z - nz) <= kFloatRoundoff;
        if (!ok && ++wrong <= 3) {
          ADD_FAILURE() << c.name << ", " << variant.name << ": d = (" << ray.direction.x << ", " << ray.direction.y
                        << ", " << ray.direction.z << "): t " << hit->t << ", residual " << residual << ", n ("
                        << hit->normal.x << ", " << hit->normal.y << ", " << hit->normal.z << ")";
        }
      }
      const std::string hardCase = std::string("hits within subnormal distances of the axis: ") + c.name;
      report(hardCase.c_str(), variant.name, fired, wrong);
      std::printf("  (%zu of them hit; the rest miss within rounding)\n", hits);
      EXPECT_GT(hits, fired / 10) << "too few hits for the check to mean anything";
      EXPECT_EQ(wrong, 0u);
    }
  }
}

}  // namespace
}  // namespace revolve
