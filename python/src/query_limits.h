// The rays and query points RaycastingScene accepts, checked one by one before any reaches Embree
// (Embree's own checks abort the process): the ranges of platform/geometry/ray_limits.h, within which
// a ray stays inside Embree's contract in the world and inside every placed shape.
#pragma once

#include "geometry/ray_limits.h"

#include <cmath>
#include <string>

namespace revolve::python {

// Origins (and query points) within 4 * 2^40 per coordinate; directions within 2^40 per
// component, finite and not zero; ray_limits.h shows such rays stay within Embree's range
// through any placement add_revolution accepts.
inline constexpr double kMaxOrigin = app::kMaxRayOrigin;
inline constexpr double kMaxDirection = app::kMaxWorldCoordinate;

inline bool pointAccepted(const float* p) noexcept {
  const auto within = [](float x) { return std::abs(x) <= float(kMaxOrigin); };  // false for NaN
  return within(p[0]) && within(p[1]) && within(p[2]);
}

// r: ox, oy, oz, dx, dy, dz.
inline bool rayAccepted(const float* r) noexcept {
  const auto within = [](float x) { return std::abs(x) <= float(kMaxDirection); };
  return pointAccepted(r) && within(r[3]) && within(r[4]) && within(r[5]) && (r[3] != 0 || r[4] != 0 || r[5] != 0);
}

// Why a point or ray is refused (the value and the rule), for the message; empty when accepted.
std::string pointFault(const float* p);
std::string rayFault(const float* r);

}  // namespace revolve::python
