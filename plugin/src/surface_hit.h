// From a kernel solution (s on the re-centred ray, segment k) to the caller's Hit.
#pragma once

#include "util/isa.h"

#include "kernel/meridian_ray.h"
#include "shape_impl.h"
#include "util/azimuth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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
  const double er = p1.r - p0.r, ez = p1.z - p0.z;
  const double length = std::sqrt(er * er + ez * ez);  // magnitudes ~R: hypot's overflow guard is not needed
  const auto [rho, cosPhi, sinPhi] = azimuthOf(px, py);
  const double nr = ez / length, nz = -er / length;  // right of the direction of travel

  Hit hit;
  hit.t = callerT(ray, caller, s);
  hit.point = {float(px), float(py), float(pz + shape.frame.zCentre)};
  // + 0.0f turns -0 into +0, so that printed normals never read "-0".
  hit.normal = {float(nr * cosPhi) + 0.0f, float(nr * sinPhi) + 0.0f, float(nz) + 0.0f};
  const double u = std::atan2(py, px) * (0.5 / std::numbers::pi);
  hit.u = float(u < 0.0 ? u + 1.0 : u);
  if (hit.u >= 1.0f) hit.u = 0.0f;  // phi just below 2 pi rounds to 1: the same azimuth as 0
  const double along = std::clamp(((rho - p0.r) * er + (pz - p0.z) * ez) / (length * length), 0.0, 1.0);
  const std::span<const double> arc = shape.profile.arcLength();
  hit.v = float((arc[k] + along * (arc[k + 1] - arc[k])) / arc.back());
  hit.segment = k;
  return hit;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
