// segmentHits (src/kernel/segment_hits.h), Wang's ray/truncated-cone intersection, for one segment at
// a time: against the closed-form solution, in long double, of the same double-precision line
// against the cone r = r0 + (z - z0)(r1 - r0)/(z1 - z0) within the segment's slab (and the annulus
// of a horizontal segment), and against the contracts the header states: hits within [tnear, tfar]
// inclusive, the half-open height rule of rays in a horizontal plane, the apex touch, rays along a
// generator.
//
// The reference solves the line the kernel sees (MeridianRay's origin and direction, exact in long
// double), so the comparison measures the kernel's own rounding, not the float ray's.
//
// Tolerance. Along the line, F(s) = rho(s)^2 - radius(z(s))^2 is a quadratic; the kernel solves
// g = ez^2 F expanded about a point m of its bracket. Its coefficients carry the rounding the header
// counts (alongSurface: at most 10 u of their terms' magnitudes), which over a bracket inside the
// bounding sphere (|x| = |s - m| <= 2R, |dz x| <= |ez| since both points lie in the slab, every
// point within R of the centre, radius(z) <= R in the slab) bound g's error by
//   C: 40 u R^2 ez^2 (rho^2, meridian_ray.h) + 16 u R^2 |ez| len (2 |L| dL, dL <= 8 u R len) + 9 u R^2 ez^2
//   2 B x: 32 u R^2 ez^2 + 44 u R^2 |ez| len + 8 u R^2 |ez| len;  A x^2: 44 u R^2 |ez| len
//   the discriminant's rounding near a tangency, 3 u (B^2 / |A| + |C|) ~ 6 u |C| <= 60 u R^2 ez^2
//     (|C| <= ez^2 R^2 + Lm^2, |Lm| <= |ez| (R + len) <= 3 |ez| R)
// in all at most 253 u R^2 |ez| len; so E = 256 u R^2 len / |ez| bounds the error in F. A computed
// root is then where the exact F is within E of 0: in the component of {s : |F(s)| <= E} around
// the exact root (widened by the root formula's own rounding, a few u |s - m| <= 16 u R). The
// long-double reference rounds 2^-11 u relative: 2^15 times below E. Where such a component
// reaches an end of the segment's stretch (a slab plane, crossed with rounding 8 u R / |dz|, or
// tnear / tfar), holds other than one root (a tangency) or passes an apex within the touch's
// tolerance (addApexTouch), the exact answer is within rounding of another and either is right:
// the count there is not checked, only that every hit lies in some component.
#include "kernel/segment_hits.h"
#include "kernel/meridian_ray.h"
#include "support/test_scale.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace revolve {
namespace {

using Real = long double;
using detail::kUnitRoundoff;
using detail::MeridianRay;

constexpr double u = kUnitRoundoff;

// A segment in the shape's local frame (zCentre = 0), with the bounding sphere Shape gives it: its
// farthest vertex from the centre, padded by 2^-20 (shape.cpp).
detail::ShapeFrame frameHolding(Point2 p0, Point2 p1) {
  return detail::makeShapeFrame(0.0, std::max(std::hypot(p0.r, p0.z), std::hypot(p1.r, p1.z)) * (1.0 + 0x1p-20));
}

MeridianRay meridian(const detail::ShapeFrame& frame, const Ray& ray) {
  MeridianRay m{};
  EXPECT_TRUE(detail::setUpMeridianRay(frame, ray, m));
  return m;
}

std::string describe(const Ray& ray) {
  std::ostringstream out;
  out.precision(9);
  out << "ray o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=(" << ray.direction.x << ", "
      << ray.direction.y << ", " << ray.direction.z << ") [" << ray.tnear << ", " << ray.tfar << "]";
  return out.str();
}

// Real roots of A x^2 + 2 B x + C, increasing (the textbook stable pair, in long double).
std::vector<Real> realRoots(Real A, Real B, Real C) {
  if (A == 0) return B == 0 ? std::vector<Real>{} : std::vector<Real>{-C / (2 * B)};
  const Real D = B * B - A * C;
  if (D < 0) return {};
  const Real q = -(B + std::copysign(std::sqrt(D), B));
  std::vector<Real> roots{q / A, q != 0 ? C / q : q / A};
  std::sort(roots.begin(), roots.end());
  return roots;
}

// F(s) = rho(s)^2 - radius(z(s))^2 for the line of `ray` and the cone through p0, p1 (ez != 0),
// expanded about s = c: F(c + x) = A x^2 + 2 B x + C. For a line in a horizontal plane (dz = 0)
// the radius is the cone's at that height, a constant.
struct Expansion {
  Real c, A, B, C;
  Real at(Real s) const {
    const Real x = s - c;
    return (A * x + 2 * B) * x + C;
  }
};

Expansion coneFunction(const MeridianRay& ray, Point2 p0, Point2 p1, Real c) {
  const Real k = (Real(p1.r) - p0.r) / (Real(p1.z) - p0.z);  // dr/dz of the cone
  const Real px = ray.ox + c * Real(ray.dx), py = ray.oy + c * Real(ray.dy), z = ray.oz + c * Real(ray.dz);
  const Real radius = p0.r + (z - p0.z) * k;
  const Real dx = ray.dx, dy = ray.dy, dz = ray.dz;
  return {c, dx * dx + dy * dy - k * k * dz * dz, px * dx + py * dy - k * dz * radius,
          px * px + py * py - radius * radius};
}

struct Interval {
  Real lo, hi;
  bool meets(Interval other) const { return lo <= other.hi && other.lo <= hi; }
  bool holds(Real s) const { return lo <= s && s <= hi; }
};

// The components of {s in [from, to] : |F(s)| <= e}: F is quadratic, so they are cut by the roots of
// F - e and F + e.
std::vector<Interval> bandComponents(const Expansion& f, Real e, Real from, Real to) {
  std::vector<Real> cuts{from, to};
  for (const Real level : {-e, e}) {
    for (const Real x : realRoots(f.A, f.B, f.C - level)) {
      if (from < f.c + x && f.c + x < to) cuts.push_back(f.c + x);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<Interval> components;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (!(std::abs(f.at(0.5L * (cuts[i] + cuts[i + 1]))) <= e)) continue;
    if (!components.empty() && components.back().hi == cuts[i]) {
      components.back().hi = cuts[i + 1];
    } else {
      components.push_back({cuts[i], cuts[i + 1]});
    }
  }
  return components;
}

// What the exact line and the kernel's error bound say about one non-horizontal segment: the
// components of {s : |F(s)| <= E} (widened by the root formula's rounding), each with the number of
// exact hits it holds, and whether that number is within rounding of another (fragile).
struct Component {
  Interval span;
  int exact;
  bool fragile;
};

// E: the bound on F's error; by default the file comment's, which holds wherever the kernel expands.
std::vector<Component> analyse(const MeridianRay& ray, Point2 p0, Point2 p1, double R, Real E = 0) {
  const double ez = p1.z - p0.z, len = std::hypot(p1.r - p0.r, ez);
  if (E == 0) E = 256 * u * R * R * len / std::abs(ez);
  const Real rootRounding = 16 * u * R;
  const Real lo = ray.lo, hi = ray.hi;
  // The segment's stretch of the line (exact), and how far the kernel's may differ at each end:
  // a slab plane's crossing rounds by 8 u R / |dz|, and an apex touch may lie beyond it by the
  // touch's tolerance (lineSlack + 4 u (|ax| + |ay| + |az|) + 8 u |az| <= lineSlack + 30 u R) over |dz|.
  Interval stretch{lo, hi};
  Real planeSlack = 0;
  bool owned = true;
  if (!ray.inPlane) {
    const Real s0 = (Real(p0.z) - ray.oz) / Real(ray.dz), s1 = (Real(p1.z) - ray.oz) / Real(ray.dz);
    stretch = {std::max(std::min(s0, s1), lo), std::min(std::max(s0, s1), hi)};
    planeSlack = (ray.lineSlack + 48 * u * R) / std::abs(ray.dz);
  } else {
    owned = std::min(p0.z, p1.z) <= ray.oz && ray.oz < std::max(p0.z, p1.z);  // the half-open height rule
  }
  const bool stretchEmpty = !owned || stretch.lo > stretch.hi;
  // Where verdicts are within rounding: around each end of the stretch (where the kernel's end
  // verdicts are taken), and where the line passes an apex within the touch's tolerance (there the
  // kernel may report a touch whatever the brackets say, in a horizontal plane too).
  std::vector<Interval> zones;
  if (!stretchEmpty) {
    const Real slackLo = ray.inPlane || stretch.lo == lo ? rootRounding : planeSlack;
    const Real slackHi = ray.inPlane || stretch.hi == hi ? rootRounding : planeSlack;
    zones = {{stretch.lo - slackLo, stretch.lo + slackLo}, {stretch.hi - slackHi, stretch.hi + slackHi}};
  } else if (owned && !ray.inPlane && stretch.lo - stretch.hi <= 2 * planeSlack) {
    zones = {{stretch.hi - planeSlack, stretch.lo + planeSlack}};  // empty within rounding of non-empty
  }
  for (const Point2 apex : {p0, p1}) {
    if (apex.r != 0.0) continue;
    const Real ax = -Real(ray.ox), ay = -Real(ray.oy), az = apex.z - Real(ray.oz);
    const Real s = ax * ray.dx + ay * ray.dy + az * ray.dz;  // closest approach (|d| = 1 within 2^-52)
    if (std::hypot(ax - s * ray.dx, ay - s * ray.dy, az - s * ray.dz) <= ray.lineSlack + 32 * u * R) {
      zones.push_back({s, s});
    }
  }

  const Real c = stretchEmpty ? 0.5L * (lo + hi) : 0.5L * (stretch.lo + stretch.hi);
  const Expansion F = coneFunction(ray, p0, p1, c);
  std::vector<Real> roots;
  for (const Real x : realRoots(F.A, F.B, F.C)) roots.push_back(c + x);
  std::vector<Component> components;
  for (const Interval band : bandComponents(F, E, lo - R, hi + R)) {
    const Interval span{band.lo - rootRounding, band.hi + rootRounding};
    int inside = 0, exact = 0;
    for (const Real root : roots) {
      if (!span.holds(root)) continue;
      ++inside;
      if (!stretchEmpty && stretch.lo <= root && root <= stretch.hi) ++exact;
    }
    bool fragile = !stretchEmpty && inside != 1 && span.meets({stretch.lo - planeSlack, stretch.hi + planeSlack});
    for (const Interval& zone : zones) fragile = fragile || zone.meets(span);
    components.push_back({span, exact, fragile});
  }
  return components;
}

struct Tally {
  std::size_t rays = 0, robustHits = 0, robustMisses = 0, fragile = 0;
};

// Checks the kernel's hits for one ray against a non-horizontal segment; see the file comment.
void checkCone(const MeridianRay& ray, Point2 p0, Point2 p1, double R, const std::string& what, Tally& tally) {
  const detail::SegmentHits hits = detail::segmentHits(ray, p0, p1, ray.lo, ray.hi);
  const detail::SegmentHits first = detail::segmentHits<true>(ray, p0, p1, ray.lo, ray.hi);
  ++tally.rays;
  ASSERT_LE(hits.count, 2) << what;
  // kFirstOnly skips only the second root's work: the same first hit, bit for bit.
  ASSERT_EQ(first.count, std::min(hits.count, 1)) << what;
  if (first.count == 1) {
    ASSERT_EQ(first.s[0], hits.s[0]) << what;
  }
  for (int i = 0; i < hits.count; ++i) ASSERT_TRUE(ray.lo <= hits.s[i] && hits.s[i] <= ray.hi) << what << ": hit " << i;
  if (hits.count == 2) {
    ASSERT_LE(hits.s[0], hits.s[1]) << what;
  }

  std::vector<int> claimed(hits.count, 0);
  bool fragile = false;
  for (const Component& component : analyse(ray, p0, p1, R)) {
    int got = 0;
    for (int i = 0; i < hits.count; ++i) {
      if (component.span.holds(hits.s[i])) ++got, ++claimed[i];
    }
    if (component.fragile) {
      fragile = true;
      continue;
    }
    EXPECT_EQ(got, component.exact) << what << ": component [" << double(component.span.lo) << ", "
                                    << double(component.span.hi) << "] holds " << component.exact << " exact hits";
    (component.exact > 0 ? tally.robustHits : tally.robustMisses) += 1;
  }
  tally.fragile += fragile;
  for (int i = 0; i < hits.count; ++i) {
    EXPECT_GE(claimed[i], 1) << what << ": hit at s=" << hits.s[i] << " lies where |F| exceeds its error bound";
  }
}

// A horizontal segment: the annulus between its vertex circles in its plane, half-open as the
// kernel's XOR of the two vertex predicates rho^2 < r^2 makes it: min r <= rho < max r.
void checkAnnulus(const MeridianRay& ray, Point2 p0, Point2 p1, double R, const std::string& what, Tally& tally) {
  const detail::SegmentHits hits = detail::segmentHits(ray, p0, p1, ray.lo, ray.hi);
  ++tally.rays;
  if (ray.inPlane) {  // a ray in the annulus' plane meets it nowhere (or everywhere): no hit
    EXPECT_EQ(hits.count, 0) << what;
    return;
  }
  const Real s = (Real(p0.z) - ray.oz) / Real(ray.dz);
  const Real px = ray.ox + s * Real(ray.dx), py = ray.oy + s * Real(ray.dy), rho2 = px * px + py * py;
  const Real rMin = std::min(p0.r, p1.r), rMax = std::max(p0.r, p1.r);
  const bool expected = Real(ray.lo) <= s && s <= Real(ray.hi) && rMin * rMin <= rho2 && rho2 < rMax * rMax;
  // The kernel's crossing rounds by 8 u R / |dz| along the line, which moves rho^2 by 2 R that much;
  // rho^2 itself rounds by 40 u R^2 (meridian_ray.h).
  const Real sSlack = 8 * u * R / std::abs(ray.dz), rho2Slack = 2 * R * sSlack + 40 * u * R * R;
  const bool fragile = std::abs(rho2 - rMin * rMin) <= rho2Slack || std::abs(rho2 - rMax * rMax) <= rho2Slack ||
                       std::abs(s - ray.lo) <= sSlack || std::abs(s - ray.hi) <= sSlack;
  if (fragile) {
    ++tally.fragile;
    EXPECT_LE(hits.count, 1) << what;
  } else {
    ASSERT_EQ(hits.count, expected ? 1 : 0) << what << ": rho^2 " << double(rho2) << " at the plane";
    (expected ? tally.robustHits : tally.robustMisses) += 1;
  }
  if (hits.count == 1) {
    EXPECT_LE(std::abs(hits.s[0] - s), sSlack) << what;
  }
}

// Rays from 3 R away aimed at a random point near the segment's surface (within a tenth of its
// length), of several kinds.
enum class RayKind { oblique, shallow, inPlane, vertexPlane, clipped };

Ray randomRay(std::mt19937_64& random, Point2 p0, Point2 p1, double R, RayKind kind) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double along = unit(random), phi = 2.0 * std::numbers::pi * unit(random);
  const double near = 0.1 * std::hypot(p1.r - p0.r, p1.z - p0.z);
  const double r = std::max(0.0, p0.r + along * (p1.r - p0.r) + near * (unit(random) - 0.5));
  const double z = p0.z + along * (p1.z - p0.z) + near * (unit(random) - 0.5);
  const Vec3 target{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)};
  // An origin 3 R away, on a uniform direction.
  const double cz = 2.0 * unit(random) - 1.0, psi = 2.0 * std::numbers::pi * unit(random),
               sz = std::sqrt(1.0 - cz * cz);
  Vec3 origin{float(3.0 * R * sz * std::cos(psi)), float(3.0 * R * sz * std::sin(psi)), float(3.0 * R * cz)};
  switch (kind) {
    case RayKind::shallow:  // rising or falling by 10^-1 to 10^-4 of its run
      origin = {float(3.0 * R * std::cos(psi)), float(3.0 * R * std::sin(psi)),
                float(z + 3.0 * R * std::pow(10.0, -1.0 - 3.0 * unit(random)) * (unit(random) < 0.5 ? -1.0 : 1.0))};
      break;
    case RayKind::inPlane:
    case RayKind::vertexPlane: {
      // dz = 0 exactly, at a random height or at a vertex's (both vertices' heights are floats).
      const float height = kind == RayKind::inPlane ? target.z : float(unit(random) < 0.5 ? p0.z : p1.z);
      origin = {float(3.0 * R * std::cos(psi)), float(3.0 * R * std::sin(psi)), height};
      return {origin, {target.x - origin.x, target.y - origin.y, 0.0f}};
    }
    default:
      break;
  }
  Ray ray{origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}};
  if (kind == RayKind::clipped) {  // a range ending near the target, where hits are
    ray.tnear = float(unit(random) * 0.9);
    ray.tfar = float(ray.tnear + unit(random) * 0.3);
  }
  return ray;
}

