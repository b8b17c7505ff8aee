// A point's distance from the z axis and the direction of its meridian plane.
#pragma once

#include "util/isa.h"

#include <cmath>
#include <limits>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

struct Azimuth {
  double rho;             // sqrt(x^2 + y^2)
  double cosPhi, sinPhi;  // (x, y) / rho, a unit vector; (1, 0) on the axis, where any azimuth will do
};

inline Azimuth azimuthOf(double x, double y) noexcept {
  const double rho2 = x * x + y * y;
  // Below DBL_MIN / eps the sum of squares (and below DBL_MIN rho itself, or x and y) is subnormal
  // and has lost relative precision: a profile may reach within 1e-300 of the axis, and then
  // (x, y) / rho is no longer unit. Scaling by a power of two is exact and keeps the direction, so
  // the direction comes from (x, y) * 2^600, whose squares are normal (|x|, |y| < 2^-485 here).
  if (rho2 < std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon()) {
    constexpr double kUp = 0x1p600, kDown = 0x1p-600;
    const double sx = x * kUp, sy = y * kUp;
    const double scaled = std::sqrt(sx * sx + sy * sy);
    if (!(scaled > 0.0)) return {0.0, 1.0, 0.0};
    return {scaled * kDown, sx / scaled, sy / scaled};
  }
  const double rho = std::sqrt(rho2);
  return {rho, x / rho, y / rho};
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
