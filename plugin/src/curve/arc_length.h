// Arc length of a cubic Bezier part by Gauss-Legendre quadrature of |c'(u)|, and v at a hit from a
// coarse table of it. A monotone part turns by less than a right angle (its tangent keeps to one
// quadrant), so |c'| is smooth on it and a few nodes integrate it to rounding.
#pragma once

#include "util/isa.h"

#include "curve/cubic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// The arc length from u = a to u = b (five-point rule, exact for |c'| of degree 9).
inline double arcLengthBetween(const double r[4], const double z[4], double a, double b) noexcept {
  constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891};
  const double half = 0.5 * (b - a), middle = 0.5 * (a + b);
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double u = middle + half * kNodes[i];
    const double dr = cubicDerivative(r, u), dz = cubicDerivative(z, u);
    sum += kWeights[i] * std::sqrt(dr * dr + dz * dz);  // coordinates within 2^+-60: no overflow or underflow
  }
  return half * sum;
}

// The arc length from u = 0 to u from a part's table of it at `steps` equal steps of [0, 1]
// (arc_table.h; `inner`: its entries at u = k / steps, k = 1 .. steps - 1, the one at 0 being 0):
// the step's entry plus the arc length from its start to u by one five-point rule. The table is
// made fine enough for that rule: within 2^-30 of the part's length.
inline double arcLengthFrom(const double* inner, std::uint32_t steps, const double r[4], const double z[4],
                            double u) noexcept {
  const double x = std::clamp(u, 0.0, 1.0) * steps;
  const std::uint32_t k = std::min(std::uint32_t(x), steps - 1);
  return (k == 0 ? 0.0 : inner[k - 1]) + arcLengthBetween(r, z, double(k) / steps, std::clamp(u, 0.0, 1.0));
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
