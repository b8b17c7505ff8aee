// 3x3 matrices of doubles: products, the inverse, rotations about the coordinate axes and about
// any unit axis (Rodrigues' formula). Everything in double precision; a caller rounds to float
// once, where Embree needs it.
#pragma once

#include "geometry/vec3d.h"

#include <revolve/core.h>

#include <array>
#include <cstddef>

namespace revolve::app {

// A 3x3 matrix of doubles, m[row][column].
struct Matrix3d {
  std::array<Vec3d, 3> m{};

  Vec3d& operator[](std::size_t row) { return m[row]; }
  const Vec3d& operator[](std::size_t row) const { return m[row]; }
  bool operator==(const Matrix3d&) const = default;

  static Matrix3d identity() { return {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}}; }

  Vec3d apply(const Vec3d& v) const {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
  }
  // A float vector through the matrix: computed in double, each component rounded to float once.
  Vec3 apply(Vec3 v) const {
    return {float(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z), float(m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z),
            float(m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z)};
  }
  // |M| |v| per row: bounds on how an error vector (or a magnitude) maps through M.
  Vec3 applyAbsolute(Vec3 v) const;
  // The largest row sum of |m|; NaN when an entry is (a singular matrix's inverse), so that every
  // range test refuses it.
  double infinityNorm() const;
  Matrix3d transposed() const;
};

// The product a b.
Matrix3d operator*(const Matrix3d& a, const Matrix3d& b);
// The inverse by cofactors; a singular matrix gives non-finite entries.
Matrix3d inverse(const Matrix3d& a);
// Each entry rounded to float (what Embree's instance transform holds), kept in double.
Matrix3d roundedToFloat(const Matrix3d& a);

// Rotations by `radians` about the coordinate axes (counter-clockwise looking down the axis).
Matrix3d rotationAboutX(double radians);
Matrix3d rotationAboutY(double radians);
Matrix3d rotationAboutZ(double radians);
// The rotation by `radians` about the unit `axis` (Rodrigues' formula).
Matrix3d rotationAbout(const Vec3d& axis, double radians);

}  // namespace revolve::app
