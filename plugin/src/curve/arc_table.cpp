#include "curve/arc_table.h"

#include "curve/arc_length.h"

#include <cmath>
#include <vector>

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

// `whole`: one five-point rule over [a, b], when the caller has it already.
double lengthBetween(const double r[4], const double z[4], double a, double b, double tolerance, double whole) {
  return adaptiveLength(r, z, a, b, whole, tolerance, 0);
}

double lengthBetween(const double r[4], const double z[4], double a, double b, double tolerance) {
  return lengthBetween(r, z, a, b, tolerance, arcLengthBetween(r, z, a, b));
}

}  // namespace

ArcTable arcTableOf(const double r[4], const double z[4]) {
  const double estimate = arcLengthBetween(r, z, 0.0, 1.0);
  const double tolerance = 0x1p-40 * estimate;
  for (std::uint32_t steps = 1;; steps *= 2) {
    ArcTable table{0.0, steps, std::vector<double>(steps + 1)};
    std::vector<double> stepRule(steps);  // one five-point rule over each step
    double cumulative = 0.0;
    for (std::uint32_t k = 1; k <= steps; ++k) {
      // One step spans [0, 1]: its rule is the estimate's (the same evaluations, not repeated).
      const double from = double(k - 1) / steps, to = double(k) / steps;
      stepRule[k - 1] = steps == 1 ? estimate : arcLengthBetween(r, z, from, to);
      cumulative += lengthBetween(r, z, from, to, tolerance / steps, stepRule[k - 1]);
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
        const double eighth = arcLengthBetween(r, z, from, to);
        exact += lengthBetween(r, z, from, to, tolerance / (8 * steps), eighth);
        // From the step's start to its first eighth the hit's rule is the eighth's own (from ==
        // start exactly), and to its end the step's: the same arguments, evaluated once.
        const double rule = j == 1 ? eighth : j == 8 ? stepRule[k] : arcLengthBetween(r, z, start, to);
        fine = std::abs(rule - exact) <= 0x1p-31 * table.length;
      }
    }
    if (fine) return table;
  }
}

}  // namespace revolve::detail
