// A ray against one monotone part of a spline profile revolved: the leaf kernel of spline shapes.
//
// The part is a cubic (r(u), z(u)), u in [0, 1], with r and z each monotone, so it lies in the box
// of its ends and, unless it is horizontal, owns the slab between its ends' planes as a segment
// does. At height z(u) the ray is at s(u) = planeS(z(u)), and
//     F(u) = rho^2(s(u)) - r(u)^2
// is negative exactly where the ray is inside the surface at that height: a polynomial of degree 6
// in u. Its hits are its roots.
//
// Watertightness, as for segments (segment_hits.h): F at u = 0 and u = 1 is computed with exactly
// the vertex-plane predicate's expression, rho2At(planeS(z_vertex)) - r_vertex^2, the value every
// neighbour (part or segment) computes at that vertex. The roots follow from signs: F's Bernstein
// coefficients bound the number of roots in an interval by their sign changes (Descartes' rule for
// the Bernstein basis), the end signs are the shared predicates, and intervals are halved (signs at
// the halving points by direct evaluation) until each holds one sign change or none. So every part
// reports hits with the parity its shared end signs dictate, and a ray leaving a closed solid is
// always reported hitting it. A root is placed by safeguarded Newton steps on the direct
// evaluation, inside its sign bracket; its s is the ray's parameter at the root's height (or, where
// that height's rounding over dz would move s noticeably, at the root's radius: rayParameterAt).
//
// Conditioning: F's coefficients carry rounding of the order of u times the squared size of the
// ray's stretch in the slab. A nearly horizontal ray crosses a slab along a stretch far longer
// than the shape; when that stretch exceeds 2^8 R, the part is first restricted (de Casteljau) to
// the heights the ray has within [lo, hi], and when that restriction is shorter than 2^-28 of
// the part, its chord replaces it (the sagitta, at most 3 R (2^-28)^2, is below the rounding of the
// coordinates) and Wang's kernel solves the chord. A part far below the rounding of rho^2 at the
// shape's scale has coefficients of noise: halving is bounded (kMaxHalvings) so it ends.
#pragma once

#include "util/isa.h"

#include "curve/cubic.h"
#include "kernel/meridian_ray.h"
#include "kernel/segment_hits.h"
#include "util/rounding.h"

#include <revolve/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace revolve::detail {

// A monotone part in the shape's local frame, as the kernel and the hit's attributes need it: 72
// bytes, its control points first (a scene of a million 64-point splines holds some 77 million).
// What only a hit's v needs (curve/arc_record.h) and the Bezier piece it came from (Shape::
// splinePiece) are kept beside the parts, in detail::SplineData.
struct CurvePart {
  double r[4], z[4];  // control points; (r[0], z[0]) and (r[3], z[3]) are exactly the part's vertices
  // A curved part's record of v in SplineData::arcRecords (unused for a straight part, whose v is its
  // chord's: SegmentFrame), and its table's steps (at most arc_table.h's 1,024).
  std::uint32_t arcRecord;
  std::uint16_t arcSteps;
  // Its control points lie within the coordinates' rounding of its chord (or it is horizontal): the
  // surface is a truncated cone or an annulus, and Wang's kernel solves it.
  bool straight;
};
static_assert(sizeof(CurvePart) == 72, "the control points and 8 bytes: a million spline shapes hold 77 million");

