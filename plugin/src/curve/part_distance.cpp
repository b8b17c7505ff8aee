#include "curve/part_distance.h"

#include "curve/cubic.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {
namespace {

// The parameter where a monotone cubic takes `target` (an end when it lies beyond), by bisection.
double parameterOf(const double c[4], double target) {
  const bool increasing = c[3] >= c[0];
  if (increasing ? target <= c[0] : target >= c[0]) return 0.0;
  if (increasing ? target >= c[3] : target <= c[3]) return 1.0;
  double a = 0.0, b = 1.0;
  for (int i = 0; i < 64 && b - a > 0x1p-53; ++i) {
    const double m = 0.5 * (a + b);
    ((cubicAt(c, m) < target) == increasing ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// The roots in (0, 1) of a degree-5 polynomial given by Bernstein coefficients: intervals halved
// until their coefficients change sign at most once (Descartes' rule), then bisected on the
// de Casteljau value. Up to five roots.
int quinticRoots(const double b[6], double out[5]) {
  struct Interval {
    double c[6];
    double u0, u1;
    int depth;
  };
  Interval stack[64];
  int top = 0, count = 0;
  stack[top++] = {{b[0], b[1], b[2], b[3], b[4], b[5]}, 0.0, 1.0, 0};
  const auto valueAt = [&](double u) {  // de Casteljau on the original coefficients
    double t[6];
    for (int i = 0; i < 6; ++i) t[i] = b[i];
    for (int level = 1; level < 6; ++level) {
      for (int i = 0; i < 6 - level; ++i) t[i] = (1.0 - u) * t[i] + u * t[i + 1];
    }
    return t[0];
  };
  while (top > 0 && count < 5) {
    const Interval in = stack[--top];
    int changes = 0;
    for (int i = 0, last = 0; i < 6; ++i) {
      const int sign = in.c[i] > 0 ? 1 : in.c[i] < 0 ? -1 : 0;
      if (sign == 0) continue;
      if (last != 0 && sign != last) ++changes;
      last = sign;
    }
    if (changes == 0) continue;
    if (changes == 1 || in.depth >= 48) {
      double a = in.u0, c = in.u1;
      const bool negativeAtA = valueAt(a) < 0.0;
      if ((valueAt(c) < 0.0) == negativeAtA && changes == 1) {
        // One sign change but equal end values' signs: a root exactly at an end (value 0); keep it.
        out[count++] = valueAt(a) == 0.0 ? a : c;
        continue;
      }
      for (int i = 0; i < 64 && c - a > 0x1p-53; ++i) {
        const double m = 0.5 * (a + c);
        ((valueAt(m) < 0.0) == negativeAtA ? a : c) = m;
      }
      out[count++] = 0.5 * (a + c);
      continue;
    }
    Interval left{{}, in.u0, 0.5 * (in.u0 + in.u1), in.depth + 1}, right{{}, left.u1, in.u1, in.depth + 1};
    double t[6];
    for (int i = 0; i < 6; ++i) t[i] = in.c[i];
    left.c[0] = t[0];
    right.c[5] = t[5];
    for (int level = 1; level < 6; ++level) {
      for (int i = 0; i < 6 - level; ++i) t[i] = 0.5 * (t[i] + t[i + 1]);
      left.c[level] = t[0];
      right.c[5 - level] = t[5 - level];
    }
    stack[top++] = right;
    stack[top++] = left;
  }
  return count;
}

}  // namespace

double rectSignedDistance(const MeridianRect& q, double r, double z) {
  const double dr = std::max(q.rLow - r, r - q.rHigh);
  const double dz = std::max(q.zLow - z, z - q.zHigh);
  if (dr <= 0 && dz <= 0) return std::max(dr, dz);
  return std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
}

PartMinimum partMinimum(const MeridianRect& q, const double r[4], const double z[4]) {
  PartMinimum best{rectSignedDistance(q, r[0], z[0]), r[0], z[0], 0.0};
  const auto consider = [&](double u) {
    const double pr = cubicAt(r, u), pz = cubicAt(z, u);
    const double value = rectSignedDistance(q, pr, pz);
    if (value < best.value) best = {value, pr, pz, u};
  };
  consider(1.0);

  // Inside: the depth min(r - rLow, rHigh - r, z - zLow, zHigh - z). Along the part each term is
  // monotone; `rising` gathers those that never decrease (constant ones too), `falling` the others.
  const bool rUp = r[3] >= r[0], zUp = z[3] >= z[0];
  const auto rising = [&](double pr, double pz) {
    return std::min(rUp ? pr - q.rLow : q.rHigh - pr, zUp ? pz - q.zLow : q.zHigh - pz);
  };
  const auto falling = [&](double pr, double pz) {
    return std::min(rUp ? q.rHigh - pr : pr - q.rLow, zUp ? q.zHigh - pz : pz - q.zLow);
  };
  const auto gap = [&](double u) {
    const double pr = cubicAt(r, u), pz = cubicAt(z, u);
    return rising(pr, pz) - falling(pr, pz);
  };
  if (gap(0.0) < 0.0 && gap(1.0) > 0.0) {
    double a = 0.0, b = 1.0;
    for (int i = 0; i < 64 && b - a > 0x1p-53; ++i) {
      const double m = 0.5 * (a + b);
      (gap(m) < 0.0 ? a : b) = m;
    }
    consider(a);
    consider(b);
  }
  if (best.value <= 0.0) return best;  // inside (or touching): nothing outside does better

  // Apart: the strip boundaries, and each corner's nearest points.
  for (const double target : {q.rLow, q.rHigh}) consider(parameterOf(r, target));
  for (const double target : {q.zLow, q.zHigh}) consider(parameterOf(z, target));
  const double corners[4][2] = {{q.rLow, q.zLow}, {q.rLow, q.zHigh}, {q.rHigh, q.zLow}, {q.rHigh, q.zHigh}};
  const int cornerCount = (q.rLow == q.rHigh && q.zLow == q.zHigh) ? 1 : 4;
  for (int k = 0; k < cornerCount; ++k) {
    // (c(u) - corner) . c'(u) / 3: the product of a cubic and a quadratic in the Bernstein basis,
    // g_m = sum over i + j = m of C(3, i) C(2, j) / C(5, m) a_i . d_j.
    double ar[4], az[4], dr[3], dz[3];
    for (int i = 0; i < 4; ++i) ar[i] = r[i] - corners[k][0], az[i] = z[i] - corners[k][1];
    for (int j = 0; j < 3; ++j) dr[j] = r[j + 1] - r[j], dz[j] = z[j + 1] - z[j];
    const auto p = [&](int i, int j) { return ar[i] * dr[j] + az[i] * dz[j]; };
    const double g[6] = {p(0, 0),
                         (2.0 * p(0, 1) + 3.0 * p(1, 0)) / 5.0,
                         (p(0, 2) + 6.0 * p(1, 1) + 3.0 * p(2, 0)) / 10.0,
                         (3.0 * p(1, 2) + 6.0 * p(2, 1) + p(3, 0)) / 10.0,
                         (3.0 * p(2, 2) + 2.0 * p(3, 1)) / 5.0,
                         p(3, 2)};
    double roots[5];
    for (int i = 0, n = quinticRoots(g, roots); i < n; ++i) consider(roots[i]);
  }
  return best;
}

}  // namespace revolve::detail