struct NamedSegment {
  const char* name;
  Point2 p0, p1;
  double sphereRadius = 0.0;  // of the profile it belongs to; 0: the segment's own
};

detail::ShapeFrame frameOf(const NamedSegment& segment) {
  return segment.sphereRadius == 0.0 ? frameHolding(segment.p0, segment.p1)
                                     : detail::makeShapeFrame(0.0, segment.sphereRadius);
}

// Every kind of segment: oblique both ways, vertical (a cylinder), horizontal (annuli and a disc),
// an apex at either end, nearly flat (to 1e-7) and nearly vertical, a wide cone close to the axis;
// and small segments of a larger profile (1/2,000 of its bounding sphere), far from its centre,
// where the kernel's expansion about its own stretch keeps the coefficients of the segment's size.
const NamedSegment kSegments[] = {
    {"oblique, rising", {0.5, -0.5}, {1.0, 0.75}},
    {"oblique, falling", {1.0, 0.75}, {0.5, -0.5}},
    {"narrowing upwards", {1.0, -0.5}, {0.25, 0.5}},
    {"vertical", {0.75, -1.0}, {0.75, 1.0}},
    {"vertical, downwards", {0.75, 1.0}, {0.75, -1.0}},
    {"apex below", {0.0, -0.75}, {1.0, 0.5}},
    {"apex above", {1.0, -0.5}, {0.0, 0.75}},
    {"apex below, steep", {0.0, -1.0}, {0.125, 1.0}},
    {"nearly flat, rising", {0.25, 0.125}, {1.0, 0.125 + 1e-7}},
    {"nearly flat, falling", {1.0, -0.125}, {0.25, -0.125 - 1e-7}},
    {"nearly flat, apex", {0.0, 0.25}, {1.0, 0.25 + 1e-7}},
    {"nearly vertical", {0.5, -1.0}, {0.5 + 1e-7, 1.0}},
    {"wide cone near the axis", {0.001, 0.0}, {1.0, 0.0625}},
    {"annulus, outwards", {0.25, 0.5}, {1.0, 0.5}},
    {"annulus, inwards", {1.0, -0.5}, {0.375, -0.5}},
    {"disc", {0.0, 0.25}, {1.0, 0.25}},
    {"small, oblique, far from the centre", {0.75, -0.5}, {0.7505, -0.4996}, 1.0},
    {"small, vertical, far from the centre", {0.75, -0.5}, {0.75, -0.4995}, 1.0},
    {"small, nearly flat, far from the centre", {0.75, 0.5}, {0.7505, 0.5 + 1e-9}, 1.0},
    {"small, nearly flat, falling", {0.7505, 0.5}, {0.75, 0.5 - 1e-9}, 1.0},
};

