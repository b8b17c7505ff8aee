// From a kernel solution (s on the re-centred ray, segment k) to the caller's Hit.
#pragma once

#include "util/isa.h"

#include "kernel/meridian_ray.h"
#include "shape_impl.h"
#include "util/azimuth.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// The caller's t for s, rounded to float and kept within [tnear, tfar] (which rounding of the
// re-centring could otherwise leave by an ulp).
inline float callerT(const MeridianRay& ray, const Ray& caller, double s) noexcept {
  const auto t = static_cast<float>(ray.t0 + s / ray.tScale);
  return std::clamp(t, caller.tnear, caller.tfar);
}

inline Hit surfaceHit(const Shape::Impl& shape, const MeridianRay& ray, const Ray& caller, double s,
                      std::uint32_t k) noexcept {
  const double px = ray.ox + s * ray.dx, py = ray.oy + s * ray.dy, pz = ray.zAt(s);
  const Point2 p0 = shape.local[k], p1 = shape.local[k + 1];
  const SegmentFrame& frame = shape.segments[k];
  const auto [rho, cosPhi, sinPhi] = azimuthOf(px, py);

  Hit hit;
  hit.t = callerT(ray, caller, s);
  hit.point = {float(px), float(py), float(pz + shape.frame.zCentre)};
  // + 0.0f turns -0 into +0, so that printed normals never read "-0".
  hit.normal = {float(frame.nr * cosPhi) + 0.0f, float(frame.nr * sinPhi) + 0.0f, float(frame.nz) + 0.0f};
  hit.u = azimuthFraction(px, py);
  const double along = ((rho - p0.r) * (p1.r - p0.r) + (pz - p0.z) * (p1.z - p0.z)) * frame.invLength2;
  hit.v = float(frame.v0 + std::clamp(along, 0.0, 1.0) * frame.dv);
  hit.segment = k;
  return hit;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
