// Where an object is placed: an affine map x -> linear x + translate, object to world, held to the
// rule that keeps every ray revolve traces inside Embree's range, in the world and inside the
// object (geometry/ray_limits.h): its scale factors lie in [2^-16, 2^40], within a factor 2^16 of
// each other. The one home of that rule and of its messages: the scene file's reader, the scene
// built into Embree, the robot's obstacles and Python's add_revolution all place objects through
// it.
#pragma once

#include "geometry/matrix3d.h"
#include "geometry/vec3d.h"

#include <revolve/core.h>

#include <array>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace revolve::app {

// Object to world as the scene file writes it: x -> translate + rotate(axis, degrees) (scale * x).
struct Transform {
  Vec3d scale{1, 1, 1};       // each > 0
  Vec3d rotateAxis{0, 0, 1};  // unit length (the scene file's reader normalises it)
  double rotateDegrees = 0;
  Vec3d translate{0, 0, 0};
};

// The transform's rotation (Rodrigues' formula about its axis), its linear part rotate * scale,
// and the linear part's inverse scale^-1 * rotation^T (exact but for rounding, unlike a cofactor
// inverse).
Matrix3d rotationOf(const Transform& transform);
Matrix3d linearPart(const Transform& transform);
Matrix3d inverseLinearPart(const Transform& transform);
// The transform's rotation applied to one vector by Rodrigues' formula directly (v c + (k x v) s +
// k (k . v)(1 - c)), without building the matrix.
Vec3d rotate(const Transform& transform, const Vec3d& v);

// The rule as messages state it: "<factor> is out of range: " + this.
inline constexpr const char* kScaleFactorRule =
    "scale factors lie in [2^-16, 2^40] (1.5e-05 to 1.1e12), within which Embree's float instance transform keeps "
    "every ray in its range";

// The rule, part by part: why one scale factor (`written` as the input wrote it), or factors from
// `smallest` to `largest` on one object, cannot place it; nothing when they can.
std::optional<std::string> scaleFactorFault(double factor, std::string_view written);
std::optional<std::string> scaleRatioFault(double smallest, double largest);
// Why an object whose placed box reaches `reach` (its largest |world coordinate|) cannot be
// placed: positions lie within the coordinate limit; nothing when it can.
std::optional<std::string> reachFault(double reach);

// A refused placement; the message names the rule (and the entry, for a matrix).
class PlacementError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class Placement {
 public:
  Placement() = default;  // the identity
  // The scene file's transform, its scale factors held to the rule as given. Throws PlacementError.
  explicit Placement(const Transform& transform);
  // A 4x4 affine matrix, row by row (`name` names it in messages): finite entries, a last row of
  // (0, 0, 0, 1), and scale factors (the singular values of its 3x3 part) held to the rule.
  // Throws PlacementError naming the entry or the rule.
  static Placement fromRows(const double rows[16], std::string_view name);

  const Matrix3d& linear() const { return linear_; }  // object to world
  const Vec3d& translate() const { return translate_; }
  const Matrix3d& inverse() const { return inverse_; }  // world to object, of the linear part
  // s when linear = s Q with Q orthogonal (to kSimilarityTolerance), else 0: distances taken in
  // object space are exact in the world only under a similarity.
  double similarity() const { return similarity_; }
  bool isIdentity() const { return linear_ == Matrix3d::identity() && translate_ == Vec3d{0, 0, 0}; }

  // Relative tolerance of the similarity test: rotations computed in double pass, a matrix
  // rounded to float (1e-7) does not, since distances through it would be off by as much.
  static constexpr double kSimilarityTolerance = 1e-12;

  Vec3d toWorld(const Vec3d& p) const;
  Vec3d toObject(const Vec3d& p) const;
  // An object-space normal carried to the world (inverse transpose), made unit length.
  Vec3d normalToWorld(const Vec3d& n) const;
  // Embree's RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR: the linear part's columns, then the translation.
  std::array<float, 12> embreeColumns() const;
  // The largest |coordinate| any corner of the object-space box [lower, upper] reaches placed.
  double reach(const Vec3d& lower, const Vec3d& upper) const;

 private:
  Matrix3d linear_ = Matrix3d::identity(), inverse_ = Matrix3d::identity();
  Vec3d translate_{0, 0, 0};
  double similarity_ = 1;
};

// The largest |coordinate| any point of `profile` reaches placed by `placement`: the corners of its
// box [-rmax, rmax]^2 x [zmin, zmax] carried to the world (what reachFault holds).
double worldReach(const Profile& profile, const Placement& placement);
// The same for the box of `points`: for a spline, its control points, whose hull holds the curve
// (a reach at least the curve's, found without drawing it).
double worldReach(std::span<const Point2> points, const Placement& placement);

}  // namespace revolve::app
