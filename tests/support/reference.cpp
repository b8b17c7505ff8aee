// Independent test oracle: see reference.h. Everything is long double; nothing calls the library.
#include "reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace revolve::reference {
namespace {

using Real = long double;

// Unit roundoff of long double: every basic operation's relative error is at most this.
constexpr Real kUnitRoundoff = std::numeric_limits<Real>::epsilon() / 2;

struct Vec {
  Real x, y, z;
};

Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(Real s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
Real dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Real length(Vec a) { return std::sqrt(dot(a, a)); }
Vec normalized(Vec a) { return (1 / length(a)) * a; }

Vec origin(const RefRay& ray) { return {ray.ox, ray.oy, ray.oz}; }
Vec direction(const RefRay& ray) { return {ray.dx, ray.dy, ray.dz}; }
Vec pointAt(const RefRay& ray, Real t) { return {ray.ox + t * ray.dx, ray.oy + t * ray.dy, ray.oz + t * ray.dz}; }

// The library's rule for rays that miss everything, so that the oracle answers them alike.
bool isValid(const RefRay& ray) {
  const bool finiteOrigin = std::isfinite(ray.ox) && std::isfinite(ray.oy) && std::isfinite(ray.oz);
  const bool finiteDirection = std::isfinite(ray.dx) && std::isfinite(ray.dy) && std::isfinite(ray.dz);
  const bool nonZeroDirection = ray.dx != 0 || ray.dy != 0 || ray.dz != 0;
  const bool orderedRange = !std::isnan(ray.tnear) && !std::isnan(ray.tfar) && ray.tnear <= ray.tfar;
  return finiteOrigin && finiteDirection && nonZeroDirection && orderedRange;
}

bool inRange(const RefRay& ray, Real t) { return ray.tnear <= t && t <= ray.tfar; }

RefHit makeHit(Real t, Vec normal, std::size_t segment) { return {t, normal.x, normal.y, normal.z, segment}; }

// Real roots of a t^2 + b t + c = 0 in increasing order, a double root once. Uses the
// cancellation-free form (Numerical Recipes 5.6): q = -(b + sign(b) sqrt(disc)) / 2, roots q / a
// and c / q, so neither root is the small difference of two large numbers.
struct QuadraticRoots {
  int count = 0;
  Real value[2] = {0, 0};
};

QuadraticRoots solveQuadratic(Real a, Real b, Real c) {
  QuadraticRoots roots;
  if (a == 0) {
    if (b != 0) roots.value[roots.count++] = -c / b;
    return roots;  // b == 0 too: no root, or (c == 0) every t, which the callers do not report
  }
  const Real discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return roots;
  if (discriminant == 0) {
    roots.value[roots.count++] = -b / (2 * a);
    return roots;
  }
  // discriminant > 0, so |b| + sqrt(discriminant) > 0 and q != 0.
  const Real q = -(b + std::copysign(std::sqrt(discriminant), b)) / 2;
  roots.value[0] = q / a;
  roots.value[1] = c / q;
  roots.count = 2;
  if (roots.value[0] > roots.value[1]) std::swap(roots.value[0], roots.value[1]);
  return roots;
}

// ---------------------------------------------------------------------------------------------
// Profile brute force.

// The meridian normal (nr, nz) rotated to the angle of the point (x, y); on the axis, where the
// angle is undefined, phi = atan2(0, 0) = 0 as the library's u.
Vec rotateMeridianNormal(Real nr, Real nz, Real x, Real y) {
  const Real rho = std::hypot(x, y);
  if (rho == 0) return {nr, 0, nz};
  return {nr * x / rho, nr * y / rho, nz};
}

struct Segment {
  Real r0, z0, r1, z1;
  Real normalR, normalZ;  // unit meridian normal (z1 - z0, -(r1 - r0)) / length
  std::size_t index;
};

// Horizontal segment: the plane z = z0, kept where the hit's distance from the axis is within the
// segment's radius range.
void appendPlaneHits(const Segment& s, const RefRay& ray, std::vector<RefHit>& hits) {
  if (ray.dz == 0) return;  // parallel to the plane (or inside it: not reported)
  const Real t = (s.z0 - ray.oz) / ray.dz;
  if (!inRange(ray, t)) return;
  const Vec p = pointAt(ray, t);
  const Real rho = std::hypot(p.x, p.y);
  if (rho < std::min(s.r0, s.r1) || rho > std::max(s.r0, s.r1)) return;
  hits.push_back(makeHit(t, rotateMeridianNormal(s.normalR, s.normalZ, p.x, p.y), s.index));
}

// Whether the ray's line passes through the point (0, 0, z), and the t of its closest approach.
// Decided up to the long-double rounding of that distance: each coordinate of `across` is formed
// by a handful of roundings of terms no larger than |offset| (|t d| <= |offset|), under 12 u
// |offset| each, so a line through the point is found within 32 u |offset|.
bool linePassesThrough(const RefRay& ray, Real z, Real& t) {
  const Vec d = direction(ray);
  const Vec offset{-ray.ox, -ray.oy, z - ray.oz};
  t = dot(offset, d) / dot(d, d);
  const Vec across = offset - t * d;
  return length(across) <= 32 * kUnitRoundoff * length(offset);
}

// Non-horizontal segment: the cone x^2 + y^2 = (r0 + (z - z0) * slope)^2, slope = dr / dz
// (slope 0 is the cylinder). Substituting the ray, the radius is a0 + a1 t, and
//   (dx^2 + dy^2 - a1^2) t^2 + 2 (ox dx + oy dy - a0 a1) t + (ox^2 + oy^2 - a0^2) = 0.
// The equation also holds on the mirror nappe (radius < 0) and beyond the segment's ends, so a
// root counts only if its z lies in the segment's closed z range and its radius is >= 0. (The
// radius, linear in z and >= 0 at both ends, is >= 0 over the whole range, so the z test alone
// already rejects the mirror nappe; the radius test states the intent and costs nothing.)
//
// Two rules of the library's (revolve.h, README's Hard cases) decide what rounding cannot:
// - The apex rule: a line through the apex of a segment reaching the axis meets the double cone
//   there only, a double root that rounding of the coefficients would keep or lose at random.
//   Such a ray touches the surface at the apex: a hit, whatever its plane. (A line along a
//   generator, all of whose points are roots, is reported at the apex alone.)
// - The half-open height rule for a ray in a horizontal plane (dz = 0): the segment owns the
//   heights [zMin, zMax), so at a vertex's height the ray meets the circles of the segments that
//   continue upwards from it, the cross-section just above the plane (at a top rim, nothing).
void appendConeHits(const Segment& s, const RefRay& ray, std::vector<RefHit>& hits) {
  for (const auto& [r, z] : {std::pair{s.r0, s.z0}, std::pair{s.r1, s.z1}}) {
    Real t;
    if (r == 0 && linePassesThrough(ray, z, t)) {
      if (inRange(ray, t)) hits.push_back(makeHit(t, rotateMeridianNormal(s.normalR, s.normalZ, 0, 0), s.index));
      return;
    }
  }
  const Real zMin = std::min(s.z0, s.z1);
  const Real zMax = std::max(s.z0, s.z1);
  if (ray.dz == 0) {
    if (!(zMin <= ray.oz && ray.oz < zMax)) return;
    // In an apex's plane, off the apex: the circle of radius 0 is not met.
    if ((ray.oz == s.z0 && s.r0 == 0) || (ray.oz == s.z1 && s.r1 == 0)) return;
  }
  const Real slope = (s.r1 - s.r0) / (s.z1 - s.z0);
  const Real a0 = s.r0 + (ray.oz - s.z0) * slope;  // cone radius at the origin's height
  const Real a1 = ray.dz * slope;                  // its rate of change along the ray
  const QuadraticRoots roots =
      solveQuadratic(ray.dx * ray.dx + ray.dy * ray.dy - a1 * a1, 2 * (ray.ox * ray.dx + ray.oy * ray.dy - a0 * a1),
                     ray.ox * ray.ox + ray.oy * ray.oy - a0 * a0);
  for (int i = 0; i < roots.count; ++i) {
    const Real t = roots.value[i];
    if (!inRange(ray, t)) continue;
    const Vec p = pointAt(ray, t);
    if (p.z < zMin || p.z > zMax) continue;
    if (s.r0 + (p.z - s.z0) * slope < 0) continue;
    hits.push_back(makeHit(t, rotateMeridianNormal(s.normalR, s.normalZ, p.x, p.y), s.index));
  }
}

void appendSegmentHits(Point2 a, Point2 b, std::size_t index, const RefRay& ray, std::vector<RefHit>& hits) {
  Segment s{a.r, a.z, b.r, b.z, 0, 0, index};
  const Real dr = s.r1 - s.r0;
  const Real dz = s.z1 - s.z0;
  if (dr == 0 && dz == 0) return;  // a repeated point sweeps no surface
  const Real len = std::hypot(dr, dz);
  s.normalR = dz / len;
  s.normalZ = -dr / len;
  if (dz == 0) {
    appendPlaneHits(s, ray, hits);
  } else {
    appendConeHits(s, ray, hits);
  }
}

// 2-D distance from (r, z) to the segment a-b: project onto the segment's line, clamp to it.
Real distanceToSegment(Real r, Real z, Point2 a, Point2 b) {
  const Real dr = Real(b.r) - a.r;
  const Real dz = Real(b.z) - a.z;
  const Real len2 = dr * dr + dz * dz;
  Real s = 0;
  if (len2 > 0) s = std::clamp(((r - a.r) * dr + (z - a.z) * dz) / len2, Real(0), Real(1));
  return std::hypot(r - (a.r + s * dr), z - (a.z + s * dz));
}

// ---------------------------------------------------------------------------------------------
// Torus.

// Bisection of f on [a, b] where f(a) and f(b) are non-zero with opposite signs, down to adjacent
// long doubles; returns the end with the smaller |f|. Needs no tolerance: it stops when the
// midpoint rounds to an end.
template <class F>
Real bisect(F f, Real a, Real b, Real fa, Real fb) {
  for (;;) {
    const Real mid = a + (b - a) / 2;
    if (mid <= a || mid >= b) break;
    const Real fm = f(mid);
    if (fm == 0) return mid;
    if ((fm < 0) == (fa < 0)) {
      a = mid;
      fa = fm;
    } else {
      b = mid;
      fb = fm;
    }
  }
  return std::fabs(fa) <= std::fabs(fb) ? a : b;
}

// The ring torus' quartic along a ray. With P = O + t d, S = |P|^2 + R^2 - rho^2 and
// w = x^2 + y^2, the torus is q(t) = S^2 - 4 R^2 w = 0, negative inside the tube.
//   q'(t)  = 4 S (P.d) - 8 R^2 (x dx + y dy)
//   q''(t) = |d|^2 (12 sigma^2 + 4 K), sigma = t |d| + O.u (u = d / |d|: the arc length from
//            the point of the line closest to the origin), K = m^2 + R^2 - rho^2 - 2 R^2 (ux^2 + uy^2),
//            m = distance from the origin to the line. (|P|^2 = sigma^2 + m^2, P.u = sigma.)
// q'' is a quadratic with closed-form roots, so the real roots of the quartic are isolated
// exactly: between consecutive roots of q'' q' is monotone (at most one root, found by bisection);
// between consecutive roots of q' q is monotone (at most one root, found by bisection). No
// sampling step is involved, so no pair of roots can be missed for being close together.
// What rounding does decide is a near-tangency: q is known only to +-dq (roundingBound), so
// an extremum with |q| <= dq may be a pair of roots up to sqrt(2 dq / |q''|) apart or a near miss
// by up to dq / |grad f|. Such an extremum counts as a hit: if the computed q crosses zero, as two
// bisected roots; if it only comes within dq of zero, as one (tangent) root at the extremum.
struct TorusQuartic {
  Real majorRadius, minorRadius;
  RefRay ray;

  Real value(Real t) const {
    const Vec p = pointAt(ray, t);
    const Real s = sum(p);
    return s * s - 4 * majorRadius * majorRadius * (p.x * p.x + p.y * p.y);
  }
  Real derivative(Real t) const {
    const Vec p = pointAt(ray, t);
    return 4 * sum(p) * dot(p, direction(ray)) - 8 * majorRadius * majorRadius * (p.x * ray.dx + p.y * ray.dy);
  }
  // |grad f| at p, f(P) = S^2 - 4 R^2 (x^2 + y^2): grad f = 4 S P - 8 R^2 (x, y, 0).
  Real gradientNorm(Vec p) const {
    const Real s = sum(p);
    const Real r2 = majorRadius * majorRadius;
    return length(Vec{(4 * s - 8 * r2) * p.x, (4 * s - 8 * r2) * p.y, 4 * s * p.z});
  }
  // Upper bound on |computed value(t) - exact q(t)|:
  // - the point's coordinates O + t d carry absolute error <= 2u (|O| + |t| |d|) each (one product
  //   and one sum), moving q by at most sqrt(3) * that * |grad f| to first order;
  // - evaluating f at a given point: S sums 5 terms of total size Sigma = |P|^2 + R^2 + rho^2 with
  //   relative error <= 8u, so S^2 errs by <= 2 |S| 8u Sigma + u S^2, and 4 R^2 w (<= Sigma^2) by
  //   <= 6u Sigma^2: in all <= 32u Sigma^2 since |S| <= Sigma.
  // The bound is doubled to cover second-order terms.
  Real roundingBound(Real t) const {
    const Vec p = pointAt(ray, t);
    const Real coordinateError = 2 * kUnitRoundoff * (length(origin(ray)) + std::fabs(t) * length(direction(ray)));
    const Real sigma = dot(p, p) + majorRadius * majorRadius + minorRadius * minorRadius;
    return 2 * (std::sqrt(Real(3)) * coordinateError * gradientNorm(p) + 32 * kUnitRoundoff * sigma * sigma);
  }

 private:
  Real sum(Vec p) const { return dot(p, p) + majorRadius * majorRadius - minorRadius * minorRadius; }
};

struct CriticalPoint {
  Real t;
  bool minimum;  // q' goes from negative to positive
};

// Roots of q' in [lo, hi], each piece between consecutive breakpoints being monotone in q'.
std::vector<CriticalPoint> criticalPoints(const TorusQuartic& quartic, const std::vector<Real>& breakpoints) {
  auto derivative = [&](Real t) { return quartic.derivative(t); };
  std::vector<CriticalPoint> critical;
  for (std::size_t i = 0; i + 1 < breakpoints.size(); ++i) {
    const Real a = breakpoints[i];
    const Real b = breakpoints[i + 1];
    const Real fa = derivative(a);
    const Real fb = derivative(b);
    if (fa == 0) {
      // q' is monotone on [a, b]: its sign after a tells the kind (if it stays 0, q is flat there).
      if (fb != 0) critical.push_back({a, fb > 0});
    } else if (fb != 0 && (fa < 0) != (fb < 0)) {
      critical.push_back({bisect(derivative, a, b, fa, fb), fa < 0});
    }
  }
  return critical;
}

// Every root of the quartic in [lo, hi] (which must lie outside the torus' bounding sphere at
// infinite ends: callers clip to a bounding sphere first).
std::vector<Real> torusRoots(const TorusQuartic& quartic, Real lo, Real hi) {
  const RefRay& ray = quartic.ray;
  const Vec d = direction(ray);
  const Real speed = length(d);
  const Vec u = (1 / speed) * d;
  const Real originAlong = dot(origin(ray), u);
  const Vec foot = origin(ray) - originAlong * u;
  const Real R2 = quartic.majorRadius * quartic.majorRadius;
  const Real K = dot(foot, foot) + R2 - quartic.minorRadius * quartic.minorRadius - 2 * R2 * (u.x * u.x + u.y * u.y);

  // Pieces on which q' is monotone: [lo, hi] split at the roots of q''.
  std::vector<Real> breakpoints{lo};
  if (K < 0) {
    const Real sigma = std::sqrt(-K / 3);
    for (Real root : {(-sigma - originAlong) / speed, (sigma - originAlong) / speed}) {
      if (root > lo && root < hi) breakpoints.push_back(root);
    }
  }
  breakpoints.push_back(hi);

  // Pieces on which q is monotone: [lo, hi] split at the roots of q'.
  const std::vector<CriticalPoint> critical = criticalPoints(quartic, breakpoints);
  std::vector<Real> monotoneEnds{lo};
  for (const CriticalPoint& c : critical) {
    if (c.t > monotoneEnds.back() && c.t < hi) monotoneEnds.push_back(c.t);
  }
  monotoneEnds.push_back(hi);

  auto value = [&](Real t) { return quartic.value(t); };
  std::vector<Real> roots;
  for (std::size_t i = 0; i + 1 < monotoneEnds.size(); ++i) {
    const Real a = monotoneEnds[i];
    const Real b = monotoneEnds[i + 1];
    const Real fa = value(a);
    const Real fb = value(b);
    if (fa == 0) {
      roots.push_back(a);
    } else if (fb != 0 && (fa < 0) != (fb < 0)) {
      roots.push_back(bisect(value, a, b, fa, fb));
    }
  }
  if (hi > lo && value(hi) == 0) roots.push_back(hi);

  // Tangency: an extremum that approaches zero within rounding without crossing it. The computed
  // critical point is off the true one by rounding, which moves q there only to second order.
  for (const CriticalPoint& c : critical) {
    const Real q = value(c.t);
    const bool approachesZero = c.minimum ? q > 0 : q < 0;
    if (approachesZero && std::fabs(q) <= quartic.roundingBound(c.t)) roots.push_back(c.t);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

std::vector<RefHit> allHits(std::span<const Point2> profile, const RefRay& ray) {
  std::vector<RefHit> hits;
  if (!isValid(ray)) return hits;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) appendSegmentHits(profile[i], profile[i + 1], i, ray, hits);
  std::sort(hits.begin(), hits.end(),
            [](const RefHit& a, const RefHit& b) { return a.t < b.t || (a.t == b.t && a.segment < b.segment); });
  return hits;
}

std::optional<RefHit> intersectProfile(std::span<const Point2> profile, const RefRay& ray) {
  const std::vector<RefHit> hits = allHits(profile, ray);
  if (hits.empty()) return std::nullopt;
  return hits.front();
}

long double meridianDistance(std::span<const Point2> profile, long double x, long double y, long double z) {
  const Real r = std::hypot(x, y);
  if (profile.size() == 1) return std::hypot(r - profile[0].r, z - profile[0].z);
  Real best = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    best = std::min(best, distanceToSegment(r, z, profile[i], profile[i + 1]));
  }
  return best;
}

std::optional<RefHit> intersectCylinder(long double radius, long double z0, long double z1, const RefRay& ray) {
  if (z0 == z1) throw std::invalid_argument("intersectCylinder: z0 == z1 sweeps no lateral surface");
  if (!isValid(ray)) return std::nullopt;
  // In the xy plane the ray is the line o + t d; its closest approach to the axis is at tClosest,
  // at distance c, and it crosses the circle of radius R at tClosest +- sqrt(R^2 - c^2) / |d|.
  const Real planarSpeed2 = ray.dx * ray.dx + ray.dy * ray.dy;
  if (planarSpeed2 == 0) return std::nullopt;  // parallel to the axis: never crosses the surface
  const Real tClosest = -(ray.ox * ray.dx + ray.oy * ray.dy) / planarSpeed2;
  const Real cx = ray.ox + tClosest * ray.dx;
  const Real cy = ray.oy + tClosest * ray.dy;
  const Real gap2 = radius * radius - (cx * cx + cy * cy);
  if (gap2 < 0) return std::nullopt;
  const Real halfChord = std::sqrt(gap2 / planarSpeed2);
  const Real orientation = z1 > z0 ? 1 : -1;  // (dz, -dr) = (z1 - z0, 0): outward iff going up
  for (Real t : {tClosest - halfChord, tClosest + halfChord}) {
    if (!inRange(ray, t)) continue;
    const Vec p = pointAt(ray, t);
    if (p.z < std::min(z0, z1) || p.z > std::max(z0, z1)) continue;
    return makeHit(t, orientation * normalized(Vec{p.x, p.y, 0}), 0);
  }
  return std::nullopt;
}

std::optional<RefHit> intersectCone(long double r0, long double z0, long double r1, long double z1, const RefRay& ray) {
  if (z0 == z1) throw std::invalid_argument("intersectCone: horizontal segment, use intersectDisc");
  if (r0 == r1) return intersectCylinder(r0, z0, z1, ray);
  if (!isValid(ray)) return std::nullopt;
  const Real height = z1 - z0;
  const Real widening = r1 - r0;
  // Apex V = (0, 0, apexZ), where the radius (linear in z) reaches 0; axis a = (0, 0, axisZ) points
  // from V towards growing radius; theta is the half angle: cos^2 = height^2 / (height^2 + widening^2).
  const Real apexZ = z0 - r0 * height / widening;
  const Real axisZ = height * widening > 0 ? 1 : -1;
  const Real cos2 = height * height / (height * height + widening * widening);
  // With C = O - V: ((C + t d).a)^2 - cos^2 |C + t d|^2 = 0.
  const Vec c{ray.ox, ray.oy, ray.oz - apexZ};
  const Vec d = direction(ray);
  const Real dAlong = d.z * axisZ;
  const Real cAlong = c.z * axisZ;
  const QuadraticRoots roots = solveQuadratic(
      dAlong * dAlong - cos2 * dot(d, d), 2 * (dAlong * cAlong - cos2 * dot(d, c)), cAlong * cAlong - cos2 * dot(c, c));
  for (int i = 0; i < roots.count; ++i) {
    const Real t = roots.value[i];
    if (!inRange(ray, t)) continue;
    const Vec p = pointAt(ray, t);
    const Vec fromApex{p.x, p.y, p.z - apexZ};
    const Real along = fromApex.z * axisZ;
    if (along < 0) continue;  // the other nappe
    if (p.z < std::min(z0, z1) || p.z > std::max(z0, z1)) continue;
    // Gradient of the implicit function, 2 ((P - V).a) a - 2 cos^2 (P - V), oriented so that its z
    // component has the sign of the meridian normal's, -(r1 - r0). It vanishes only at the apex,
    // where the normal is the meridian one at phi = 0.
    const Vec gradient{-cos2 * fromApex.x, -cos2 * fromApex.y, along * axisZ - cos2 * fromApex.z};
    const Real meridianLength = std::hypot(height, widening);
    Vec normal{height / meridianLength, 0, -widening / meridianLength};
    if (length(gradient) > 0) {
      normal = normalized(gradient);
      if ((normal.z < 0) != (widening > 0)) normal = -1 * normal;
    }
    return makeHit(t, normal, 0);
  }
  return std::nullopt;
}

std::optional<RefHit> intersectDisc(long double z, long double rInner, long double rOuter, const RefRay& ray) {
  if (rInner == rOuter) throw std::invalid_argument("intersectDisc: rInner == rOuter sweeps no surface");
  if (!isValid(ray) || ray.dz == 0) return std::nullopt;
  const Real t = (z - ray.oz) / ray.dz;
  if (!inRange(ray, t)) return std::nullopt;
  const Vec p = pointAt(ray, t);
  const Real rho = std::hypot(p.x, p.y);
  if (rho < std::min(rInner, rOuter) || rho > std::max(rInner, rOuter)) return std::nullopt;
  return makeHit(t, Vec{0, 0, rInner < rOuter ? Real(-1) : Real(1)}, 0);
}

std::optional<RefHit> intersectSphere(long double centerZ, long double radius, const RefRay& ray) {
  if (!isValid(ray)) return std::nullopt;
  const Vec center{0, 0, centerZ};
  const Vec d = direction(ray);
  const Real speed2 = dot(d, d);
  // Closest approach of the line to the centre, then the half chord sqrt(R^2 - c^2) / |d|.
  const Real tClosest = dot(center - origin(ray), d) / speed2;
  const Vec offset = pointAt(ray, tClosest) - center;
  const Real gap2 = radius * radius - dot(offset, offset);
  if (gap2 < 0) return std::nullopt;
  const Real halfChord = std::sqrt(gap2 / speed2);
  for (Real t : {tClosest - halfChord, tClosest + halfChord}) {
    if (!inRange(ray, t)) continue;
    return makeHit(t, normalized(pointAt(ray, t) - center), 0);
  }
  return std::nullopt;
}

std::optional<RefHit> intersectTorus(long double majorRadius, long double minorRadius, const RefRay& ray) {
  if (!(minorRadius > 0 && minorRadius < majorRadius)) {
    throw std::invalid_argument("intersectTorus: needs 0 < minorRadius < majorRadius (a ring torus)");
  }
  if (!isValid(ray)) return std::nullopt;
  // Search only where the line is within a sphere about the origin of twice the torus' outer
  // radius: it holds the torus with room to spare, so rounding of the clipped interval's ends cannot
  // cut off a root, and at its ends q > 0.
  const Vec d = direction(ray);
  const Real speed = length(d);
  const Vec u = (1 / speed) * d;
  const Real originAlong = dot(origin(ray), u);
  const Vec foot = origin(ray) - originAlong * u;
  const Real bound = 2 * (majorRadius + minorRadius);
  const Real halfChord2 = bound * bound - dot(foot, foot);
  if (halfChord2 <= 0) return std::nullopt;
  const Real halfChord = std::sqrt(halfChord2);
  const Real lo = std::max(ray.tnear, (-halfChord - originAlong) / speed);
  const Real hi = std::min(ray.tfar, (halfChord - originAlong) / speed);
  if (!(lo <= hi)) return std::nullopt;

  const TorusQuartic quartic{majorRadius, minorRadius, ray};
  const std::vector<Real> roots = torusRoots(quartic, lo, hi);
  if (roots.empty()) return std::nullopt;
  const Real t = roots.front();
  // Outward normal: from the nearest point of the core circle to the hit.
  const Vec p = pointAt(ray, t);
  const Real rho = std::hypot(p.x, p.y);  // > 0: a ring torus never meets the axis
  const Vec core{majorRadius * p.x / rho, majorRadius * p.y / rho, 0};
  return makeHit(t, normalized(p - core), 0);
}

bool verdictIsFragile(std::span<const Point2> profile, const RefRay& ray, long double nudge, long double size) {
  // A ray in a vertex's horizontal plane is nudged within the plane: there the half-open rule, not
  // rounding, decides its answer, and off the plane another rule applies.
  bool inVertexPlane = false;
  for (const Point2& p : profile) inVertexPlane |= ray.dz == 0 && ray.oz == p.z;
  const std::optional<RefHit> hit = intersectProfile(profile, ray);
  const long double speed = std::sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
  for (int axis = 0; axis < (inVertexPlane ? 2 : 3); ++axis) {
    for (long double sign : {-1.0L, 1.0L}) {
      RefRay moved = ray;
      (axis == 0 ? moved.ox : axis == 1 ? moved.oy : moved.oz) += sign * nudge;
      const std::optional<RefHit> other = intersectProfile(profile, moved);
      if (other.has_value() != hit.has_value()) return true;
      // A nudge that moves the nearest hit to another part of the surface (a seam, or a nearer
      // surface appearing) makes the distance fragile too.
      if (other && hit && std::abs(other->t - hit->t) * speed > 1e-6L * size) return true;
    }
  }
  return false;
}

bool passesNearAnApex(std::span<const Point2> profile, const RefRay& ray, long double distance) {
  const Vec d = direction(ray);
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    if (profile[i].z == profile[i + 1].z) continue;  // a disc's centre is no apex
    for (const Point2& p : {profile[i], profile[i + 1]}) {
      if (p.r != 0) continue;
      // The apex's offset from the origin, less its projection on the line.
      const Vec offset = Vec{0, 0, p.z} - origin(ray);
      const Vec across = offset - (dot(offset, d) / dot(d, d)) * d;
      if (length(across) <= distance) return true;
    }
  }
  return false;
}

}  // namespace revolve::reference
