// The objects of revolve-bench scale: a seeded family of distinct surfaces of revolution, every
// object its own 64-point profile (even objects a polyline, odd ones a centripetal Catmull-Rom
// spline through the same points), placed on a square grid. Object i depends on the seed and i
// alone, so any N draws the first N objects of the same sequence.
#pragma once

#include "io/scene_file.h"

#include <revolve/revolve.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace revolve::bench {

struct ScaleFamily {
  static constexpr std::size_t kPoints = 64;
  static constexpr double kSpacing = 1.25;  // grid pitch: objects are at most 1.2 across (radius <= 0.6 x scale 1)
  std::uint64_t seed = 20011;

  // Object i's profile points, bottom (on the axis) to top, z in [0, 1].
  std::vector<Point2> points(std::size_t i) const;
  bool isSpline(std::size_t i) const { return i % 2 == 1; }
  // The smooth radius the points sample, r(z) for z in [0, 1]: the surface object i stands for.
  double smoothRadius(std::size_t i, double z) const;
  // Object i's placement: its grid cell for N objects, a uniform scale in [0.8, 1].
  app::Transform transform(std::size_t i, std::size_t count) const;
  // The grid's side: ceil(sqrt(count)).
  static std::size_t gridSide(std::size_t count);

  // The largest distance between a polyline object's chords and its smooth radius, over objects
  // 0 to `objects` - 1, sampled 16 times a segment: the error of a 64-point polyline against the
  // shape it samples, at which the meshes are matched.
  double polylineError(std::size_t objects) const;
};

// How the description's profiles are made: traced exactly (polylines and splines as they are), or
// meshed (splines sampled as polylines within `tolerance`, as the scene file's "tolerance").
struct FamilyScene {
  bool mesh = false;
  double tolerance = 0;
};

// N objects as a scene file would describe them: one profile each, one material.
io::SceneDescription familyDescription(const ScaleFamily& family, std::size_t count, const FamilyScene& how);

}  // namespace revolve::bench
