// A point's distance from the z axis and the direction of its meridian plane.
#pragma once

#include <cmath>
#include <limits>

namespace revolve::detail {

struct Azimuth {
  double rho;             // sqrt(x^2 + y^2)
  double cosPhi, sinPhi;  // (x, y) / rho, a unit vector; (1, 0) on the axis, where any azimuth will do
};

inline Azimuth azimuthOf(double x, double y) noexcept {
  double rho = std::sqrt(x * x + y * y);
  // Below DBL_MIN / eps the sum of squares is subnormal or close to it and has lost relative
  // precision (a profile may reach within 1e-161 of the axis), so (x, y) / rho would no longer be
  // unit. hypot scales instead of squaring; it is slower, so only there.
  if (rho * rho < std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon()) {
    rho = std::hypot(x, y);
  }
  if (!(rho > 0.0)) return {0.0, 1.0, 0.0};
  return {rho, x / rho, y / rho};
}

}  // namespace revolve::detail
