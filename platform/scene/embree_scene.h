// A scene description (io/scene_file.h) built into Embree: each distinct profile once, as a
// revolve Shape + Geometry (or a tessellated mesh, or Embree's own linear cone curve) in a scene of its own, instanced
// into a flat top-level scene under each object's transform; quads as top-level triangles. Hits come back in world
// space with their object's index, a smooth shading normal, and what is needed to spawn secondary rays without
// re-hitting the surface. Shared by the applications that trace scenes.
//
// Object ids: the instance of objects[i] is attached under geometry id i, so Embree's instID is the
// scene's object index; the quads are one triangle geometry under id objects.size().
#pragma once

#include "embree/embree_handles.h"
#include "io/scene_file.h"

#include <revolve/revolve.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace revolve::scene {

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

struct WorldHit {
  float t = 0;
  Vec3 point{};            // world position of the hit
  Vec3 geometricNormal{};  // world, unit; the surface's own side (not flipped towards the ray)
  Vec3 shadingNormal{};    // world, unit, on the geometric normal's side
  std::uint32_t material = 0;
  std::uint32_t object = 0;  // index into objects, or objects.size() + quad index
  // For spawning rays (EmbreeScene::spawn): the world ray and, for exact surfaces, the extra
  // error of the instance transform; for triangles, the point's per-axis error bound.
  bool exactSurface = false;
  Ray ray{};
  float transformError = 0;
  Vec3 pointError{};
};

// The nearest hit's distance and object only: what a range-finder needs, without the normals and
// surface parameters WorldHit carries.
struct RangeHit {
  float t = 0;
  std::uint32_t object = 0;  // index into objects, or objects.size() + quad index
};

class EmbreeScene {
 public:
  EmbreeScene(const io::SceneDescription& description, const BuildSettings& settings);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Rays that break Embree's contract (common/ray_limits.h) are not traced: they miss, and are
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
  std::int64_t embreeBytes() const noexcept;  // Embree's own allocations now (its memory monitor)
  std::int64_t embreePeakBytes() const noexcept;
  double buildSeconds() const noexcept { return buildSeconds_; }
  std::size_t prototypeCount() const noexcept { return prototypes_.size(); }

  struct Prototype;
  struct Instance;

 private:
  std::optional<WorldHit> instanceHit(const Ray& ray, const RTCRayHit& rayHit) const noexcept;
  std::optional<WorldHit> quadHit(const Ray& ray, const RTCRayHit& rayHit) const noexcept;
  // The packet of rays[i] set up and traced: lanes that are not traced come back without a hit
  // (geomID invalid); lengths[i] is what the lane's t is to be divided by (unit directions).
  void tracePacket(std::span<const Ray> rays, RTCRayHit8& packet, float (&lengths)[kPacketRays]) const noexcept;

  struct MemoryCounter {
    std::atomic<std::int64_t> current{0}, peak{0};
  };
  std::unique_ptr<MemoryCounter> memory_;  // outlives the device, which reports to it
  std::unique_ptr<std::atomic<std::uint64_t>> refused_ = std::make_unique<std::atomic<std::uint64_t>>(0);
  app::Device device_;
  std::vector<std::unique_ptr<Prototype>> prototypes_;
  std::vector<Instance> instances_;
  std::vector<Vec3> quadVertices_;  // 4 per quad, world space
  std::vector<std::uint32_t> quadMaterials_;
  app::Scene top_;
  double buildSeconds_ = 0;
  bool unitDirections_ = false;  // Embree's cone curves need them
};

}  // namespace revolve::scene
