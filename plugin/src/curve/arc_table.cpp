#include "curve/arc_table.h"

#include "curve/arc_length.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace revolve::detail {
namespace {

constexpr std::uint32_t kMostSteps = 1024;

// [a, b]'s arc length, halving until two levels agree within `tolerance` (`whole`: the five-point
// rule over [a, b], which the caller has).
double adaptiveLength(const double r[4], const double z[4], double a, double b, double whole, double tolerance,
                      int depth) {
  const double middle = 0.5 * (a + b);
  const double left = arcLengthBetween(r, z, a, middle), right = arcLengthBetween(r, z, middle, b);
  if (depth >= 30 || std::abs(left + right - whole) <= tolerance) return left + right;
  return adaptiveLength(r, z, a, middle, left, 0.5 * tolerance, depth + 1) +
         adaptiveLength(r, z, middle, b, right, 0.5 * tolerance, depth + 1);
}

struct StepCheck {
  double length;  // the step's arc length (the sum of its eighths' references)
  double worst;   // the hit's rule's largest distance from it at an eighth
};

// Step k of `steps`: its arc length by quadrature, and how far the hit's rule from the step's start
// (arcLengthBetween(start, to), what arcLengthFrom computes) is from the running sum at each eighth
// of the step. The reference is the eighths' five-point rules, each quarter's two checked against
// the quarter's own rule: where they agree within the quarter's share of `tolerance` the finer
// level is kept, as the halving does, and where they do not each eighth is halved further. The
// hit's rules to the first eighth, the first quarter and the end are the eighth's, the quarter's
// and `stepRule` (the step's): the same arguments, evaluated once. Stops early, with worst above
// `certainlyTooFar`, where a rule is that far off.
StepCheck checkStep(const double r[4], const double z[4], std::uint32_t k, std::uint32_t steps, double stepRule,
                    double tolerance, double certainlyTooFar) {
  const double start = double(k) / steps;
  const auto at = [&](int eighth) { return (k + eighth / 8.0) / steps; };  // at(0) is start exactly
  StepCheck check{0.0, 0.0};
  for (int q = 0; q < 4; ++q) {
    const double a = at(2 * q), middle = at(2 * q + 1), b = at(2 * q + 2);
    const double first = arcLengthBetween(r, z, a, middle), second = arcLengthBetween(r, z, middle, b);
    const double quarter = arcLengthBetween(r, z, a, b);
    double left = first, right = second;
    if (!(std::abs(first + second - quarter) <= tolerance / (4 * steps))) {
      left = adaptiveLength(r, z, a, middle, first, tolerance / (8 * steps), 0);
      right = adaptiveLength(r, z, middle, b, second, tolerance / (8 * steps), 0);
    }
    check.length += left;
    const double toMiddle = q == 0 ? first : arcLengthBetween(r, z, start, middle);
    check.worst = std::max(check.worst, std::abs(toMiddle - check.length));
    check.length += right;
    const double toEnd = q == 0 ? quarter : q == 3 ? stepRule : arcLengthBetween(r, z, start, b);
    check.worst = std::max(check.worst, std::abs(toEnd - check.length));
    // Cut short: the step's length is partial, and the table is refused whatever the length is.
    if (!(check.worst <= certainlyTooFar)) return {check.length, std::numeric_limits<double>::infinity()};
  }
  return check;
}

}  // namespace

ArcTable arcTableOf(const double r[4], const double z[4]) {
  const double estimate = arcLengthBetween(r, z, 0.0, 1.0);
  const double tolerance = 0x1p-40 * estimate;
  // A monotone part is no longer than |dr| + |dz|, at most sqrt 2 (below 1.5) times its chord: a
  // rule farther than 2^-31 of that from the reference fails the check whatever the length is.
  const double chord = std::hypot(r[3] - r[0], z[3] - z[0]);
  const double certainlyTooFar = 0x1p-31 * 1.5 * chord;
  ArcTable table{0.0, 0, {}};
  table.cumulative.reserve(5);  // most parts stop at one to four steps: one allocation
  for (std::uint32_t steps = 1;; steps *= 2) {
    table.steps = steps;
    table.cumulative.assign(1, 0.0);
    double worst = 0.0;
    for (std::uint32_t k = 0; k < steps && worst <= certainlyTooFar; ++k) {
      // One step spans [0, 1]: its rule is the estimate's (the same evaluations, not repeated).
      const double stepRule = steps == 1 ? estimate : arcLengthBetween(r, z, double(k) / steps, double(k + 1) / steps);
      double length;
      if (steps >= kMostSteps) {
        length = adaptiveLength(r, z, double(k) / steps, double(k + 1) / steps, stepRule, tolerance / steps, 0);
      } else {
        const StepCheck check = checkStep(r, z, k, steps, stepRule, tolerance, certainlyTooFar);
        length = check.length;
        worst = std::max(worst, check.worst);
      }
      table.cumulative.push_back(table.cumulative.back() + length);
    }
    table.length = table.cumulative.back();
    // Within 2^-31 of the part's length at every eighth, half the promise: the rule's error between
    // the eighths is not sampled (arc_table_test checks sixteenths).
    if (steps >= kMostSteps || (table.cumulative.size() == steps + 1 && worst <= 0x1p-31 * table.length)) {
      return table;
    }
  }
}

}  // namespace revolve::detail