TEST(SegmentHits, AgreeWithTheClosedFormOfTheConeWithinTheKernelsErrorBound) {
  const RayKind kinds[] = {RayKind::oblique, RayKind::oblique,     RayKind::oblique, RayKind::shallow,
                           RayKind::inPlane, RayKind::vertexPlane, RayKind::clipped, RayKind::clipped};
  const std::size_t raysPerSegment = testing::scaledRays(8000);
  for (const std::uint64_t seed : testing::testSeeds({0x5e9, 0x5ea})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    for (const NamedSegment& segment : kSegments) {
      SCOPED_TRACE(segment.name);
      const detail::ShapeFrame frame = frameOf(segment);
      const double R = frame.sphereRadius;
      Tally tally;
      for (std::size_t i = 0; i < raysPerSegment; ++i) {
        const Ray ray = randomRay(random, segment.p0, segment.p1, R, kinds[i % std::size(kinds)]);
        MeridianRay m{};
        if (!detail::setUpMeridianRay(frame, ray, m)) continue;  // misses the bounding sphere
        const std::string what = describe(ray);
        if (segment.p0.z == segment.p1.z) {
          checkAnnulus(m, segment.p0, segment.p1, R, what, tally);
        } else {
          checkCone(m, segment.p0, segment.p1, R, what, tally);
        }
        if (::testing::Test::HasFatalFailure()) return;
      }
      // Most rays are decided away from rounding, and many hit: the comparison is not vacuous.
      EXPECT_GT(tally.robustHits, tally.rays / 4);
      EXPECT_LT(tally.fragile, tally.rays / 50 + 1);
    }
  }
}

