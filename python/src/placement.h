// Where RaycastingScene.add_revolution puts a shape: an affine 4x4 matrix (object to world), checked
// against the ranges the tools trace within (platform/geometry/ray_limits.h), with what the queries need
// of it: Embree's float matrix, the double-precision maps both ways, the normals' map, and whether
// it is a similarity (distances are exact only under rotation, uniform scale and translation).
#pragma once

#include <revolve/revolve.h>

#include <array>

namespace revolve::python {

using Vec3d = std::array<double, 3>;
using Matrix3d = std::array<Vec3d, 3>;  // row by row

struct Placement {
  Matrix3d linear{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // object to world
  Vec3d translate{};
  Matrix3d inverse{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // world to object, of the linear part
  // s when linear = s Q, Q orthogonal (to kSimilarityTolerance), else 0.
  double similarity = 1;

  // Relative tolerance of the similarity test: rotations computed in double pass, a matrix
  // rounded to float (1e-7) does not, since distances through it would be off by as much.
  static constexpr double kSimilarityTolerance = 1e-12;

  Vec3d toWorld(const Vec3d& p) const;
  Vec3d toObject(const Vec3d& p) const;
  // An object-space normal carried to the world (inverse transpose) and made unit length.
  Vec3d normalToWorld(const Vec3d& n) const;
  // Embree's RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR.
  std::array<float, 12> embreeColumns() const;
};

// `rows`: the 4x4 matrix row by row. Throws std::invalid_argument naming the entry or the rule:
// finite entries; a last row of (0, 0, 0, 1); a linear part whose scale factors lie in [2^-16,
// 2^40] within a factor 2^16 of each other; and the shape's box, carried to the world, within
// +-2^40 (the scene file's rules).
Placement placementOf(const double* rows, const Shape& shape);

}  // namespace revolve::python
