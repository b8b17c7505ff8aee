// Roots of a quadratic inside an interval, decided by signs rather than by the roots' values.
//
// g(x) = A x^2 + 2 B x + C on [x0, x1], with the caller's inside/outside verdicts at both ends
// (inside = g < 0). g is monotone on each side of its extremum e = -B/A, so the number of roots in
// [x0, x1] follows from the signs at x0, e (when e lies inside) and x1 alone; the root values only
// place the roots, each clamped into its bracket. The caller decides the end signs, and can thus
// make two neighbouring surfaces evaluate a shared boundary identically: whether a ray crosses a
// seam is then never decided twice (see segment_hits.h).
#pragma once

#include "util/isa.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

struct Quadratic {
  double A, B, C;  // g(x) = A x^2 + 2 B x + C
};

struct Roots {
  int count = 0;
  double x[2];
};

// Ends of the interval where the caller found the ray exactly on the surface (an end that is not
// shared with a neighbour: tnear or tfar). Such an end is a root: its inside/outside verdict is
// taken opposite to the side next to it within the interval, so that the sign rule finds a root
// there, whether the ray enters or leaves the solid at that point.
struct EndsOnSurface {
  bool at0 = false, at1 = false;
};

// Roots of g in [x0, x1] (x0 <= x1), in increasing order; with kFirstOnly, only the first of them
// (the nearest hit wants no more, and is spared the second root's division). A double root at the
// extremum (a tangent touch, discriminant exactly 0) is reported twice (once with kFirstOnly).
template <bool kFirstOnly = false>
inline Roots bracketedRoots(const Quadratic& g, double x0, double x1, bool inside0, bool inside1,
                            EndsOnSurface on = {}) noexcept {
  Roots roots;
  const auto push = [&](double x, double lo, double hi) { roots.x[roots.count++] = std::clamp(x, lo, hi); };

  if (g.A == 0.0) {
    if (on.at1) inside1 = !inside0;
    if (on.at0) inside0 = !inside1;
    if (inside0 == inside1) return roots;
    // Linear (or, when B == 0 too, constant: signs that differ then come from a ray running along
    // the surface, where every point of the interval lies on it within rounding).
    push(g.B != 0.0 ? -g.C / (2.0 * g.B) : x0, x0, x1);
    return roots;
  }

  const double D = g.B * g.B - g.A * g.C;
  const double sqrtD = std::sqrt(std::max(D, 0.0));  // D < 0 only when signs and D disagree by rounding
  // Stable pair: q has no cancellation; the roots are q / A and C / q, and which is the lower
  // follows from the signs of A and B (copysign gives q the sign opposite to B's sign bit).
  const double q = -(g.B + std::copysign(sqrtD, g.B));
  const double invA = 1.0 / g.A;
  const bool qOverAIsLow = !std::signbit(g.B) == (g.A > 0.0);
  // q == 0 only when B == 0 and D == 0: a double root at the extremum x = 0.
  const auto low = [&] { return q == 0.0 ? 0.0 : qOverAIsLow ? q * invA : g.C / q; };
  const auto high = [&] { return q == 0.0 ? 0.0 : qOverAIsLow ? g.C / q : q * invA; };
  const double e = -g.B * invA;
  // Inside at the extremum: for a convex g its minimum is -D/A <= 0 (a touch, D == 0, counts as
  // reaching the surface); for a concave g its maximum is -D/A < 0.
  const bool insideE = g.A > 0.0 ? D >= 0.0 : D < 0.0;
  const bool eInside = x0 < e && e < x1;
  if (on.at1) inside1 = !(eInside ? insideE : inside0);
  if (on.at0) inside0 = !(eInside ? insideE : inside1);

  if (eInside) {
    if (inside0 != insideE) {
      push(low(), x0, e);
      if constexpr (kFirstOnly) return roots;
    }
    if (insideE != inside1) push(high(), e, x1);
  } else if (inside0 != inside1) {
    // g is monotone on [x0, x1]: one root, the one on the interval's side of e.
    push(e <= x0 ? high() : low(), x0, x1);
  }
  return roots;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