inline namespace REVOLVE_ISA {

struct CurveHits {
  static constexpr int kMax = 6;  // F has degree 6
  int count = 0;
  double s[kMax];  // increasing
  double u[kMax];  // the part's parameter at each hit (unused for straight parts)
  bool solved = false;
};

namespace curve_hits_internal {

// Safeguarded Newton in [a, b] where eval(u, f, df) changes sign (negativeAtA: f < 0 at a): Newton
// steps that stay in the bracket and at least halve it, bisection otherwise (Press et al.'s rtsafe).
// Ends when the bracket or f is down to nothing, or when two Newton steps in a row predict the
// error left after the second below 2^-53 (u in [0, 1]: the parameter's own resolution): near a
// simple root each step is C times the previous one squared, so after a step d following d0 the
// error is about C d^2 = d^3 / d0^2, known without another evaluation. (Near a double root the
// steps shrink by a constant factor instead, the prediction stays large, and Newton continues.)
template <class Eval>
inline double safeguardedRoot(Eval&& eval, double a, double b, bool negativeAtA, double u) noexcept {
  double step = b - a, previous = step;
  bool wasNewton = false;
  for (int iteration = 0; iteration < 100; ++iteration) {
    double f, df;
    eval(u, f, df);
    if (f == 0.0) return u;
    ((f < 0.0) == negativeAtA ? a : b) = u;
    double next = u - f / df;
    const bool newton = next > a && next < b && std::abs(2.0 * f) <= std::abs(previous * df);
    if (!newton) next = 0.5 * (a + b);
    previous = step;
    step = next - u;
    u = next;
    if (b - a <= 0x1p-52 || std::abs(step) <= 0x1p-53) break;
    if (newton && wasNewton && std::abs(step) * step * step <= 0x1p-53 * previous * previous) break;
    wasNewton = newton;
  }
  return u;
}

// The parameter where a monotone cubic takes `target` (an end when target lies beyond it).
inline double monotoneParameter(const double c[4], double target) noexcept {
  const bool increasing = c[3] > c[0];
  if (increasing ? target <= c[0] : target >= c[0]) return 0.0;
  if (increasing ? target >= c[3] : target <= c[3]) return 1.0;
  const auto eval = [&](double u, double& f, double& df) {
    cubicWithDerivative(c, u, f, df);
    f -= target;
  };
  return safeguardedRoot(eval, 0.0, 1.0, increasing, std::clamp((target - c[0]) / (c[3] - c[0]), 0.0, 1.0));
}

// F on a cubic (controls r, z): F(u) = rho2At(planeS(z(u))) - r(u)^2, with s(u) beside it.
struct PartView {
  const MeridianRay& ray;
  double r[4], z[4];

  [[gnu::always_inline]] double at(double u, double& s) const noexcept {
    const double zu = cubicAt(z, u), ru = cubicAt(r, u);
    s = ray.planeS(zu);
    return ray.rho2At(s) - ru * ru;
  }
  void withDerivative(double u, double& f, double& df) const noexcept {
    double zu, dzu, ru, dru;
    cubicWithDerivative(z, u, zu, dzu);
    cubicWithDerivative(r, u, ru, dru);
    const double s = ray.planeS(zu);
    const double px = ray.ox + s * ray.dx, py = ray.oy + s * ray.dy;
    f = px * px + py * py - ru * ru;  // rho2At's expression
    df = 2.0 * ((px * ray.dx + py * ray.dy) * (dzu * ray.invDz) - ru * dru);
  }
};

// F's Bernstein coefficients over [0, 1] (degree 6), from the products of the cubics
// P(u) = (ox, oy) + s(u) (dx, dy) and r(u): F_k = sum over i + j = k of
// C(3, i) C(3, j) / C(6, k) (P_i . P_j - r_i r_j).
[[gnu::always_inline]] inline void coefficientsOf(const PartView& view, double b[7]) noexcept {
  const MeridianRay& ray = view.ray;
  double px[4], py[4];
  for (int i = 0; i < 4; ++i) {
    const double s = ray.planeS(view.z[i]);
    px[i] = ray.ox + s * ray.dx;
    py[i] = ray.oy + s * ray.dy;
  }
  const auto q = [&](int i, int j) { return px[i] * px[j] + py[i] * py[j] - view.r[i] * view.r[j]; };
  b[0] = q(0, 0);
  b[1] = q(0, 1);
  b[2] = (2.0 * q(0, 2) + 3.0 * q(1, 1)) / 5.0;
  b[3] = (q(0, 3) + 9.0 * q(1, 2)) / 10.0;
  b[4] = (2.0 * q(1, 3) + 3.0 * q(2, 2)) / 5.0;
  b[5] = q(2, 3);
  b[6] = q(3, 3);
}

// de Casteljau at 1/2: the coefficients of both halves.
inline void halveCoefficients(const double b[7], double left[7], double right[7]) noexcept {
  double t[7];
  for (int i = 0; i < 7; ++i) t[i] = b[i];
  left[0] = t[0];
  right[6] = t[6];
  for (int level = 1; level < 7; ++level) {
    for (int i = 0; i < 7 - level; ++i) t[i] = 0.5 * (t[i] + t[i + 1]);
    left[level] = t[0];
    right[6 - level] = t[6 - level];
  }
}

struct Interval {
  double b[7];
  double u0, u1, s0, s1;
  bool in0, in1;  // F < 0 at u0, u1
  int depth;
};

// Halving stops at this depth (2^-44 of the part): an interval still holding two or more sign
// changes there is a tangency within rounding, and counts as one root if its ends' signs differ.
inline constexpr int kMaxDepth = 44;
// And after this many halvings in all. In exact arithmetic a halving never adds sign changes
// (Bernstein subdivision diminishes variation), so isolating F's at most 6 roots takes at most
// 6 kMaxDepth; beyond that the coefficients' signs are rounding noise (a part far smaller than the
// rounding of rho^2 at the shape's scale), and the intervals left count one root each where their
// ends' signs differ, which keeps the parity.
inline constexpr int kMaxHalvings = 6 * kMaxDepth;

inline int signChanges(const Interval& interval) noexcept {
  int changes = 0;
  bool negative = interval.in0;
  for (int i = 1; i < 6; ++i) {
    if (interval.b[i] == 0.0) continue;
    const bool n = interval.b[i] < 0.0;
    changes += n != negative;
    negative = n;
  }
  return changes + (interval.in1 != negative);
}

// The ray's parameter at the part's point u: planeS(z(u)), unless z's rounding (8 u max |z_i|),
// magnified by 1 / dz, could move it by more than sTolerance: then a nearly horizontal ray, whose
// crossing of the height z(u) is ill-conditioned, is solved against the part's chord about u
// (2^-30 of the part either side, whose sagitta is below the coordinates' rounding) by Wang's kernel, which
// places the crossing by the radius instead; of that chord's roots, the one nearest planeS(z(u)).
// `span`: the part's parameter range the view covers (a restriction's is narrower), so that the
// chord is 2^-29 of the part whatever the view.
[[gnu::always_inline]] inline double rayParameterAt(const PartView& view, double u, double span, double lo, double hi,
                                                    double sTolerance) noexcept {
  double s;
  view.at(u, s);
  const double zMagnitude =
      std::max({std::abs(view.z[0]), std::abs(view.z[1]), std::abs(view.z[2]), std::abs(view.z[3])});
  if (!(8.0 * kUnitRoundoff * zMagnitude * std::abs(view.ray.invDz) > sTolerance)) return s;
  const double half = 0x1p-30 / span;
  const double u0 = std::max(0.0, u - half), u1 = std::min(1.0, u + half);
  const Point2 a{cubicAt(view.r, u0), cubicAt(view.z, u0)}, b{cubicAt(view.r, u1), cubicAt(view.z, u1)};
  const SegmentHits chord = segmentHits<false>(view.ray, a, b, lo, hi);
  double best = s;
  for (int i = 0; i < chord.count; ++i) {
    if (i == 0 || std::abs(chord.s[i] - s) < std::abs(best - s)) best = chord.s[i];
  }
  return best;
}

// The roots of F on a cubic (its u mapped to uFrom + t (uTo - uFrom)) with lo <= s <= hi, nearest first.
template <bool kFirstOnly>
inline void isolateRoots(const PartView& view, double lo, double hi, double uFrom, double uTo, double sTolerance,
                         CurveHits& hits) noexcept {
  Interval stack[kMaxDepth + 2];
  int top = 0;
  Interval& root = stack[top++];
  coefficientsOf(view, root.b);
  root.u0 = 0.0, root.u1 = 1.0;
  root.s0 = view.ray.planeS(view.z[0]), root.s1 = view.ray.planeS(view.z[3]);
  root.in0 = root.b[0] < 0.0, root.in1 = root.b[6] < 0.0;  // the vertex predicates' values
  root.depth = 0;
  const bool increasing = root.s1 > root.s0;  // s grows with u: nearer halves first
  const double sLow = std::min(root.s0, root.s1), sHigh = std::max(root.s0, root.s1);
  int halvings = 0;
  while (top > 0) {
    const Interval interval = stack[--top];
    if (std::max(interval.s0, interval.s1) < lo || std::min(interval.s0, interval.s1) > hi) continue;
    const int changes = signChanges(interval);
    if (changes == 0) continue;
    if (changes == 1 || interval.depth >= kMaxDepth || halvings >= kMaxHalvings) {
      if (interval.in0 == interval.in1) continue;  // a tangency within rounding
      // One root: start where F's control polygon crosses zero (it crosses once, and the curve
      // follows it), then safeguarded Newton.
      double start = 0.5 * (interval.u0 + interval.u1);
      for (int k = 0; k < 6; ++k) {
        const double p = interval.b[k], q = interval.b[k + 1];
        if ((p < 0.0) != (q < 0.0)) {
          const double t = (k + p / (p - q)) / 6.0;
          const double guess = interval.u0 + (interval.u1 - interval.u0) * t;
          if (guess > interval.u0 && guess < interval.u1) start = guess;
          break;
        }
      }
      const auto eval = [&](double u, double& f, double& df) { view.withDerivative(u, f, df); };
      const double u = safeguardedRoot(eval, interval.u0, interval.u1, interval.in0, start);
      const double s = std::clamp(rayParameterAt(view, u, uTo - uFrom, lo, hi, sTolerance), sLow, sHigh);
      if (s >= lo && s <= hi && hits.count < CurveHits::kMax) {
        hits.s[hits.count] = s;
        hits.u[hits.count++] = uFrom + u * (uTo - uFrom);
        if constexpr (kFirstOnly) return;
      }
      continue;
    }
    ++halvings;
    Interval left, right;
    halveCoefficients(interval.b, left.b, right.b);
    const double middle = 0.5 * (interval.u0 + interval.u1);
    double sMiddle;
    const bool inMiddle = view.at(middle, sMiddle) < 0.0;
    left.u0 = interval.u0, left.u1 = middle, left.s0 = interval.s0, left.s1 = sMiddle;
    left.in0 = interval.in0, left.in1 = inMiddle;
    right.u0 = middle, right.u1 = interval.u1, right.s0 = sMiddle, right.s1 = interval.s1;
    right.in0 = inMiddle, right.in1 = interval.in1;
    left.depth = right.depth = interval.depth + 1;
    // The stack pops the nearer half first.
    stack[top++] = increasing ? right : left;
    stack[top++] = increasing ? left : right;
  }
}

inline void addApexTouches(const MeridianRay& ray, const CurvePart& part, double low, double high, double lo, double hi,
                           CurveHits& hits) noexcept {
  SegmentHits touch;
  if (part.r[0] == 0.0) segment_hits_internal::addApexTouch(ray, part.z[0], low, high, lo, hi, touch);
  if (touch.count == 0 && part.r[3] == 0.0) {
    segment_hits_internal::addApexTouch(ray, part.z[3], low, high, lo, hi, touch);
    if (touch.count > 0) hits.u[0] = 1.0;
  } else if (touch.count > 0) {
    hits.u[0] = 0.0;
  }
  if (touch.count > 0) hits.s[0] = touch.s[0], hits.count = 1;
}

}  // namespace curve_hits_internal

// All hits of the ray with the part with lo <= s <= hi, in increasing order (kFirstOnly: the first).
// `sphereRadius`: the shape's bounding radius R, the scale of the conditioning threshold.
template <bool kFirstOnly = false>
inline CurveHits curveHits(const MeridianRay& ray, const CurvePart& part, double lo, double hi,
                           double sphereRadius) noexcept {
  using namespace curve_hits_internal;
  CurveHits hits;
  const Point2 p0{part.r[0], part.z[0]}, p3{part.r[3], part.z[3]};
  if (part.straight) {
    const SegmentHits segment = segmentHits<kFirstOnly>(ray, p0, p3, lo, hi);
    hits.count = segment.count;
    hits.solved = segment.solved;
    for (int i = 0; i < segment.count; ++i) hits.s[i] = segment.s[i], hits.u[i] = 0.0;
    return hits;
  }
  if (p0.r == 0.0 && p3.r == 0.0) return hits;  // on the axis throughout (r is monotone): no area

  double bracketLow = 0.0, bracketHigh = -1.0;
  if (!ray.inPlane) {
    const double s0 = ray.planeS(p0.z), s3 = ray.planeS(p3.z);
    bracketLow = std::max(std::min(s0, s3), lo);
    bracketHigh = std::min(std::max(s0, s3), hi);
    if (!(bracketLow <= bracketHigh)) return hits;
    hits.solved = true;
    const PartView view{
        ray, {part.r[0], part.r[1], part.r[2], part.r[3]}, {part.z[0], part.z[1], part.z[2], part.z[3]}};
    const double sTolerance = 0x1p-32 * sphereRadius;  // far below the float t the caller gets
    if (std::abs(s3 - s0) <= 0x1p8 * sphereRadius || (std::min(s0, s3) >= lo && std::max(s0, s3) <= hi)) {
      isolateRoots<kFirstOnly>(view, lo, hi, 0.0, 1.0, sTolerance, hits);
    } else {
      // A stretch far longer than the shape: restrict the part to the heights the ray has in [lo, hi],
      // widened so that the restriction's end heights, as evaluated, still lie beyond the ray's:
      // by the evaluation error of z (de Casteljau's three levels, within 8 u max |z_i|) over the
      // slope there, and by 2^-20 of the span. Roots found outside [lo, hi] are dropped.
      const double uLo = monotoneParameter(part.z, ray.zAt(lo)), uHi = monotoneParameter(part.z, ray.zAt(hi));
      const double span = std::abs(uHi - uLo);
      const double zError =
          8.0 * kUnitRoundoff *
          std::max({std::abs(part.z[0]), std::abs(part.z[1]), std::abs(part.z[2]), std::abs(part.z[3])});
      const double slope = std::abs(cubicDerivative(part.z, 0.5 * (uLo + uHi)));
      const double widen = 0x1p-20 * span + 0x1p-52 + (slope > 0.0 ? 4.0 * zError / slope : 1.0);
      const double ua = std::max(0.0, std::min(uLo, uHi) - widen);
      const double ub = std::min(1.0, std::max(uLo, uHi) + widen);
      if (ub - ua <= 0x1p-28) {
        // The chord of so short a restriction lies within the coordinates' rounding of it.
        const Point2 a{cubicAt(part.r, ua), cubicAt(part.z, ua)}, b{cubicAt(part.r, ub), cubicAt(part.z, ub)};
        const SegmentHits chord = segmentHits<kFirstOnly>(ray, a, b, lo, hi);
        const double er = b.r - a.r, ez = b.z - a.z, length2 = er * er + ez * ez;
        for (int i = 0; i < chord.count; ++i) {
          const double px = ray.ox + chord.s[i] * ray.dx, py = ray.oy + chord.s[i] * ray.dy;
          const double along =
              length2 > 0.0 ? ((std::sqrt(px * px + py * py) - a.r) * er + (ray.zAt(chord.s[i]) - a.z) * ez) / length2
                            : 0.0;
          hits.s[hits.count] = chord.s[i];
          hits.u[hits.count++] = ua + std::clamp(along, 0.0, 1.0) * (ub - ua);
        }
      } else {
        PartView restricted{ray, {}, {}};
        cubicRestricted(part.r, ua, ub, restricted.r);
        cubicRestricted(part.z, ua, ub, restricted.z);
        isolateRoots<kFirstOnly>(restricted, lo, hi, ua, ub, sTolerance, hits);
      }
    }
  } else {
    // The ray stays in the plane z = oz; the part owns the heights [zmin, zmax), as a segment does.
    bracketLow = lo;
    bracketHigh = hi;
    const double zMin = std::min(p0.z, p3.z), zMax = std::max(p0.z, p3.z);
    if (p0.z != p3.z && zMin <= ray.oz && ray.oz < zMax) {
      const double u = ray.oz == p0.z ? 0.0 : monotoneParameter(part.z, ray.oz);
      const double radius = u == 0.0 ? p0.r : cubicAt(part.r, u);
      const double R2 = radius * radius;
      const Quadratic g{ray.a * ray.a, 0.0, ray.cross * ray.cross - ray.a * R2};
      // As for segments: an end exactly on the circle (tnear or tfar) is a hit, entering or leaving.
      const double rho2Lo = ray.rho2At(lo), rho2Hi = ray.rho2At(hi);
      const Roots roots = bracketedRoots<kFirstOnly>(g, lo - ray.sAxis, hi - ray.sAxis, rho2Lo < R2, rho2Hi < R2,
                                                     EndsOnSurface{rho2Lo == R2, rho2Hi == R2});
      for (int i = 0; i < roots.count; ++i)
        hits.s[hits.count] = std::clamp(ray.sAxis + roots.x[i], lo, hi), hits.u[hits.count++] = u;
      hits.solved = true;
    }
  }
  if (hits.count == 0 && bracketLow <= bracketHigh) addApexTouches(ray, part, bracketLow, bracketHigh, lo, hi, hits);
  return hits;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
