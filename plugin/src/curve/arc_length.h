// Arc length of a cubic Bezier part by Gauss-Legendre quadrature of |c'(u)|. A monotone part turns
// by less than a right angle (its tangent keeps to one quadrant), so |c'| is smooth on it and a
// few nodes integrate it to rounding.
#pragma once

#include "util/isa.h"

#include "curve/cubic.h"

#include <cmath>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// The arc length from u = 0 to u = to (five-point rule, exact for |c'| of degree 9).
inline double arcLengthTo(const double r[4], const double z[4], double to) noexcept {
  constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891};
  const double half = 0.5 * to;
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double u = half * (1.0 + kNodes[i]);
    const double dr = cubicDerivative(r, u), dz = cubicDerivative(z, u);
    sum += kWeights[i] * std::sqrt(dr * dr + dz * dz);  // coordinates within 2^+-60: no overflow or underflow
  }
  return half * sum;
}

// The whole part's length: the five-point rule on each of 16 equal subintervals, for the
// normalisation of v (built once).
inline double arcLength(const double r[4], const double z[4]) noexcept {
  constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891};
  constexpr int kParts = 16;
  double total = 0.0;
  for (int p = 0; p < kParts; ++p) {
    const double half = 0.5 / kParts, middle = (p + 0.5) / kParts;
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
      const double u = middle + half * kNodes[i];
      sum += kWeights[i] * std::hypot(cubicDerivative(r, u), cubicDerivative(z, u));
    }
    total += half * sum;
  }
  return total;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
