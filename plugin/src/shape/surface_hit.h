// From a kernel solution (s on the re-centred ray, segment k) to the caller's Hit.
#pragma once

#include "util/isa.h"

#include "curve/arc_record.h"
#include "kernel/meridian_ray.h"
#include "shape/shape_impl.h"
#include "util/azimuth.h"
#include "util/simd.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// The caller's t for s, rounded to float and kept within [tnear, tfar] (which rounding of the
// re-centring could otherwise leave by an ulp).
inline float callerT(const MeridianRay& ray, const Ray& caller, double s) noexcept {
  const auto t = static_cast<float>(ray.t0 + s / ray.tScale);
  return std::clamp(t, caller.tnear, caller.tfar);
}

// Which of a hit's attributes to compute (Geometry::Options::normal, ::uv): t, the point and the
// segment always; the normal and u, v only when asked for, zero otherwise. What is computed is the
// same bit for bit whatever else is (each attribute is its own chain of operations).
inline constexpr unsigned kNormalAttribute = 1, kUvAttribute = 2, kAllAttributes = 3;

// Segment k's frame, from what it is measured on: a polyline's own points, or the chord between a
// spline part's local knots; v from the profile's arc lengths (a spline shape's: the curve's length
// up to each part end). Each value is one chain of operations on the stored values, so every copy
// (and surfaceHitLanes) computes it bit for bit alike.
template <bool kCurve>
inline SegmentFrame segmentFrameOf(const detail::ShapeImpl& shape, std::uint32_t k) noexcept {
  double er, ez;
  if constexpr (kCurve) {
    const LocalPoints local = localPointsOf(shape);
    const Point2 a = local[k], b = local[k + 1];
    er = b.r - a.r, ez = b.z - a.z;
  } else {
    const Point2* p = shape.profile.points().data();
    er = p[k + 1].r - p[k].r, ez = p[k + 1].z - p[k].z;
  }
  const double* arc = shape.profile.arcLength().data();
  const double total = arc[shape.profile.segmentCount()];
  const double v0 = arc[k] / total, dv = (arc[k + 1] - arc[k]) / total;
  const double length2 = er * er + ez * ez;  // magnitudes within 2^+-60: no overflow, no underflow
  const double length = std::sqrt(length2);
  return {ez / length, -er / length, 1.0 / length2, v0, dv};
}

template <unsigned kAttributes = kAllAttributes, bool kCurve = false>
inline Hit surfaceHit(const detail::ShapeImpl& shape, const MeridianRay& ray, const Ray& caller, double s,
                      std::uint32_t k) noexcept {
  const double px = ray.ox + s * ray.dx, py = ray.oy + s * ray.dy, pz = ray.zAt(s);
  const LocalPoints local = localPointsOf(shape);
  const Point2 p0 = local[k], p1 = local[k + 1];

  Hit hit{};
  hit.t = callerT(ray, caller, s);
  hit.point = {float(px), float(py), float(pz + shape.frame.zCentre)};
  hit.segment = k;
  if constexpr (kAttributes == 0) return hit;
  const SegmentFrame frame = segmentFrameOf<kCurve>(shape, k);
  const auto [rho, cosPhi, sinPhi] = azimuthOf(px, py);
  if constexpr ((kAttributes & kNormalAttribute) != 0) {
    // + 0.0f turns -0 into +0, so that printed normals never read "-0".
    hit.normal = {float(frame.nr * cosPhi) + 0.0f, float(frame.nr * sinPhi) + 0.0f, float(frame.nz) + 0.0f};
  }
  if constexpr ((kAttributes & kUvAttribute) != 0) {
    hit.u = azimuthFraction(px, py);
    const double along = ((rho - p0.r) * (p1.r - p0.r) + (pz - p0.z) * (p1.z - p0.z)) * frame.invLength2;
    hit.v = float(frame.v0 + std::clamp(along, 0.0, 1.0) * frame.dv);
  }
  return hit;
}

// A hit on a spline shape's part k at parameter u. Straight parts are segments (surfaceHit);
// curved ones take their normal from the curve's tangent at u and v from its arc length up to u.
template <unsigned kAttributes = kAllAttributes>
inline Hit curveSurfaceHit(const detail::ShapeImpl& shape, const MeridianRay& ray, const Ray& caller, double s,
                           std::uint32_t k, double u) noexcept {
  const CurvePart& part = shape.parts[k];
  if (part.straight) return surfaceHit<kAttributes, true>(shape, ray, caller, s, k);
  const double px = ray.ox + s * ray.dx, py = ray.oy + s * ray.dy, pz = ray.zAt(s);
  Hit hit{};
  hit.t = callerT(ray, caller, s);
  hit.point = {float(px), float(py), float(pz + shape.frame.zCentre)};
  hit.segment = k;
  if constexpr ((kAttributes & kUvAttribute) != 0) {
    hit.u = azimuthFraction(px, py);
    const double* arc = shape.profile.arcLength().data();
    hit.v = float(arcRecordV(shape.curve->arcRecords.data() + part.arcRecord, part.arcSteps, part.r, part.z, u, arc[k],
                             arc[k + 1], arc[shape.profile.segmentCount()]));
  }
  if constexpr ((kAttributes & kNormalAttribute) == 0) return hit;
  const auto [rho, cosPhi, sinPhi] = azimuthOf(px, py);
  double tr = cubicDerivative(part.r, u), tz = cubicDerivative(part.z, u);
  if (tr == 0.0 && tz == 0.0) {
    // Only at an end with a repeated control point (validation refuses cusps): the tangent's limit
    // there is the next control point's direction, or the chord's.
    const int from = u <= 0.5 ? 0 : 1, to = u <= 0.5 ? 2 : 3;
    tr = part.r[to] - part.r[from], tz = part.z[to] - part.z[from];
    if (tr == 0.0 && tz == 0.0) tr = part.r[3] - part.r[0], tz = part.z[3] - part.z[0];
  }
  // A tangent below 2^-500 (next to a control point repeated within rounding; found by fuzzing)
  // would square to nothing: scaled by 2^600 first, exactly.
  if (!(std::max(std::abs(tr), std::abs(tz)) >= 0x1p-500)) tr *= 0x1p600, tz *= 0x1p600;
  const double inverse = 1.0 / std::sqrt(tr * tr + tz * tz);
  const double nr = tz * inverse, nz = -tr * inverse;  // right of the direction of travel
  hit.normal = {float(nr * cosPhi) + 0.0f, float(nr * sinPhi) + 0.0f, float(nz) + 0.0f};
  return hit;
}

