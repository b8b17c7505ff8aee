// The revolutions one "revolution" geometry holds, built from its parameters: each a revolve::Shape
// (the exact surface) and, for a spline traced as its polyline, the curve's shading normals.
// Plain revolve, no OSPRay: the geometry's commit() hands over the parameters it read.
#pragma once

#include <revolve/core.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace revolve::ospray_module {

struct Revolution {
  Shape shape;
  // Only for a curved spline traced as its polyline (a tolerance): the curve's normals, and where
  // each polyline segment starts along the profile (in v's units, [0, 1]) to find a hit's segment.
  std::optional<ShadingNormals> curveNormals;
  std::vector<float> segmentStart;

  // Unit object-space shading normal at (u, v), or nothing when the geometric normal is the one to
  // shade with (a polyline profile, or a spline traced exactly: Ng is then the curve's own normal).
  [[nodiscard]] std::optional<Vec3> shadingNormal(float u, float v) const noexcept;
};

struct RevolutionParameters {
  std::vector<std::vector<Point2>> profiles;  // one profile per revolution, in the caller's order
  std::optional<std::string> spline;          // a scene file spline kind; none: polylines
  std::optional<float> tolerance;             // trace the spline as its polyline within this
};

// Builds every revolution. Throws std::invalid_argument naming the profile (its index among
// `profiles`), the point and the rule it breaks, for: no profile, an invalid profile or spline
// (revolve's rules, ProfileError), an unknown spline kind, a tolerance that is not a finite number
// > 0 or is given without a curved spline.
[[nodiscard]] std::vector<Revolution> buildRevolutions(const RevolutionParameters& parameters);

}  // namespace revolve::ospray_module
