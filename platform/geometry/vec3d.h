// Points and directions in double precision: the platform's one Vec3d, and the few operations on
// it that the floors above share. (revolve::Vec3, the library's float vector, is what rays and
// hits carry; geometry/vector_math.h has its operators.)
#pragma once

#include <array>

namespace revolve::app {

using Vec3d = std::array<double, 3>;

inline Vec3d plus(const Vec3d& a, const Vec3d& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace revolve::app