// The hit of either kind of shape (u: the part's parameter, spline shapes only).
template <bool kCurve, unsigned kAttributes = kAllAttributes>
inline Hit leafSurfaceHit(const detail::ShapeImpl& shape, const MeridianRay& ray, const Ray& caller, double s,
                          std::uint32_t k, double u) noexcept {
  if constexpr (kCurve) {
    return curveSurfaceHit<kAttributes>(shape, ray, caller, s, k, u);
  } else {
    return surfaceHit<kAttributes>(shape, ray, caller, s, k);
  }
}

// kLanes hits at once, for packets: hit j is ray[j] at s[j] on segment[j], for a caller with
// [tnear[j], tfar[j]]. The same operations as surfaceHit lane by lane, so the results equal its bit
// for bit, except where a hit point's x^2 + y^2 is subnormal (within 1e-154 of the axis), where
// surfaceHit scales: surfaceHitLanes reports those lanes in its result, and the caller takes them
// through surfaceHit. Unused lanes repeat a used one.
struct HitLanes {
  const MeridianRay* ray[kLanes];
  double s[kLanes];
  std::uint32_t segment[kLanes];
  float tnear[kLanes], tfar[kLanes];
};
struct HitAttributes {
  float t[kLanes], nx[kLanes], ny[kLanes], nz[kLanes], u[kLanes], v[kLanes];
};

template <unsigned kAttributes = kAllAttributes>
inline unsigned surfaceHitLanes(const detail::ShapeImpl& shape, const HitLanes& in, HitAttributes& out) noexcept {
  // Gathered lane by lane: ray, local segment, the segment's own (global) rise, its arc lengths.
  alignas(32) double f[16][kLanes];
  const Point2* points = shape.profile.points().data();
  const double* arc = shape.profile.arcLength().data();
  const LocalPoints local = localPointsOf(shape);
  for (int lane = 0; lane < kLanes; ++lane) {
    const MeridianRay& ray = *in.ray[lane];
    const std::uint32_t k = in.segment[lane];
    const Point2 p0 = local[k], p1 = local[k + 1];
    const double values[16] = {ray.ox,     ray.oy,     ray.oz, ray.dx, ray.dy, ray.dz, ray.t0,
                               ray.tScale, in.s[lane], p0.r,   p0.z,   p1.r,   p1.z,   points[k + 1].z - points[k].z,
                               arc[k],     arc[k + 1]};
    for (int i = 0; i < 16; ++i) f[i][lane] = values[i];
  }
  const Lanes s = load(f[8]);
  storeFloats(out.t, load(f[6]) + s / load(f[7]));
  for (int lane = 0; lane < kLanes; ++lane) out.t[lane] = std::clamp(out.t[lane], in.tnear[lane], in.tfar[lane]);
  if constexpr (kAttributes == 0) return 0;
  const Lanes px = load(f[0]) + s * load(f[3]), py = load(f[1]) + s * load(f[4]), pz = load(f[2]) + s * load(f[5]);
  const Lanes rho2 = px * px + py * py;
  const unsigned scaled =
      bits(rho2 < splat(std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon()));
  const Lanes rho = sqrt(rho2);
  // segmentFrameOf's operations, lane by lane (r is the same in either frame).
  const Lanes er = load(f[11]) - load(f[9]), ez = load(f[13]);
  const Lanes length2 = er * er + ez * ez;
  if constexpr ((kAttributes & kNormalAttribute) != 0) {
    const Lanes cosPhi = px / rho, sinPhi = py / rho;
    const Lanes length = sqrt(length2);
    const Lanes nr = ez / length;
    storeFloats(out.nx, nr * cosPhi);
    storeFloats(out.ny, nr * sinPhi);
    storeFloats(out.nz, -er / length);
    for (int lane = 0; lane < kLanes; ++lane) out.nx[lane] += 0.0f, out.ny[lane] += 0.0f, out.nz[lane] += 0.0f;
  }
  if constexpr ((kAttributes & kUvAttribute) != 0) {
    azimuthFractions(px, py, out.u);
    const Lanes r0 = load(f[9]), z0 = load(f[10]);
    const Lanes along = ((rho - r0) * (load(f[11]) - r0) + (pz - z0) * (load(f[12]) - z0)) * (splat(1.0) / length2);
    const Lanes total = splat(arc[shape.profile.segmentCount()]), arc0 = load(f[14]);
    const Lanes v0 = arc0 / total, dv = (load(f[15]) - arc0) / total;
    storeFloats(out.v, v0 + minOf(maxOf(along, splat(0.0)), splat(1.0)) * dv);
  }
  return scaled;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
