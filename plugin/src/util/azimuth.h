// A point's distance from the z axis and the direction of its meridian plane.
#pragma once

#include "util/isa.h"
#include "util/simd.h"

#include <emmintrin.h>

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

// u = atan2(y, x) / 2 pi in [0, 1), the hit's surface parameter, to float precision.
//
// libm's atan2 cost a fifth of a ray at 16 points (perf): 120 cycles of latency on the hit's
// critical path, in a call the rest of the attributes cannot overlap. Here: one division to the
// first octant, atan(a) = a P(a^2) on [0, 1] with P of degree 10 (largest relative error 3.7e-10,
// fitted by scripts/fit_atan_polynomial.py), evaluated by Estrin's scheme, and the octant undone
// by selects on comparison masks: the quadrant of a random hit is a coin toss that a branch would
// mispredict half the time (1.2 mispredictions a hit, simulated by cachegrind). u is then within
// 2^-31 relative (or 6e-11 absolute) of the exact value, far inside half a float ulp: the float u
// is the correctly rounded one except when the exact value lies that close to a rounding boundary,
// and then one ulp off. On the axis (x = y = 0) u = 0.
namespace azimuth_internal {
inline constexpr double c0 = 0.999999999628638, c1 = -0.3333332393819627, c2 = 0.1999960469924586,
                        c3 = -0.1427916025220038, c4 = 0.11054504604737364, c5 = -0.08798783337292032,
                        c6 = 0.06716131221745177, c7 = -0.04435780917567998, c8 = 0.022274608772727314,
                        c9 = -0.00719949830984707, c10 = 0.0010911327931163242;
}  // namespace azimuth_internal

[[gnu::always_inline]] inline float azimuthFraction(double x, double y) noexcept {
  using namespace azimuth_internal;
  const __m128d zero = _mm_setzero_pd();
  const __m128d vx = _mm_set_sd(x), vy = _mm_set_sd(y);
  const __m128d signBit = _mm_set_sd(-0.0);
  const __m128d ax = _mm_andnot_pd(signBit, vx), ay = _mm_andnot_pd(signBit, vy);
  const __m128d steep = _mm_cmplt_sd(ax, ay);  // all ones where |y| > |x|
  const double big = _mm_cvtsd_f64(_mm_max_sd(ax, ay)), small = _mm_cvtsd_f64(_mm_min_sd(ax, ay));
  const double a = big > 0.0 ? small / big : 0.0;  // (0, 0) is the axis, a rare and predictable case
  const double s = a * a, s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
  const double p =
      (c0 + c1 * s) + s2 * (c2 + c3 * s) + s4 * ((c4 + c5 * s) + s2 * (c6 + c7 * s)) + s8 * ((c8 + c9 * s) + s2 * c10);
  // phi in [0, pi / 4]; then pi / 2 - phi when steep, pi - phi when x < 0, -phi when y < 0.
  const auto select = [](__m128d mask, __m128d ifSet, __m128d otherwise) {
    return _mm_or_pd(_mm_and_pd(mask, ifSet), _mm_andnot_pd(mask, otherwise));
  };
  __m128d phi = _mm_set_sd(a * p);
  phi = select(steep, _mm_sub_sd(_mm_set_sd(1.5707963267948966), phi), phi);
  phi = select(_mm_cmplt_sd(vx, zero), _mm_sub_sd(_mm_set_sd(3.141592653589793), phi), phi);
  phi = select(_mm_cmplt_sd(vy, zero), _mm_xor_pd(phi, signBit), phi);
  const __m128d u = _mm_mul_sd(phi, _mm_set_sd(0.5 / 3.141592653589793));
  const double wrapped = _mm_cvtsd_f64(_mm_add_sd(u, _mm_and_pd(_mm_cmplt_sd(u, zero), _mm_set_sd(1.0))));
  const auto f = static_cast<float>(wrapped);
  return f < 1.0f ? f : 0.0f;  // phi just below 2 pi rounds to 1: the same azimuth as 0
}

// azimuthFraction of kLanes points at once, the same operations lane by lane: bit for bit equal.
inline void azimuthFractions(Lanes x, Lanes y, float* u) noexcept {
  using namespace azimuth_internal;
  const Lanes zero = splat(0.0);
  const Lanes ax = abs(x), ay = abs(y);
  const LaneMask steep = ax < ay;
  const Lanes big = max(ax, ay), small = min(ax, ay);  // maxsd / minsd, as the scalar version
  const Lanes a = select(zero < big, small / big, zero);
  const Lanes s = a * a, s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
  const Lanes p = (splat(c0) + splat(c1) * s) + s2 * (splat(c2) + splat(c3) * s) +
                  s4 * ((splat(c4) + splat(c5) * s) + s2 * (splat(c6) + splat(c7) * s)) +
                  s8 * ((splat(c8) + splat(c9) * s) + s2 * splat(c10));
  Lanes phi = a * p;
  phi = select(steep, splat(1.5707963267948966) - phi, phi);
  phi = select(x < zero, splat(3.141592653589793) - phi, phi);
  phi = select(y < zero, -phi, phi);
  const Lanes fraction = phi * splat(0.5 / 3.141592653589793);
  storeFloats(u, fraction + onlyWhere(fraction < zero, splat(1.0)));
  for (int lane = 0; lane < kLanes; ++lane) u[lane] = u[lane] < 1.0f ? u[lane] : 0.0f;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