TEST(SegmentHits, NearTangentRootsKeepTheDigitsOfTheirNeighbourhood) {
  // A needle, the cylinder of radius r0 = 2^-10 R, and rays grazing it (passing the axis at
  // r0 (1 +- 10^-4)), from anywhere along a slab of height 1.8 R. Where the discriminant about the
  // middle of the ray's stretch has lost over 20 bits (computed here in long double, with 2 bits to
  // spare: 2^-22), the kernel expands g again about its extremum, next to the roots (segment_hits.h),
  // and its coefficients then carry the rounding of that neighbourhood rather than of the stretch's
  // middle, R away. Divided by ez^2 (er = 0, so L = r0 ez rounds once): rho^2 at the extremum
  // (px, py within 3 u R each, rho ~ r0) errs by 8.5 u R r0; 2 B x by 2 (4.3 u R) |x| <= 9 u R r0
  // (|x| <= r0 for roots this near tangency); the squares', L^2's and the discriminant's own
  // rounding by 14 u r0^2. So E = 32 u R r0 bounds F's error, here 2^-10 of the stretch-wide bound.
  const double r0 = 0x1p-10;
  const NamedSegment needle{"needle", {r0, -0.9}, {r0, 0.9}, 1.0};
  const detail::ShapeFrame frame = frameOf(needle);
  const double R = frame.sphereRadius;
  const Real E = 32 * u * R * r0;
  for (const std::uint64_t seed : testing::testSeeds({0x7a9})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::size_t grazing = 0, robust = 0;
    for (std::size_t i = 0; i < testing::scaledRays(20000); ++i) {
      const double phi = 2.0 * std::numbers::pi * unit(random), d = r0 * (1.0 + 1e-4 * (2.0 * unit(random) - 1.0));
      const double v = (0.2 + 0.7 * unit(random)) * (unit(random) < 0.5 ? -1.0 : 1.0), h = std::sqrt(1.0 - v * v);
      const double tx = -std::sin(phi) * h, ty = std::cos(phi) * h, zT = unit(random) - 0.5;
      const Ray ray{{float(d * std::cos(phi) - 3.0 * tx), float(d * std::sin(phi) - 3.0 * ty), float(zT - 3.0 * v)},
                    {float(tx), float(ty), float(v)}};
      MeridianRay m{};
      if (!detail::setUpMeridianRay(frame, ray, m)) continue;
      // The kernel's regime: the discriminant about the middle of the stretch, lost beyond 22 bits.
      const Real s0 = (Real(needle.p0.z) - m.oz) / Real(m.dz), s1 = (Real(needle.p1.z) - m.oz) / Real(m.dz);
      const Real c = 0.5L * (std::max(std::min(s0, s1), Real(m.lo)) + std::min(std::max(s0, s1), Real(m.hi)));
      const Expansion F = coneFunction(m, needle.p0, needle.p1, c);
      if (!(std::abs(F.B * F.B - F.A * F.C) < 0x1p-22L * (F.B * F.B + std::abs(F.A * F.C)))) continue;
      ++grazing;
      const detail::SegmentHits hits = detail::segmentHits(m, needle.p0, needle.p1, m.lo, m.hi);
      std::vector<int> claimed(hits.count, 0);
      for (const Component& component : analyse(m, needle.p0, needle.p1, R, E)) {
        int got = 0;
        for (int k = 0; k < hits.count; ++k) {
          if (component.span.holds(hits.s[k])) ++got, ++claimed[k];
        }
        if (component.fragile) continue;
        ASSERT_EQ(got, component.exact) << describe(ray) << ": component [" << double(component.span.lo) << ", "
                                        << double(component.span.hi) << "]";
        robust += component.exact > 0;
      }
      for (int k = 0; k < hits.count; ++k) {
        ASSERT_GE(claimed[k], 1) << describe(ray) << ": hit at s=" << hits.s[k]
                                 << ", |F| = " << double(std::abs(F.at(hits.s[k]))) << " beyond " << double(E);
      }
    }
    // Grazing rays were drawn, and most of them cross the needle away from rounding.
    EXPECT_GT(grazing, testing::scaledRays(20000) / 10);
    EXPECT_GT(robust, grazing / 2);
  }
}

