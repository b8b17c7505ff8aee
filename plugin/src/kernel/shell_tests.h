// Bounding-shell tests: does the ray pass through a shell within the stretch [s0, s1] of its path?
//
// Both tests are exact in real arithmetic (no over-approximation): along the ray, rho(s) and any
// f(s) = nr rho(s) + nz z(s) with nr >= 0 are convex, so their range over [s0, s1] is [min, max]
// with the max at an end and the min at an end or at the one stationary point; the ray meets the
// shell iff that range meets the shell's. Rounding is absorbed by margins that bound the
// evaluation errors (MeridianRay's slacks), so a shell never prunes a segment the ray hits.
#pragma once

#include "kernel/meridian_ray.h"
#include "util/isa.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {

// A band between two lines of the meridian plane: wLow <= nr rho + nz z <= wHigh, with (nr, nz) a
// unit normal and nr >= 0. A truncated-cone shell is such a band clipped to a z slab; a Ballard
// strip is two such bands.
struct Band {
  double nr, nz;
  double wLow, wHigh;
};

inline namespace REVOLVE_ISA {

// Annular cylinder rMin <= rho <= rMax over [s0, s1] (already clipped to the z slab), given
// rho^2 at both ends (q0, q1): the tree searches share these between neighbouring nodes.
[[gnu::always_inline]] inline bool cylinderShellPasses(const MeridianRay& ray, double rMin, double rMax, double s0,
                                                       double s1, double q0, double q1) noexcept {
  if (std::max(q0, q1) < rMin * rMin - ray.rho2Margin) return false;  // inside the inner cylinder throughout
  if (std::min(q0, q1) <= rMax * rMax + ray.rho2Margin) return true;
  // Both ends outside the outer cylinder: only the closest approach to the axis can reach in.
  // rho^2(s) = a (s - sAxis)^2 + beta (Lagrange's identity).
  return ray.a > 0.0 && s0 < ray.sAxis && ray.sAxis < s1 && ray.beta <= rMax * rMax + ray.rho2Margin;
}

[[gnu::always_inline]] inline bool cylinderShellPasses(const MeridianRay& ray, double rMin, double rMax, double s0,
                                                       double s1) noexcept {
  return cylinderShellPasses(ray, rMin, rMax, s0, s1, ray.rho2At(s0), ray.rho2At(s1));
}

// The band test over [s0, s1] given rho at both ends.
inline bool bandPasses(const MeridianRay& ray, const Band& band, double s0, double s1, double rho0,
                       double rho1) noexcept {
  const double f0 = band.nr * rho0 + band.nz * ray.zAt(s0), f1 = band.nr * rho1 + band.nz * ray.zAt(s1);
  if (std::max(f0, f1) < band.wLow - ray.bandMargin) return false;  // below the band throughout
  if (std::min(f0, f1) <= band.wHigh + ray.bandMargin) return true;
  // Both ends above the band: only the minimum between them can reach in.
  if (!(band.nr > 0.0 && ray.a > 0.0)) return false;  // f is linear along the ray: no interior minimum
  // f'(s) = nr a (s - sAxis) / rho + nz dz = 0 where a (s - sAxis) / rho = mu; |a (s - sAxis) / rho|
  // < sqrt(a), so a stationary point exists only for mu^2 < a.
  const double mu = -band.nz * ray.dz / band.nr;
  if (!(mu * mu < ray.a)) return false;
  const double rhoStationary = std::sqrt(ray.beta * ray.a / (ray.a - mu * mu));
  const double s = ray.sAxis + mu * rhoStationary * ray.invA;
  return s0 < s && s < s1 && band.nr * rhoStationary + band.nz * ray.zAt(s) <= band.wHigh + ray.bandMargin;
}

inline bool bandPasses(const MeridianRay& ray, const Band& band, double s0, double s1) noexcept {
  return bandPasses(ray, band, s0, s1, std::sqrt(ray.rho2At(s0)), std::sqrt(ray.rho2At(s1)));
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
