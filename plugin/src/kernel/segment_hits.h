// Wang's intersection: a ray against one profile segment revolved, i.e. a truncated cone
// r = r0 + (z - z0) (r1 - r0) / (z1 - z0), or an annulus when the segment is horizontal.
//
// Watertightness. A non-horizontal segment owns the slab between the horizontal planes of its end
// points. Within it, the cone's implicit function
//     g(s) = ez^2 rho(s)^2 - L(s)^2,  L(s) = r0 ez + (z(s) - z0) er   (= ez * radius of the cone at z(s))
// is negative exactly where the ray is inside the cone, and because the cone's radius is >= 0 in
// the slab, g's roots there are the real nappe's (the mirror nappe lies outside the slab). Whether
// the ray is inside at a slab end that is a vertex plane is decided by one shared predicate,
//     rho^2(plane) < r_vertex^2,
// evaluated with the same expression by both segments meeting at that vertex (and by the annulus
// of a horizontal segment, whose hit is the XOR of its two vertex predicates). So along the ray the
// inside/outside state is handed from segment to segment without ever being computed twice, the
// number of hits each segment reports has the parity its end signs dictate, and a ray leaving a
// closed profile's solid must be reported hitting some segment: no leaks, by construction rather
// than by tolerance. Root values are only clamped into their sign-bracketed intervals.
//
// Accuracy. The quadratic is expanded about the middle of the ray's stretch in the slab, so its
// coefficients are of the size of the segment's neighbourhood (not of distances to the ray's
// origin): a nearly horizontal segment keeps its roots well conditioned. When the discriminant is
// lost to cancellation (near tangency), g is expanded again about its extremum, where the roots are.
#pragma once

#include "util/isa.h"

#include "kernel/bracketed_roots.h"
#include "kernel/meridian_ray.h"

#include <revolve/core.h>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

struct SegmentHits {
  int count = 0;
  double s[2];          // increasing
  bool solved = false;  // whether a quadratic was set up (the ray met the segment's slab)
};

namespace segment_hits_internal {

// A ray through an apex (a vertex on the axis) touches the surface there even when it is outside
// on both sides: a double root that rounding may turn either way, so the sign brackets cannot be
// relied on to see it. Count it as a hit when the point of [sLow, sHigh] (the segment's bracket)
// nearest the apex lies within lineSlack (the line's distance from the caller's float ray) plus
// this test's own rounding (4 u R) of the apex. Only called when the brackets found no root: a ray
// that enters the cone through its apex has its root there already.
//
// Where the bracket ends at the apex's plane, that end is where this double-precision line crosses
// the plane, which is not where the caller's ray crosses it: moving the line sideways by the
// tolerance moves the crossing along it by up to tolerance / |dz|, plus the crossing's own
// rounding (8 u |zApex - oz| |1 / dz|). The bracket is widened by that much (within [lo, hi]), or a
// ray nearly level with the apex, passing through it exactly, would be clamped to a point of the
// line up to tolerance / |dz| from the apex and missed (half of such rays rising 1 in 1,000 were).
// The widening stays far inside the searches' own margins on slab entries (2^-21 R |1 / dz| in
// the float filter), so a touch still lies after the entry of every tree node holding the
// segment, as their pruning assumes.
inline void addApexTouch(const MeridianRay& ray, double zApex, double sLow, double sHigh, double lo, double hi,
                         SegmentHits& hits) noexcept {
  const double ax = -ray.ox, ay = -ray.oy, az = zApex - ray.oz;  // apex - origin
  const double tolerance = ray.lineSlack + 4.0 * kUnitRoundoff * (std::abs(ax) + std::abs(ay) + std::abs(az));
  const double widen = (tolerance + 8.0 * kUnitRoundoff * std::abs(az)) * std::abs(ray.invDz);
  const double s =
      std::clamp(ax * ray.dx + ay * ray.dy + az * ray.dz, std::max(sLow - widen, lo), std::min(sHigh + widen, hi));
  const double px = ray.ox + s * ray.dx, py = ray.oy + s * ray.dy, pz = ray.zAt(s) - zApex;
  if (px * px + py * py + pz * pz <= tolerance * tolerance) hits.s[hits.count++] = s;
}

// Where the ray is at s against the cone, for an interval end that is not a vertex plane: tnear,
// tfar or the exit from the bounding sphere. Evaluated as the sign of ez * (rho - radius), whose
// error stays proportional to the segment's length however flat the segment is. Positive outside,
// negative inside, zero exactly on the surface: such an end is a hit itself (tnear <= t <= tfar is
// inclusive at both ends), which bracketedRoots reports whichever way the ray crosses there.
[[gnu::always_inline]] inline double outwardAt(const MeridianRay& ray, double s, Point2 p0, double er,
                                               double ez) noexcept {
  const double rho = std::sqrt(ray.rho2At(s));
  const double L = p0.r * ez + (ray.zAt(s) - p0.z) * er;
  return ez > 0.0 ? ez * rho - L : L - ez * rho;
}

// Whether g (expanded about m) vanishes within its rounding: a ray along a generator of the cone
// (in a meridian plane, through the apex, at the cone's slope), where g is identically zero and the
// computed coefficients are noise whose signs would place roots anywhere in the bracket. Each
// coefficient is a difference of products of the terms below, computed with at most 6 roundings
// from quantities themselves within 3 roundings of their terms (gamma_9 < 10 u of the terms'
// magnitudes): 32 u bounds it with room. A ray parallel to a generator a few u R away is then taken
// as running along it too, which moves its hit by no more than that distance.
inline bool alongSurface(const MeridianRay& ray, const Quadratic& g, double m, Point2 p0, double er,
                         double ez) noexcept {
  const double ez2 = ez * ez;
  if (!(std::abs(g.A) <= 32.0 * kUnitRoundoff * (ez2 * ray.a + er * er * ray.dz * ray.dz)))
    return false;  // the usual case
  const double px = ray.ox + m * ray.dx, py = ray.oy + m * ray.dy;
  const double bTerms = std::abs(px * ray.dx) + std::abs(py * ray.dy);
  const double lTerms = std::abs(p0.r * ez) + std::abs((ray.zAt(m) - p0.z) * er) + std::abs(ray.zAt(m) * er);
  const double magnitudeB = ez2 * bTerms + std::abs(er * ray.dz) * lTerms;
  const double magnitudeC = ez2 * (px * px + py * py) + lTerms * lTerms;
  return std::abs(g.B) <= 32.0 * kUnitRoundoff * magnitudeB && std::abs(g.C) <= 32.0 * kUnitRoundoff * magnitudeC;
}

}  // namespace segment_hits_internal