// --- The header's contracts, each on rays whose answer is exact ---------------------------------

TEST(SegmentHits, HitsExactlyAtTnearAndTfarCount) {
  // The cone radius(z) = 1 + z, z in [-1, 1], and a ray parallel to the axis at x = 0.5: on the
  // surface exactly at z = -0.5, t = 2.5 (all of it exact in double).
  const Point2 p0{0.0, -1.0}, p1{2.0, 1.0};
  const detail::ShapeFrame frame = frameHolding(p0, p1);
  const Ray up{{0.5f, 0.0f, -3.0f}, {0.0f, 0.0f, 1.0f}};
  const auto hitsWithin = [&](float tnear, float tfar) {
    Ray ray = up;
    ray.tnear = tnear;
    ray.tfar = tfar;
    const MeridianRay m = meridian(frame, ray);
    std::vector<double> t;
    const detail::SegmentHits hits = detail::segmentHits(m, p0, p1, m.lo, m.hi);
    for (int i = 0; i < hits.count; ++i) t.push_back(m.t0 + hits.s[i] / m.tScale);
    return t;
  };
  EXPECT_EQ(hitsWithin(0.0f, INFINITY), (std::vector<double>{2.5}));
  EXPECT_EQ(hitsWithin(0.0f, 2.5f), (std::vector<double>{2.5}));      // tfar on the surface: inclusive
  EXPECT_EQ(hitsWithin(2.5f, INFINITY), (std::vector<double>{2.5}));  // tnear on the surface: inclusive
  EXPECT_EQ(hitsWithin(2.5f, 2.5f), (std::vector<double>{2.5}));
  EXPECT_TRUE(hitsWithin(0.0f, std::nextafter(2.5f, 0.0f)).empty());
  EXPECT_TRUE(hitsWithin(std::nextafter(2.5f, 3.0f), INFINITY).empty());

  // The same in a horizontal plane (the in-plane path): the cylinder r = 1 met at t = 2 and 4.
  const Point2 c0{1.0, -1.0}, c1{1.0, 1.0};
  const detail::ShapeFrame cylinder = frameHolding(c0, c1);
  for (const auto& [tnear, tfar, expected] :
       {std::tuple{0.0f, 4.0f, std::vector<double>{2.0, 4.0}}, std::tuple{2.0f, 3.0f, std::vector<double>{2.0}},
        std::tuple{3.0f, 4.0f, std::vector<double>{4.0}}, std::tuple{2.5f, 3.5f, std::vector<double>{}}}) {
    const MeridianRay m = meridian(cylinder, {{-3.0f, 0.0f, 0.25f}, {1.0f, 0.0f, 0.0f}, tnear, tfar});
    ASSERT_TRUE(m.inPlane);
    const detail::SegmentHits hits = detail::segmentHits(m, c0, c1, m.lo, m.hi);
    std::vector<double> t;
    for (int i = 0; i < hits.count; ++i) t.push_back(m.t0 + hits.s[i] / m.tScale);
    EXPECT_EQ(t, expected) << "[" << tnear << ", " << tfar << "]";
  }
}

