// The benchmark's ground truth: the exact first hit of a beam with a scene description, by brute
// force in double precision, written independently of revolve's kernel and of Embree. Each object
// of revolution is solved in its own frame (the scene transform inverted in double) segment by
// segment, each segment's truncated cone by its quadratic (a disc or an annulus when horizontal);
// quads as their two triangles (Moller-Trumbore). Slow (every segment of every object near the
// beam), exact to double rounding: what a range error is measured against.
#pragma once

#include "geometry/vec3d.h"
#include "io/scene_file.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace revolve::bench {

using app::Vec3d;

struct ReferenceHit {
  double distance;      // along the unit beam
  std::int64_t object;  // the scene's object index (quads: objects + quad index)
};

class ReferenceRanges {
 public:
  explicit ReferenceRanges(const io::SceneDescription& scene);
  // The first hit of origin + t direction, t > 0 (direction unit length).
  std::optional<ReferenceHit> trace(const Vec3d& origin, const Vec3d& direction) const;

 private:
  struct Object {
    const std::vector<Point2>* profile;
    std::array<Vec3d, 3> inverse;  // world to object, linear part
    Vec3d translate;
    Vec3d centre;  // object space: a sphere holding the profile
    double radius;
  };
  struct Triangle {
    Vec3d a, b, c;
    std::int64_t object;
  };
  std::vector<std::vector<Point2>> profiles_;
  std::vector<Object> objects_;
  std::vector<Triangle> triangles_;
};

}  // namespace revolve::bench
