// revolve's counterpart of Open3D's RaycastingScene (open3d.t.geometry, Open3D 0.19): surfaces of
// revolution, each placed by an affine matrix and traced exactly, beside triangle meshes, in one
// Embree scene; every query runs over an array of rays or points on TBB's threads. Plain C++
// over raw arrays; raycasting_bindings.cpp binds it to numpy with Open3D's names and layouts.
//
// The scene is the tools' (platform/scene/embree_scene.h: the same placements, limits and Embree
// layout), laid out as Open3D's: watertight triangles, and a revolution placed by the identity
// attached to the top scene itself. What is Python's alone is on top: the queries over arrays, the
// crossing count, closest points over meshes and revolutions, and the lock that lets queries and
// additions come from any thread.
#pragma once

#include "geometry/placement.h"
#include "scene/embree_scene.h"

#include <revolve/revolve.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <shared_mutex>
#include <span>
#include <string>
#include <vector>

namespace revolve::python {

class RaycastingScene {
 public:
  static constexpr std::uint32_t kInvalidId = RTC_INVALID_GEOMETRY_ID;

  RaycastingScene();

  // Additions are thread-safe: each waits for the queries running to finish, and queries started
  // meanwhile wait for it. The new geometry's id.
  std::uint32_t addRevolution(Shape shape, const app::Placement& placement);
  // 3 floats a vertex, 3 indices a triangle; the caller has checked the indices against the
  // vertex count and the vertices against the coordinate limit.
  std::uint32_t addTriangles(std::span<const float> vertices, std::span<const std::uint32_t> triangles);
  std::size_t geometryCount() const;

  // What a pickle keeps of a revolution (pickling.cpp): its profile and placement as given, after
  // their checks. Added with one, the revolution keeps it; a mesh's arrays are the scene's own.
  struct RevolutionRecipe {
    std::vector<double> points;  // (r, z) pairs, as given
    std::optional<std::string> spline;
    std::optional<double> tolerance;
    std::array<double, 16> rows{};  // the 4x4 object-to-world matrix, row by row
  };
  std::uint32_t addRevolution(Shape shape, const app::Placement& placement, RevolutionRecipe recipe);
  // Many revolutions at once (add_revolutions), each with its recipe: their Embree geometries built
  // in parallel; the ids are consecutive, the first returned.
  std::uint32_t addRevolutions(std::vector<Shape> shapes, std::span<const app::Placement> placements,
                               std::vector<RevolutionRecipe> recipes);
  // Calls `revolution` or `mesh` for each geometry in id order, under the lock additions take
  // shared: what rebuilds the scene addition by addition. Throws std::logic_error for a revolution
  // added without its recipe.
  void forEachAddition(const std::function<void(const RevolutionRecipe&)>& revolution,
                       const std::function<void(const scene::TriangleMesh&)>& mesh) const;
  // Heap bytes the geometry holds: revolve's shapes and the meshes' vertices and indices, and what
  // Embree has allocated for the scene (its memory monitor), device set-up included.
  std::size_t memoryBytes() const;

  // Every query reads `count` rays (ox, oy, oz, dx, dy, dz) or points (x, y, z), refuses those
  // geometry/ray_limits.h refuses for queries (without tracing them), and returns the index of the
  // first refused, or nothing. `threads` 0 means all (checked by the caller: 0 to kMaxThreads).
  // Thread-safe, against each other and against additions.
  struct Hits {
    float* t;                  // inf on a miss
    std::uint32_t* geometry;   // kInvalidId on a miss
    std::uint32_t* primitive;  // kInvalidId on a miss
    float* uv;                 // 2 a ray
    float* normal;             // 3 a ray: unit, world space, the surface's own side (not turned to the ray)
  };
  std::optional<std::size_t> castRays(const float* rays, std::size_t count, const Hits& out, int threads);
  std::optional<std::size_t> testOcclusions(const float* rays, std::size_t count, float tnear, float tfar, bool* out,
                                            int threads);
  // Hits along the whole ray (t >= 0), each surface crossing once (Open3D's rule for a hit on an
  // edge shared by two triangles of a mesh).
  std::optional<std::size_t> countIntersections(const float* rays, std::size_t count, std::int32_t* out, int threads);
  // Every crossing countIntersections counts, as Open3D's list_intersections lists them: `splits`
  // (count + 1 offsets: ray i's crossings are [splits[i], splits[i + 1])) and the crossings, each
  // ray's nearest first, written where allocate(total) says (called once, between the two passes:
  // the crossings are counted, then traced again and written). Throws std::length_error when the
  // total exceeds 2^32 - 1.
  struct Crossing {
    float t;
    std::uint32_t geometry, primitive;
    float u, v;
  };
  std::optional<std::size_t> listIntersections(const float* rays, std::size_t count,
                                               const std::function<Crossing*(std::size_t)>& allocate,
                                               std::vector<std::uint32_t>& splits, int threads);

  struct Closest {
    float* point;  // 3 a point
    std::uint32_t* geometry;
    std::uint32_t* primitive;
    float* uv;        // 2 a point (revolutions: u exact, v along the segment or part, see docs/python.md)
    float* normal;    // 3 a point
    float* distance;  // 1 a point; negative inside a solid when signed
  };
  // Exact closest surface points, distances in double rounded once. `signedDistance`: negative
  // inside any closed revolution (revolve::insideSolid). Throws std::invalid_argument with
  // distanceLimitation() (and for signed, solidLimitation()) when it is not empty.
  std::optional<std::size_t> closestPoints(const float* points, std::size_t count, const Closest& out,
                                           bool signedDistance, int threads);
  // Inside (1) or outside (0) the union of the closed revolutions. Throws std::invalid_argument with
  // solidLimitation() when it is not empty.
  std::optional<std::size_t> occupancy(const float* points, std::size_t count, float* out, int threads);

 private:
  using QueryLock = std::shared_lock<std::shared_mutex>;
  // The shared lock a query holds while it runs, taken once the scene is committed (and, with
  // `counting`, its crossing-counting copy built): everything it reads stays as it is until it ends.
  QueryLock readyForQueries(bool counting);
  // Why distances (or the inside) cannot be exact here, or empty; under the caller's lock.
  std::string distanceLimitation() const;
  std::string solidLimitation() const;
  // Heap bytes the recipes hold; under the caller's lock.
  std::size_t recipeBytes() const noexcept;
  // Whether world point p lies inside any revolution's solid (all closed: solidLimitation() empty).
  bool insideAny(const app::Vec3d& p) const noexcept;
  template <class Body>
  std::optional<std::size_t> forEach(const float* items, std::size_t count, bool rays, int threads, Body body) const;

  scene::EmbreeScene scene_;
  RTCScene counting_ = nullptr;  // scene_.filteredScene(): every crossing counted
  bool committed_ = false, countingCurrent_ = false;
  mutable std::shared_mutex mutex_;  // shared: queries; exclusive: additions, commits, the counting copy

  std::vector<std::optional<RevolutionRecipe>> recipes_;  // by geometry id; nothing for a mesh
};

}  // namespace revolve::python
