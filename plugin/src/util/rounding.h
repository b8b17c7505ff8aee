// Floating-point facts shared by the library: the unit roundoff, rounding to float outwards, signs.
#pragma once

#include <cmath>

namespace revolve::detail {

inline constexpr double kUnitRoundoff = 0x1p-53;  // u for double

// The largest float <= x and the smallest float >= x: bounds stored as floats stay conservative.
inline float floatBelow(double x) {
  const auto f = static_cast<float>(x);
  return double(f) > x ? std::nextafter(f, -INFINITY) : f;
}
inline float floatAbove(double x) {
  const auto f = static_cast<float>(x);
  return double(f) < x ? std::nextafter(f, INFINITY) : f;
}

inline int signOf(double x) { return (x > 0.0) - (x < 0.0); }

}  // namespace revolve::detail
