// Where a scene object is placed: its transform (io::SceneTransform, x -> translate + rotate(axis,
// degrees) (scale * x)) as matrices, and the 3x3 matrix arithmetic the tools share: rotations
// (Rodrigues' formula about an axis, and about the coordinate axes for a sensor's roll, pitch and
// yaw), products, the inverse and the inverse transpose for normals, and the reach of a placed
// profile. Everything in double precision; a tool rounds to float once, where Embree needs it.
#pragma once

#include "io/scene_file.h"

#include <revolve/revolve.h>

#include <array>
#include <cstddef>

namespace revolve::scene {

using Vec3d = std::array<double, 3>;

// A 3x3 matrix of doubles, m[row][column].
struct Matrix3d {
  std::array<Vec3d, 3> m{};

  Vec3d& operator[](std::size_t row) { return m[row]; }
  const Vec3d& operator[](std::size_t row) const { return m[row]; }

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
  double infinityNorm() const;  // the largest row sum of |m|; NaN entries are passed over
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

// The transform's rotation (Rodrigues' formula about its unit axis), its linear part rotate *
// scale, and the linear part's inverse scale^-1 * rotation^T.
Matrix3d rotationOf(const io::SceneTransform& transform);
Matrix3d linearPart(const io::SceneTransform& transform);
Matrix3d inverseLinearPart(const io::SceneTransform& transform);
// The transform's rotation applied to one vector by Rodrigues' formula directly (v c + (k x v) s +
// k (k . v)(1 - c)), without building the matrix.
Vec3d rotate(const io::SceneTransform& transform, const Vec3d& v);

// The largest |coordinate| any point of `profile` reaches placed by `transform`: the corners of
// its box [-rmax, rmax]^2 x [zmin, zmax], carried to the world. The scene file's reader holds it
// within the coordinate limit (common/ray_limits.h).
double worldReach(const Profile& profile, const io::SceneTransform& transform);

}  // namespace revolve::scene
