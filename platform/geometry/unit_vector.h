// Robust normalisation in double for directions read from files (camera, sun, rotation axes).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace revolve::app {

// A non-zero finite vector scaled to unit length without overflow or underflow: first by its
// largest component (exact but for rounding), so that components of 1e-200 or 1e300 normalise as
// well as components of 1 do.
inline std::array<double, 3> unitVector(std::array<double, 3> v) {
  const double largest = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  for (double& c : v) c /= largest;
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& c : v) c /= length;
  return v;
}

}  // namespace revolve::app