// All hits of the ray with segment p0 -> p1 (local frame) with lo <= s <= hi, in increasing order;
// with kFirstOnly only the first of them (the same value: only the second root's work is skipped).
template <bool kFirstOnly = false>
inline SegmentHits segmentHits(const MeridianRay& ray, Point2 p0, Point2 p1, double lo, double hi) noexcept {
  using namespace segment_hits_internal;
  SegmentHits hits;
  if (p0.r == 0.0 && p1.r == 0.0) return hits;  // a segment on the axis sweeps no area
  const double er = p1.r - p0.r, ez = p1.z - p0.z;

  double bracketLow = 0.0, bracketHigh = -1.0;  // the ray's stretch this segment owns; empty if none
  if (!ray.inPlane) {
    const double s0 = ray.planeS(p0.z);
    if (ez == 0.0) {
      // Annulus (or disc): hit where the ray crosses its plane between the two vertex circles.
      if (s0 >= lo && s0 <= hi) {
        const double rho2 = ray.rho2At(s0);
        if ((rho2 < p0.r * p0.r) != (rho2 < p1.r * p1.r)) hits.s[hits.count++] = s0;
      }
      return hits;
    }
    const double s1 = ray.planeS(p1.z);
    const bool p0First = s0 <= s1;
    const double sEnter = p0First ? s0 : s1, sLeave = p0First ? s1 : s0;
    const double rEnter = p0First ? p0.r : p1.r, rLeave = p0First ? p1.r : p0.r;
    bracketLow = std::max(sEnter, lo);
    bracketHigh = std::min(sLeave, hi);
    if (bracketLow <= bracketHigh) {
      const double x0 = bracketLow, x1 = bracketHigh;
      // The end signs: at a vertex plane the predicate the neighbouring segment shares, elsewhere
      // the cone's own sign, with exactly-on-the-surface kept apart.
      const double outward0 = sEnter >= lo ? 1.0 : outwardAt(ray, x0, p0, er, ez);
      const double outward1 = sLeave <= hi ? 1.0 : outwardAt(ray, x1, p0, er, ez);
      const bool inside0 = sEnter >= lo ? ray.rho2At(sEnter) < rEnter * rEnter : outward0 < 0.0;
      const bool inside1 = sLeave <= hi ? ray.rho2At(sLeave) < rLeave * rLeave : outward1 < 0.0;
      const EndsOnSurface on{outward0 == 0.0, outward1 == 0.0};
      // Expand g about the middle m of [x0, x1]: g(m + x) = A x^2 + 2 B x + C.
      const auto expandAbout = [&](double m) {
        const double px = ray.ox + m * ray.dx, py = ray.oy + m * ray.dy;
        const double bm = px * ray.dx + py * ray.dy;
        const double cm = px * px + py * py;
        const double Lm = p0.r * ez + (ray.zAt(m) - p0.z) * er;
        const double ez2 = ez * ez;
        return Quadratic{ez2 * ray.a - er * er * ray.dz * ray.dz, ez2 * bm - er * ray.dz * Lm, ez2 * cm - Lm * Lm};
      };
      double m = 0.5 * (x0 + x1);
      Quadratic g = expandAbout(m);
      // A near-tangent ray (or one through a sliver of the cone near its apex) has a discriminant
      // lost to cancellation: the roots sit near g's extremum, far from m, below the rounding of
      // coefficients taken at m. Expanding again about the extremum measures g there with local
      // magnitudes. Always valid (the end signs, hence the parity, do not change); worth its cost
      // only when D has lost at least 20 bits, |D| < 2^-20 (B^2 + |A C|).
      if (g.A != 0.0 && std::abs(g.B * g.B - g.A * g.C) < 0x1p-20 * (g.B * g.B + std::abs(g.A * g.C))) {
        m = std::clamp(m - g.B / g.A, x0, x1);
        g = expandAbout(m);
      }
      hits.solved = true;
      if (alongSurface(ray, g, m, p0, er, ez)) {
        // Every point of [x0, x1] lies on the surface within rounding: the first is the hit, and
        // the last too when the end signs agree, so that the parity they dictate holds.
        hits.s[hits.count++] = x0;
        if (!kFirstOnly && inside0 == inside1 && x1 > x0) hits.s[hits.count++] = x1;
        return hits;
      }
      const Roots roots = bracketedRoots<kFirstOnly>(g, x0 - m, x1 - m, inside0, inside1, on);
      // Clamped again after adding m back, which rounds: a root must not leave its segment's stretch.
      for (int i = 0; i < roots.count; ++i) hits.s[hits.count++] = std::clamp(m + roots.x[i], x0, x1);
    }
  } else {
    // The ray stays in the plane z = oz, where the cone is a circle. A segment owns the heights
    // [zmin, zmax) — half-open, so that a vertex height belongs to exactly the segments that
    // continue upwards from it, and the circles seen at any height are the true cross-section.
    bracketLow = lo;
    bracketHigh = hi;
    const double zMin = std::min(p0.z, p1.z), zMax = std::max(p0.z, p1.z);
    if (ez != 0.0 && zMin <= ray.oz && ray.oz < zMax) {
      const double radius = ray.oz == p0.z ? p0.r : ray.oz == p1.z ? p1.r : p0.r + (ray.oz - p0.z) * (er / ez);
      const double R2 = radius * radius;
      // a * (rho^2 - radius^2) about the closest approach to the axis: a^2 x^2 + cross^2 - a radius^2.
      const Quadratic g{ray.a * ray.a, 0.0, ray.cross * ray.cross - ray.a * R2};
      const double rho2Lo = ray.rho2At(lo), rho2Hi = ray.rho2At(hi);
      const Roots roots = bracketedRoots<kFirstOnly>(g, lo - ray.sAxis, hi - ray.sAxis, rho2Lo < R2, rho2Hi < R2,
                                                     EndsOnSurface{rho2Lo == R2, rho2Hi == R2});
      for (int i = 0; i < roots.count; ++i) hits.s[hits.count++] = std::clamp(ray.sAxis + roots.x[i], lo, hi);
      hits.solved = true;
    }
  }

  if (ez != 0.0 && hits.count == 0 && bracketLow <= bracketHigh) {
    if (p0.r == 0.0) addApexTouch(ray, p0.z, bracketLow, bracketHigh, lo, hi, hits);
    if (p1.r == 0.0 && hits.count == 0) addApexTouch(ray, p1.z, bracketLow, bracketHigh, lo, hi, hits);
  }
  return hits;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