TEST(SegmentHits, RaysInAHorizontalPlaneSeeTheHeightsASegmentOwnsHalfOpen) {
  // A segment owns [zmin, zmax): at its lower vertex's height a horizontal ray meets that vertex's
  // circle (twice, through it), at its upper vertex's height nothing, whichever way it runs.
  // (Named points, not structured bindings: clang 14 cannot capture those in a lambda.)
  for (const std::pair<Point2, Point2>& segment :
       {std::pair{Point2{1.0, -1.0}, Point2{2.0, 1.0}}, std::pair{Point2{2.0, 1.0}, Point2{1.0, -1.0}}}) {
    const Point2 p0 = segment.first, p1 = segment.second;
    const detail::ShapeFrame frame = frameHolding(p0, p1);
    const auto hitsAt = [&](float z) {
      const MeridianRay m = meridian(frame, {{-4.0f, 0.0f, z}, {1.0f, 0.0f, 0.0f}});
      const detail::SegmentHits hits = detail::segmentHits(m, p0, p1, m.lo, m.hi);
      std::vector<double> t;
      for (int i = 0; i < hits.count; ++i) t.push_back(m.t0 + hits.s[i] / m.tScale);
      return t;
    };
    EXPECT_EQ(hitsAt(-1.0f), (std::vector<double>{3.0, 5.0}));  // the circle of radius 1
    EXPECT_EQ(hitsAt(0.0f), (std::vector<double>{2.5, 5.5}));   // radius 1.5
    EXPECT_TRUE(hitsAt(1.0f).empty());
    EXPECT_TRUE(hitsAt(-1.5f).empty());
  }
}

