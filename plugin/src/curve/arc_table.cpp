#include "curve/arc_table.h"

#include "curve/arc_length.h"

#include <cmath>

namespace revolve::detail {
namespace {

double adaptiveLength(const double r[4], const double z[4], double a, double b, double whole, double tolerance,
                      int depth) {
  const double middle = 0.5 * (a + b);
  const double left = arcLengthBetween(r, z, a, middle), right = arcLengthBetween(r, z, middle, b);
  if (depth >= 30 || std::abs(left + right - whole) <= tolerance) return left + right;
  return adaptiveLength(r, z, a, middle, left, 0.5 * tolerance, depth + 1) +
         adaptiveLength(r, z, middle, b, right, 0.5 * tolerance, depth + 1);
}

double lengthBetween(const double r[4], const double z[4], double a, double b, double tolerance) {
  return adaptiveLength(r, z, a, b, arcLengthBetween(r, z, a, b), tolerance, 0);
}

}  // namespace

ArcTable arcTableOf(const double r[4], const double z[4]) {
  const double estimate = arcLengthBetween(r, z, 0.0, 1.0);
  const double tolerance = 0x1p-40 * estimate;
  for (std::uint32_t steps = 1;; steps *= 2) {
    ArcTable table{0.0, steps, std::vector<double>(steps + 1)};
    double cumulative = 0.0;
    for (std::uint32_t k = 1; k <= steps; ++k) {
      cumulative += lengthBetween(r, z, double(k - 1) / steps, double(k) / steps, tolerance / steps);
      table.cumulative[k] = cumulative;
    }
    table.length = cumulative;
    if (steps >= 1024) return table;
    bool fine = true;
    for (std::uint32_t k = 0; k < steps && fine; ++k) {
      // At each eighth of the step, the panels integrated once each; within 2^-31, half the promise:
      // the rule's error between the eighths is not sampled (arc_table_test checks sixteenths).
      const double start = double(k) / steps;
      double exact = 0.0;
      for (int j = 1; j <= 8 && fine; ++j) {
        const double from = (k + (j - 1) / 8.0) / steps, to = (k + j / 8.0) / steps;
        exact += lengthBetween(r, z, from, to, tolerance / (8 * steps));
        fine = std::abs(arcLengthBetween(r, z, start, to) - exact) <= 0x1p-31 * table.length;
      }
    }
    if (fine) return table;
  }
}

}  // namespace revolve::detail
