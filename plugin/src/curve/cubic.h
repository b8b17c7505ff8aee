// Cubic Bezier arithmetic in one coordinate: evaluation, derivative, restriction to a sub-interval,
// and the parameters where the derivative changes sign. Everything works on the Bernstein
// coefficients (control values) with de Casteljau's scheme, which is exact at u = 0 and u = 1 (it
// returns the end control values themselves) and, for derivatives, on the control differences, so
// that a derivative that vanishes at an end (a repeated control point) keeps its relative accuracy
// next to it.
#pragma once

#include "util/isa.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// How far cubicAt(c, u) may lie from the exact c(u), as a multiple of max |c_i|: each of de
// Casteljau's three levels of convex combinations v a + u b rounds two products and their sum (2u
// relative to max |c_i|) and uses v = 1 - u rounded (u more), so 9u in all; 16u = 2^-49 leaves room
// for the second-order terms. Two evaluated points closer than twice this cannot be told apart.
inline constexpr double kCubicAtError = 0x1p-49;

// c(u) for control values c[0..3].
inline double cubicAt(const double c[4], double u) noexcept {
  const double v = 1.0 - u;
  const double a = v * c[0] + u * c[1], b = v * c[1] + u * c[2], d = v * c[2] + u * c[3];
  const double e = v * a + u * b, f = v * b + u * d;
  return v * e + u * f;
}

// c'(u).
inline double cubicDerivative(const double c[4], double u) noexcept {
  const double v = 1.0 - u;
  const double d0 = c[1] - c[0], d1 = c[2] - c[1], d2 = c[3] - c[2];
  const double a = v * d0 + u * d1, b = v * d1 + u * d2;
  return 3.0 * (v * a + u * b);
}

// c and c' together (the leaves' Newton steps need both).
inline void cubicWithDerivative(const double c[4], double u, double& value, double& derivative) noexcept {
  const double v = 1.0 - u;
  const double a = v * c[0] + u * c[1], b = v * c[1] + u * c[2], d = v * c[2] + u * c[3];
  const double e = v * a + u * b, f = v * b + u * d;
  value = v * e + u * f;
  derivative = 3.0 * (f - e);
}

// The control values of c restricted to [u0, u1], reparametrised to [0, 1]: the blossom
// c(u0, u0, u0), c(u0, u0, u1), c(u0, u1, u1), c(u1, u1, u1). Exact at the ends of [0, 1].
[[gnu::always_inline]] inline void cubicRestricted(const double c[4], double u0, double u1, double out[4]) noexcept {
  const auto blossom = [&](double a, double b, double d) {
    const double va = 1.0 - a, vb = 1.0 - b, vd = 1.0 - d;
    const double x0 = va * c[0] + a * c[1], x1 = va * c[1] + a * c[2], x2 = va * c[2] + a * c[3];
    const double y0 = vb * x0 + b * x1, y1 = vb * x1 + b * x2;
    return vd * y0 + d * y1;
  };
  out[0] = blossom(u0, u0, u0);
  out[1] = blossom(u0, u0, u1);
  out[2] = blossom(u0, u1, u1);
  out[3] = blossom(u1, u1, u1);
}

// The parameters in (0, 1) where c' changes sign (at most two, increasing): the simple roots of
// the quadratic c'(u) / 3 = d0 (1 - u)^2 + 2 d1 u (1 - u) + d2 u^2 in power form, solved without
// cancellation. A double root (c' touching zero) is no change of sign and is left out. The
// differences are first scaled by a power of two to a largest magnitude in [0.5, 1): the roots do
// not depend on the scale, a power of two changes no bit of them, and without it the discriminant's
// squares of differences near 1e-160 or below underflow to zero and lose the roots (a control
// polygon of r within 1e-230 of the axis dipped below it unseen).
inline int derivativeSignChanges(const double c[4], double out[2]) noexcept {
  double d0 = c[1] - c[0], d1 = c[2] - c[1], d2 = c[3] - c[2];
  const double largest = std::max({std::abs(d0), std::abs(d1), std::abs(d2)});
  if (largest > 0.0 && largest < HUGE_VAL) {
    int exponent;
    std::frexp(largest, &exponent);
    d0 = std::ldexp(d0, -exponent), d1 = std::ldexp(d1, -exponent), d2 = std::ldexp(d2, -exponent);
  }
  const double a = d0 - 2.0 * d1 + d2, b = 2.0 * (d1 - d0), k = d0;  // a u^2 + b u + k
  int count = 0;
  const auto keep = [&](double u) {
    if (u > 0.0 && u < 1.0) out[count++] = u;
  };
  if (a == 0.0) {
    if (b != 0.0) keep(-k / b);
    return count;
  }
  const double disc = b * b - 4.0 * a * k;
  if (!(disc > 0.0)) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double x = q / a, y = q != 0.0 ? k / q : x;
  if (x > y) std::swap(x, y);
  keep(x);
  if (y != x) keep(y);
  return count;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