TEST(SegmentHits, AnnulusIsHitBetweenItsCirclesHalfOpen) {
  // A ray down the axis and rays straight down at exact radii: the disc holds its centre, the
  // annulus [0.5, 1) its inner circle but not its outer one, in either orientation.
  const Point2 disc0{0.0, 0.5}, disc1{1.0, 0.5};
  for (const auto& [p0, p1] :
       {std::pair{Point2{0.5, 0.5}, Point2{1.0, 0.5}}, std::pair{Point2{1.0, 0.5}, Point2{0.5, 0.5}}}) {
    const detail::ShapeFrame frame = frameHolding(p0, p1);
    const auto hitCount = [&](Point2 a, Point2 b, float x) {
      const MeridianRay m = meridian(frame, {{x, 0.0f, 2.0f}, {0.0f, 0.0f, -1.0f}});
      const detail::SegmentHits hits = detail::segmentHits(m, a, b, m.lo, m.hi);
      if (hits.count == 1) {
        EXPECT_EQ(m.t0 + hits.s[0] / m.tScale, 1.5);
      }
      return hits.count;
    };
    EXPECT_EQ(hitCount(disc0, disc1, 0.0f), 1);
    EXPECT_EQ(hitCount(p0, p1, 0.0f), 0);
    EXPECT_EQ(hitCount(p0, p1, 0.25f), 0);
    EXPECT_EQ(hitCount(p0, p1, 0.5f), 1);
    EXPECT_EQ(hitCount(p0, p1, 0.75f), 1);
    EXPECT_EQ(hitCount(p0, p1, 1.0f), 0);
  }
}

