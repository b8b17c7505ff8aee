// revolve's counterpart of Open3D's RaycastingScene (open3d.t.geometry, Open3D 0.19): surfaces of
// revolution, each placed by an affine matrix and traced exactly, beside triangle meshes, in one
// Embree scene; every query runs over an array of rays or points on TBB's threads. Plain C++
// over raw arrays; raycasting_bindings.cpp binds it to numpy with Open3D's names and layouts.
//
// Geometry ids count 0, 1, ... in the order geometries are added, as Open3D's do. A revolution is
// a one-shape Embree scene instanced into the top scene under its id (Embree's instID); a mesh is
// attached to the top scene itself under its id (Embree's geomID).
#pragma once

#include "placement.h"

#include "embree/embree_handles.h"

#include <revolve/revolve.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
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
  ~RaycastingScene();
  RaycastingScene(const RaycastingScene&) = delete;
  RaycastingScene& operator=(const RaycastingScene&) = delete;

  // The new geometry's id.
  std::uint32_t addRevolution(Shape shape, const Placement& placement);
  // 3 floats a vertex, 3 indices a triangle; the caller has checked the indices against the
  // vertex count and the vertices against the coordinate limit.
  std::uint32_t addTriangles(std::span<const float> vertices, std::span<const std::uint32_t> triangles);
  std::size_t geometryCount() const;
  // Heap bytes the geometry holds: revolve's shapes and the meshes' vertices and indices, and what
  // Embree has allocated for the scene (its memory monitor), device set-up included.
  std::size_t memoryBytes() const;

  // Every query reads `count` rays (ox, oy, oz, dx, dy, dz) or points (x, y, z), refuses those
  // query_limits.h refuses (without tracing them), and returns the index of the first refused,
  // or nothing. `threads` 0 means all. Thread-safe; the geometry may not change meanwhile (a
  // call that adds one waits).
  struct Hits {
    float* t;                 // inf on a miss
    std::uint32_t* geometry;  // kInvalidId on a miss
    std::uint32_t* primitive;
    float* uv;      // 2 a ray
    float* normal;  // 3 a ray: unit, world space, the surface's own side (not turned to the ray)
  };
  std::optional<std::size_t> castRays(const float* rays, std::size_t count, const Hits& out, int threads);
  std::optional<std::size_t> testOcclusions(const float* rays, std::size_t count, float tnear, float tfar, bool* out,
                                            int threads);
  // Hits along the whole ray (t >= 0), each surface crossing once (Open3D's rule for a hit on an
  // edge shared by two triangles of a mesh).
  std::optional<std::size_t> countIntersections(const float* rays, std::size_t count, std::int32_t* out, int threads);

  struct Closest {
    float* point;  // 3 a point
    std::uint32_t* geometry;
    std::uint32_t* primitive;
    float* uv;        // 2 a point (revolutions: u exact, v along the segment or part, see docs/python.md)
    float* normal;    // 3 a point
    float* distance;  // 1 a point; negative inside a solid when signed
  };
  // Exact closest surface points, distances in double rounded once. `signedDistance`: negative
  // inside any closed revolution (solid_inside.h). Precondition: distanceLimitation() (and for
  // signed, solidLimitation()) empty.
  std::optional<std::size_t> closestPoints(const float* points, std::size_t count, const Closest& out,
                                           bool signedDistance, int threads);
  // Inside (1) or outside (0) the union of the closed revolutions. Precondition: solidLimitation() empty.
  std::optional<std::size_t> occupancy(const float* points, std::size_t count, float* out, int threads);

  // Why distances cannot be exact here (a revolution placed by other than a similarity), or empty.
  std::string distanceLimitation() const;
  // Why inside cannot be decided here (a mesh, an open profile), or empty.
  std::string solidLimitation() const;

  struct Revolution;
  struct Mesh;

 private:
  void commitIfChanged();
  void buildCountingScene();
  template <class Body>
  std::optional<std::size_t> forEach(const float* items, std::size_t count, std::size_t width, bool rays, int threads,
                                     Body body);

  std::unique_ptr<std::atomic<std::int64_t>> embreeBytes_ =
      std::make_unique<std::atomic<std::int64_t>>(0);  // outlives the device
  app::Device device_;
  app::Scene top_, counting_;
  std::vector<std::unique_ptr<Revolution>> revolutions_;  // by id; nullptr for meshes
  std::vector<std::unique_ptr<Mesh>> meshes_;             // by id; nullptr for revolutions
  bool committed_ = false, countingBuilt_ = false;
  mutable std::shared_mutex mutex_;  // shared: queries; exclusive: changes and commits
};

}  // namespace revolve::python
