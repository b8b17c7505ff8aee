// revolve's Embree glue: a Shape as an Embree user geometry, and point queries over Embree scenes.
// (Embree's own primitives for comparison, a tessellated mesh and a linear cone curve, are in
// revolve/embree_baselines.h.)
//
// Built against Embree 3 or Embree 4 (revolve/config.h says which); revolve/embree_api.h includes
// that Embree's header. The answers are the same with either: the callbacks run the same search.
#pragma once

#include <revolve/core.h>
#include <revolve/embree_api.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace revolve {

namespace detail {
struct GeometryPayload;  // what the callbacks receive as user data: private to the library
}  // namespace detail

// An Embree user geometry that traces a Shape: bounds, intersect and occluded callbacks for
// packets of 1, 4, 8 and 16 rays, filter functions, instancing and point queries. Create it,
// attach handle() to a scene (rtcAttachGeometry), and keep both the Geometry and the Shape alive
// while any scene holding the geometry is used (moving the Shape is fine; destroying it is not).
// One Shape may back any number of Geometries, and a scene holding a Geometry may be instanced any
// number of times (one instance level). A Geometry owns its Embree handle: moving it moves the
// handle, destroying it releases it (a scene it is attached to keeps its own reference).
//
// A hit writes tfar, Ng, u, v, primID (the profile segment, see Conventions), geomID, and the
// query context's instID (and instPrimID, with an Embree 4 built with instance arrays).
// Where a placed Geometry puts its shape: world = linear * object + translate (linear row by row,
// finite and invertible).
struct Placement {
  double linear[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double translate[3] = {0, 0, 0};
};

class Geometry {
 public:
  struct Options {
    bool countStats = false;  // accumulate Stats (slower); read them with stats()
    // Lean hits: which of a hit's attributes rtcIntersect* computes. With `normal` off Ng is written
    // as (0, 0, 0), with `uv` off u and v as 0; tfar, primID, geomID and the instance ids always.
    // Embree reads none of Ng, u, v of a user geometry's hit: they are the caller's. Turning them
    // off saves their cost a hit (for a caller that needs only the distance, or needs them for a
    // few hits: revolve::surfaceAttributes computes them afterwards, equal bit for bit to what the
    // callback would have written). A filter function is always offered every attribute, and a
    // hit a filter accepted is written with every attribute. rtcOccluded* computes none anyway.
    bool normal = true;
    bool uv = true;
  };
  // Throws std::runtime_error, with Embree's error code, when Embree cannot create the geometry.
  Geometry(RTCDevice device, const Shape& shape, Options options);
  Geometry(RTCDevice device, const Shape& shape) : Geometry(device, shape, Options{}) {}
  // The shape placed in the scene it is attached to, without an Embree instance: the callbacks map
  // each ray into object space themselves (in double, rounded once to float, where an instance
  // maps it in float) and report Ng in object space, u, v and primID as an instanced geometry
  // does; geomID is this geometry's and instID is left as the query context's. Bounds and point
  // queries are the placed shape's. What it saves is the instance's own scene (about 4 KB of
  // Embree's memory and 12 microseconds of building an object, measured with Embree 3.13) and
  // each ray's second traversal: a scene of many distinct shapes wants one per object. Throws
  // std::invalid_argument for a placement that is not finite or whose linear part is singular.
  Geometry(RTCDevice device, const Shape& shape, const Placement& placement, Options options);
  ~Geometry();
  Geometry(Geometry&& other) noexcept;
  Geometry& operator=(Geometry&& other) noexcept;
  Geometry(const Geometry&) = delete;
  Geometry& operator=(const Geometry&) = delete;

  [[nodiscard]] RTCGeometry handle() const noexcept { return geometry_; }

  // Filter functions. Set the geometry's own through these (not rtcSetGeometry*FilterFunction
  // directly): a user geometry's callback must offer each candidate hit to the filters itself, and
  // does so only when one may apply, so revolve needs to know. Pass nullptr to remove a filter.
  // Commit the geometry afterwards.
  void setIntersectFilter(RTCFilterFunctionN filter) noexcept;
  void setOcclusionFilter(RTCFilterFunctionN filter) noexcept;
  // Filter functions passed with a query. Embree 3 calls a context's filter for every geometry
  // (with RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION on the scene); revolve's callbacks do the same.
  // Embree 4 calls an argument filter (RTC_SCENE_FLAG_FILTER_FUNCTION_IN_ARGUMENTS on the scene)
  // for the geometries enabled by rtcSetGeometryEnableFilterFunctionFromArguments, or for all with
  // RTC_RAY_QUERY_FLAG_INVOKE_ARGUMENT_FILTER, but never for user geometries by itself; revolve's
  // callbacks call it as Embree does for a triangle mesh, after the geometry's own filter. Enable
  // it for this geometry through this call (it also makes Embree's call); no effect with Embree 3.
  void enableFilterFunctionFromArguments(bool enable) noexcept;
  // Whether the callbacks can reach a query's argument filter (Embree 4): checked once per process
  // by tracing one probe ray; false means argument filters are not called on revolve's geometries
  // with this Embree build. Always true with Embree 3.
  [[nodiscard]] static bool argumentFiltersSupported(RTCDevice device);

  [[nodiscard]] Stats stats() const noexcept;  // zero unless Options::countStats
  // What revolve keeps for this geometry beside Embree's own object and the Shape.
  [[nodiscard]] std::size_t memoryBytes() const noexcept;

 private:
  RTCGeometry geometry_ = nullptr;
  std::unique_ptr<detail::GeometryPayload> payload_;  // Embree's user data: stays put when moved
};

// Closest surface point over an Embree scene (rtcPointQuery), for SoR geometries and instances
// of scenes holding them. `shapeOf` maps (instID, geomID) to the Geometry that was attached under
// that geomID in the scene that instance instID shows (instID is RTC_INVALID_GEOMETRY_ID for
// geometries attached to `scene` itself); return nullptr for geometries to skip.
struct ScenePoint {
  Vec3 point;  // world space
  float distance;
  unsigned geomID;
  unsigned instID;  // RTC_INVALID_GEOMETRY_ID when not instanced
  std::uint32_t segment;
};
using GeometryLookup = const Geometry* (*)(void* user, unsigned instID, unsigned geomID);
[[nodiscard]] std::optional<ScenePoint> closestPoint(RTCScene scene, Vec3 p, float maxDistance, GeometryLookup lookup,
                                                     void* user);

}  // namespace revolve
