// Each curved part's table of arc length, from which a hit's v is interpolated: built once.
#pragma once

#include <cstdint>
#include <vector>

namespace revolve::detail {

struct ArcTable {
  double length;                    // the part's arc length
  std::uint32_t steps;              // equal steps of u
  std::vector<double> interleaved;  // arc length and its derivative |c'(u)| at u = k / steps
};

// Arc lengths by adaptive Gauss-Legendre quadrature (halving until two levels agree within 2^-40
// of the part's length); steps doubled from 8 (up to 1024) until cubic Hermite interpolation of
// the table is within 2^-30 of the part's length of the arc length at every step's middle. A part
// whose speed |c'| varies fast (a curve turning sharply) gets more steps.
ArcTable arcTableOf(const double r[4], const double z[4]);

}  // namespace revolve::detail