TEST(SegmentHits, EveryRayThroughAnApexTouchesIt) {
  // Lines through the apex exactly: origin = apex + D and direction -D, with D on a grid of 2^-20
  // (|D| < 4), so that both are exact in float. Whether they enter the cone there or pass it
  // outside (where F has a double root at the apex, which rounding keeps or loses at random), the
  // apex is a hit: a root the brackets find, or the touch addApexTouch adds, which must lie where
  // |F| <= E around the apex, as any hit must. The apexes lie off the bounding sphere's centre, so
  // that the apex plane's crossing rounds (by about u R / |dz|); slopes run from steep down to
  // 1 in 20,000, where that rounding moves the crossing farther than the touch's tolerance.
  const NamedSegment cones[] = {{"apex below", {0.0, -0.75}, {1.0, 0.5}},
                                {"apex above", {1.0, -0.5}, {0.0, 0.75}},
                                {"apex below, nearly flat", {0.0, 0.25}, {1.0, 0.25 + 1e-3}},
                                {"apex below, steep", {0.0, -1.0}, {0.125, 1.0}}};
  for (const std::uint64_t seed : testing::testSeeds({0xa9e})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto onGrid = [](double x) { return float(std::ldexp(std::round(std::ldexp(x, 20)), -20)); };
    for (const NamedSegment& cone : cones) {
      SCOPED_TRACE(cone.name);
      const detail::ShapeFrame frame = frameOf(cone);
      const double R = frame.sphereRadius;
      const float apexZ = float(cone.p0.r == 0.0 ? cone.p0.z : cone.p1.z);
      std::size_t touched = 0;
      for (std::size_t i = 0; i < testing::scaledRays(4000); ++i) {
        const double psi = 2.0 * std::numbers::pi * unit(random);
        const double slope =
            i % 2 == 0 ? 2.0 * unit(random) - 1.0 : std::pow(10.0, -4.3 * unit(random)) * (i % 4 == 1 ? 1 : -1);
        const Vec3 D{onGrid(2.0 * R * std::cos(psi)), onGrid(2.0 * R * std::sin(psi)), onGrid(2.0 * R * slope)};
        if (D.z == 0.0f) continue;  // in the apex's plane: the in-plane rule, not the touch
        const Ray ray{{D.x, D.y, apexZ + D.z}, {-D.x, -D.y, -D.z}};
        ASSERT_EQ(ray.origin.z - apexZ, D.z) << "the origin must be exact";
        const MeridianRay m = meridian(frame, ray);
        const detail::SegmentHits hits = detail::segmentHits(m, cone.p0, cone.p1, m.lo, m.hi);
        // The component of |F| <= E holding the line's closest approach to the apex.
        const Real sApex = -(m.ox * Real(m.dx) + m.oy * Real(m.dy) + (m.oz - Real(apexZ)) * m.dz);
        int atApex = 0;
        for (const Component& component : analyse(m, cone.p0, cone.p1, R)) {
          if (!component.span.holds(sApex)) continue;
          for (int k = 0; k < hits.count; ++k) atApex += component.span.holds(hits.s[k]);
        }
        ASSERT_GE(atApex, 1) << describe(ray) << ": " << hits.count << " hits, none at the apex";
        ++touched;
      }
      EXPECT_GT(touched, testing::scaledRays(4000) * 9 / 10);
    }
  }
}

TEST(SegmentHits, RayAlongAGeneratorHitsWhereItMeetsTheSegment) {
  // In the meridian plane y = 0, x = -z runs along the cone r = z from its rim (-1, 0, 1) to the
  // apex: every point of it is on the surface. Its first hit is where it enters the segment's slab,
  // t = 1 (within the plane crossing's rounding, 8 u R / |dz|), at the rim.
  const Point2 p0{0.0, 0.0}, p1{1.0, 1.0};
  const detail::ShapeFrame frame = frameHolding(p0, p1);
  const MeridianRay m = meridian(frame, {{-2.0f, 0.0f, 2.0f}, {1.0f, 0.0f, -1.0f}});
  const detail::SegmentHits hits = detail::segmentHits(m, p0, p1, m.lo, m.hi);
  ASSERT_GE(hits.count, 1);
  const double t = m.t0 + hits.s[0] / m.tScale;
  EXPECT_NEAR(t, 1.0, 8 * u * frame.sphereRadius / std::abs(m.dz) / m.tScale + 4 * u);
}

TEST(SegmentHits, SegmentOnTheAxisSweepsNothing) {
  const Point2 p0{0.0, -1.0}, p1{0.0, 1.0};
  const MeridianRay m = meridian(frameHolding(p0, p1), {{-2.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.25f}});
  EXPECT_EQ(detail::segmentHits(m, p0, p1, m.lo, m.hi).count, 0);
}

}  // namespace
}  // namespace revolve
