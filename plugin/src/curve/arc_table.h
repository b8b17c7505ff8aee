// Each curved part's table of arc length, from which a hit's v is computed: built once.
#pragma once

#include <cstdint>
#include <vector>

namespace revolve::detail {

struct ArcTable {
  double length;                   // the part's arc length
  std::uint32_t steps;             // equal steps of u
  std::vector<double> cumulative;  // arc length at u = k / steps, k = 0 .. steps
};

// Arc lengths by adaptive Gauss-Legendre quadrature (halving until two levels agree within 2^-40
// of the part's length: each step's eighths, checked by its quarters); steps doubled from 1 (up to
// 1024) until one five-point Gauss-Legendre rule from a step's start (arcLengthBetween, what a hit
// computes: arc_length.h's arcLengthFrom) is within 2^-31 of the part's length of the arc length at
// every eighth of the step: 2^-30 is promised anywhere in it, the other half room for the points
// between. A smooth part needs one to four steps: a few doubles a part rather than a dense table.
ArcTable arcTableOf(const double r[4], const double z[4]);

}  // namespace revolve::detail
