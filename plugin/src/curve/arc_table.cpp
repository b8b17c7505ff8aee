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
  for (std::uint32_t steps = 8;; steps *= 2) {
    ArcTable table{0.0, steps, std::vector<double>(2 * (steps + 1))};
    double cumulative = 0.0;
    for (std::uint32_t k = 0; k <= steps; ++k) {
      const double u = double(k) / steps;
      if (k > 0) cumulative += lengthBetween(r, z, double(k - 1) / steps, u, tolerance / steps);
      const double dr = cubicDerivative(r, u), dz = cubicDerivative(z, u);
      table.interleaved[2 * k] = cumulative;
      table.interleaved[2 * k + 1] = std::sqrt(dr * dr + dz * dz);
    }
    table.length = cumulative;
    if (steps >= 1024) return table;
    bool fine = true;
    for (std::uint32_t k = 0; k < steps && fine; ++k) {
      const double middle = (k + 0.5) / steps;
      const double exact = table.interleaved[2 * k] + lengthBetween(r, z, double(k) / steps, middle, tolerance / steps);
      fine = std::abs(hermiteAt(table.interleaved.data(), steps, middle) - exact) <= 0x1p-30 * table.length;
    }
    if (fine) return table;
  }
}

}  // namespace revolve::detail
