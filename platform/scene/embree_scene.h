// Surfaces of revolution and triangles in one Embree scene: the one scene stack of the tools and of
// Python's RaycastingScene. Each surface of revolution is a prototype (a revolve Shape, or a
// tessellated mesh, or Embree's own linear cone curve) placed under its object's placement
// (geometry/placement.h): an exact surface as a revolve::Geometry of its own that maps rays into
// object space itself, attached to the top scene (its Shape shared by every object of the same
// profile); a mesh or cone curve by an Embree instance of the prototype's scene. Triangles (a scene
// file's quads, a Python user's meshes) are top-level triangle geometries. Hits come back in world
// space with their object's index, a smooth shading normal, and what is needed to spawn secondary
// rays without re-hitting the surface.
//
// Geometry ids: every geometry, revolution or mesh, is attached under the id it was added as (0, 1,
// ... in order), so Embree's instID (for an instance) or geomID (for one attached to the top scene
// itself) is its id. A scene file's objects[i] is geometry i, each distinct profile built once; its
// quads are one triangle geometry under id objects.size(), quad q its triangles 2q and 2q + 1.
#pragma once

#include "embree/embree_handles.h"
#include "embree/memory_monitor.h"
#include "geometry/placement.h"
#include "io/scene_file.h"

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace revolve::scene {

// How a scene file's profiles are built (the tools' --geometry and the MIBIT switches).
struct BuildSettings {
  bool mesh = false;  // tessellate every profile instead of tracing it exactly
  // Trace every profile as Embree's linear cone curve instead (ConeCurveGeometry); the scene is
  // refused, naming the first object whose profile it cannot express or that is scaled. Its kernel
  // assumes unit ray directions: rays are handed to Embree normalised (t scaled back), and an
  // instance's scale would make them other lengths again in object space.
  bool embreeCone = false;
  std::uint32_t slices = 64;  // azimuthal steps of the mesh
  BuildOptions options;       // the exact surfaces' search structure
  bool countStats = false;    // MIBIT counters (slower); read with EmbreeScene::stats()
};

// How the top-level scene is laid out, for a scene built geometry by geometry.
struct Layout {
  // RTC_SCENE_FLAG_ROBUST on the top scene: watertight triangles (a ray through the edge two
  // triangles share does not slip between them), as Open3D's RaycastingScene asks of Embree.
  bool robust = false;
};

struct WorldHit {
  float t = 0;
  Vec3 point{};            // world position of the hit
  Vec3 geometricNormal{};  // world, unit; the surface's own side (not flipped towards the ray)
  Vec3 shadingNormal{};    // world, unit, on the geometric normal's side
  std::uint32_t material = 0;
  std::uint32_t object = 0;  // the geometry id, or for a scene file's quads objects.size() + quad index
  // For spawning rays (EmbreeScene::spawn): the world ray and, for exact surfaces, the extra
  // error of the instance transform; for triangles, the point's per-axis error bound.
  bool exactSurface = false;
  Ray ray{};
  float transformError = 0;
  Vec3 pointError{};
};

// The nearest hit as a range-finder needs it: its distance, object, the surface's geometric normal
// (the exact surface's own, a facet's for a mesh) and reflectivity, without the shading normals,
// surface parameters and error bounds WorldHit carries.
struct RangeHit {
  float t = 0;
  std::uint32_t object = 0;  // as WorldHit::object
  Vec3 normal{};             // world, unit (either side)
  float reflectivity = 1;    // the object's or quad's (io::SceneObject::reflectivity)
};

// A triangle mesh as added: 3 floats a vertex (and one more at the end: Embree reads a vertex as
// 16 bytes), 3 vertex indices a triangle, shared with Embree.
struct TriangleMesh {
  std::vector<float> vertices;
  std::vector<std::uint32_t> triangles;
  std::vector<std::uint32_t> quadMaterials;  // a scene file's quads: one material a pair of triangles
  std::vector<float> quadReflectivities;     // and one reflectivity
  std::size_t vertexCount() const { return (vertices.size() - 1) / 3; }
  std::size_t triangleCount() const { return triangles.size() / 3; }
};

class EmbreeScene {
 public:
  // A scene file's objects and quads, built and committed. Throws std::runtime_error naming the
  // object that cannot be built.
  EmbreeScene(const io::SceneDescription& description, const BuildSettings& settings);
  // An empty scene: geometries are added one by one, and the scene committed before it is traced.
  explicit EmbreeScene(const Layout& layout);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Adds a surface of revolution traced exactly, placed by `placement`; returns its geometry id.
  // Not thread-safe: no query may run meanwhile.
  std::uint32_t addRevolution(Shape shape, const app::Placement& placement, std::uint32_t material = 0);
  // Adds many surfaces of revolution at once, shapes[i] placed by placements[i] (as many of each):
  // their Embree geometries are built in parallel, and the ids are consecutive, the first returned.
  // Not thread-safe, as addRevolution.
  std::uint32_t addRevolutions(std::vector<Shape> shapes, std::span<const app::Placement> placements);
  // Adds a triangle mesh whose indices the caller has checked against its vertices; returns its
  // geometry id. Not thread-safe, as addRevolution.
  std::uint32_t addTriangles(std::span<const float> vertices, std::span<const std::uint32_t> triangles);
  // Builds Embree's tree over what was added; needed after an addition, before any query. Throws
  // std::runtime_error when Embree fails.
  void commit();

  std::size_t geometryCount() const noexcept { return geometries_.size(); }
  // Geometry `id` (< geometryCount()): the surface of revolution's shape and placement (nullptr
  // for a mesh or for a profile built as a mesh or cone curve), or the mesh (nullptr otherwise).
  const Shape* shapeOf(std::uint32_t id) const noexcept;
  const app::Placement& placementOf(std::uint32_t id) const noexcept;  // the identity for a mesh
  const TriangleMesh* meshOf(std::uint32_t id) const noexcept;
  // Whether a hit on `id` reports Embree's Ng in world space (a mesh; a surface of revolution
  // placed by the identity); otherwise it is in object space, for the placement to carry.
  bool worldNormals(std::uint32_t id) const noexcept;
  RTCScene handle() const noexcept { return top_.get(); }

  // Every geometry again, each with `filter` as its intersect filter, in a top scene of their own
  // (rebuilt after an addition, the same filter each time): what a query that sees every crossing
  // traces (Python's count_intersections). Not thread-safe, as addRevolution.
  RTCScene filteredScene(RTCFilterFunctionN filter);

  // Rays that break Embree's contract (geometry/ray_limits.h) are not traced: they miss, and are
  // counted by refusedRays(). The readers' limits keep every ray a tool makes within it, so a
  // tool reports a non-zero count as a fault rather than let Embree abort the process.
  //
  // Nearest hit with tnear <= t <= tfar, or nothing. Thread-safe; never allocates, throws or locks.
  std::optional<WorldHit> intersect(const Ray& ray) const noexcept;
  // The same nearest hit, reduced to its t and object. Thread-safe; never allocates, throws or locks.
  std::optional<RangeHit> nearest(const Ray& ray) const noexcept;
  // Whether anything lies on the ray within [tnear, tfar].
  bool occluded(const Ray& ray) const noexcept;
  // Packets: up to kPacketRays rays traced together through Embree's 8-wide query (rtcIntersect8
  // with a valid mask), so that Embree walks its tree once for rays that travel together (a camera's
  // neighbouring pixels, a lidar's neighbouring beams). hits[i] is exactly what intersect(rays[i]) /
  // nearest(rays[i]) returns, bit for bit; rays.size() <= kPacketRays, hits.size() == rays.size().
  // Rays that break Embree's contract are refused and counted as above, the rest of the packet traced.
  static constexpr std::size_t kPacketRays = 8;
  void intersect(std::span<const Ray> rays, std::span<std::optional<WorldHit>> hits) const noexcept;
  void nearest(std::span<const Ray> rays, std::span<std::optional<RangeHit>> hits) const noexcept;
  // Origin for a ray leaving `hit` in `direction`: revolve::offsetRayOrigin for exact surfaces
  // (plus the instance transform's error), the same construction from the barycentric point's
  // error bound for triangles (pbrt-v4), so the new ray neither re-hits the surface it leaves nor
  // misses a nearby one.
  Vec3 spawn(const WorldHit& hit, Vec3 direction) const noexcept;

  std::uint64_t refusedRays() const noexcept { return refused_->load(std::memory_order_relaxed); }
  Stats stats() const noexcept;  // MIBIT counters summed over every prototype
  // Search-tree nodes summed over the objects (an instanced tree counts once per object; meshes
  // and the linear scan have none): the paper's denominator for "percent of nodes traversed".
  std::size_t treeNodeCount() const noexcept;
  std::size_t revolveBytes() const noexcept;  // Shapes and shading normals
  std::size_t meshBytes() const noexcept;     // the triangle meshes' arrays
  // The scene's own records of its objects and prototypes (placements, ids, handles).
  std::size_t recordBytes() const noexcept;
  std::int64_t embreeBytes() const noexcept;  // Embree's own allocations now (its memory monitor)
  std::int64_t embreePeakBytes() const noexcept;
  double buildSeconds() const noexcept { return buildSeconds_; }
  std::size_t prototypeCount() const noexcept { return prototypes_.size(); }

  struct Prototype;
  struct Instance;

 private:
  struct Geometry {
    bool mesh = false;
    std::uint32_t index = 0;  // into instances_ or meshes_
  };

  EmbreeScene(const Layout& layout, bool unitDirections);
  // An exact surface's Embree geometry for `instance`: placed by its placement, unplaced for the identity.
  revolve::Geometry exactGeometry(const Shape& shape, const Instance& instance) const;
  // Places prototype `prototype` (built already) as a new geometry; returns its id.
  std::uint32_t addInstance(std::uint32_t prototype, const app::Placement& placement, std::uint32_t material,
                            float reflectivity = 1);
  // The record of object `id` and, for an exact surface, its Embree geometry, without changing the
  // scene: many are made in parallel. attach() adds instances_[index] (made for the next id) to the
  // top scene.
  Instance newInstance(std::uint32_t id, std::uint32_t prototype, const app::Placement& placement,
                       std::uint32_t material, float reflectivity) const;
  std::uint32_t attach(std::size_t index);
  RangeHit rangeHitOf(const RTCHit& hit, float t) const noexcept;
  std::uint32_t addMesh(TriangleMesh mesh);
  std::optional<WorldHit> hitOf(const Ray& ray, const RTCRayHit& rayHit) const noexcept;
  std::uint32_t objectOf(const RTCHit& hit) const noexcept;
  std::optional<WorldHit> instanceHit(const Instance& instance, const Ray& ray, const RTCRayHit& rayHit) const noexcept;
  std::optional<WorldHit> triangleHit(std::uint32_t id, const Ray& ray, const RTCRayHit& rayHit) const noexcept;
  // The packet of rays[i] set up and traced: lanes that are not traced come back without a hit
  // (geomID invalid); lengths[i] is what the lane's t is to be divided by (unit directions).
  void tracePacket(std::span<const Ray> rays, RTCRayHit8& packet, float (&lengths)[kPacketRays]) const noexcept;

  std::unique_ptr<app::EmbreeMemory> memory_;  // outlives the device, which reports to it
  std::unique_ptr<std::atomic<std::uint64_t>> refused_ = std::make_unique<std::atomic<std::uint64_t>>(0);
  app::Device device_;
  Layout layout_;
  std::vector<std::unique_ptr<Prototype>> prototypes_;
  std::vector<Instance> instances_;
  std::vector<TriangleMesh> meshes_;
  std::vector<Geometry> geometries_;  // by id
  app::Scene top_, filtered_;
  bool filteredCurrent_ = false;
  double buildSeconds_ = 0;
  bool unitDirections_ = false;  // Embree's cone curves need them
  bool countStats_ = false;      // BuildSettings::countStats
};

}  // namespace revolve::scene
