// Small float 3-vector arithmetic on revolve::Vec3 for the applications (the library keeps its
// own double-precision maths private).
#pragma once

#include <revolve/revolve.h>

#include <algorithm>
#include <cmath>

namespace revolve::app {

// The platform's own, not the library's (whose namespace, revolve, argument-dependent lookup would
// search): code in the platform's other namespaces names them with using-declarations.
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(Vec3 a, float s) { return {s * a.x, s * a.y, s * a.z}; }

inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline float length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return (1.0f / length(a)) * a; }
inline Vec3 absolute(Vec3 a) { return {std::abs(a.x), std::abs(a.y), std::abs(a.z)}; }
inline float maxComponent(Vec3 a) { return std::max({a.x, a.y, a.z}); }

// A right-handed orthonormal basis (s, t, n) around unit n (Duff et al. 2017, branchless).
struct Frame {
  Vec3 s, t, n;
  explicit Frame(Vec3 normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
    s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t = {b, sign + n.y * n.y * a, -n.y};
  }
  Vec3 toWorld(Vec3 local) const { return local.x * s + local.y * t + local.z * n; }
  Vec3 toLocal(Vec3 world) const { return {dot(world, s), dot(world, t), dot(world, n)}; }
};

}  // namespace revolve::app
