// Embree 3 or Embree 4, whichever revolve was built with (revolve/config.h), behind one small API.
//
// This is the one public place that names Embree's header or tests its version. revolve/embree.h
// includes it; revolve's own tools, tests and benchmarks trace through RayQuery so that one code
// base builds against either Embree. An application written for one Embree can just as well call
// that Embree's own API on revolve's geometries (revolve/embree.h says what each version gives).
#pragma once

#include <revolve/config.h>

#if REVOLVE_EMBREE_MAJOR == 4
#include <embree4/rtcore.h>
#elif REVOLVE_EMBREE_MAJOR == 3
#include <embree3/rtcore.h>
#else
#error "revolve/config.h names no Embree major version revolve supports (3 or 4)"
#endif

namespace revolve::embree {

inline constexpr int kMajorVersion = REVOLVE_EMBREE_MAJOR;

#if REVOLVE_EMBREE_MAJOR == 4
// What geometry callbacks and filter functions receive as `context`.
using QueryContext = RTCRayQueryContext;
// The scene flag a scene needs before a query may carry its own filter function.
inline constexpr RTCSceneFlags kQueryFilterSceneFlag = RTC_SCENE_FLAG_FILTER_FUNCTION_IN_ARGUMENTS;
#else
using QueryContext = RTCIntersectContext;
inline constexpr RTCSceneFlags kQueryFilterSceneFlag = RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION;
#endif

struct QueryOptions {
  // A filter function offered the candidate hits of every geometry in the scene, after the
  // geometry's own filter: Embree 4's argument filter with RTC_RAY_QUERY_FLAG_INVOKE_ARGUMENT_FILTER,
  // Embree 3's context filter. The scene must have kQueryFilterSceneFlag. nullptr: none.
  RTCFilterFunctionN filter = nullptr;
  // Rays of one query are coherent (neighbouring camera rays): RTC_RAY_QUERY_FLAG_COHERENT /
  // RTC_INTERSECT_CONTEXT_FLAG_COHERENT.
  bool coherent = false;
};

// One query's context and arguments, reusable for any number of rays on one thread. Not copyable:
// Embree 4's arguments point at the context inside it.
class RayQuery {
 public:
  explicit RayQuery(const QueryOptions& options = {}) noexcept {
#if REVOLVE_EMBREE_MAJOR == 4
    rtcInitRayQueryContext(&context_);
    rtcInitIntersectArguments(&intersect_);
    rtcInitOccludedArguments(&occluded_);
    const RTCRayQueryFlags flags = RTCRayQueryFlags(
        (options.coherent ? RTC_RAY_QUERY_FLAG_COHERENT : RTC_RAY_QUERY_FLAG_INCOHERENT) |
        (options.filter != nullptr ? RTC_RAY_QUERY_FLAG_INVOKE_ARGUMENT_FILTER : RTC_RAY_QUERY_FLAG_NONE));
    intersect_.flags = occluded_.flags = flags;
    intersect_.context = occluded_.context = &context_;
    intersect_.filter = occluded_.filter = options.filter;
#else
    rtcInitIntersectContext(&context_);
    context_.flags = options.coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    context_.filter = options.filter;
#endif
  }
  RayQuery(const RayQuery&) = delete;
  RayQuery& operator=(const RayQuery&) = delete;

#if REVOLVE_EMBREE_MAJOR == 4
  void intersect(RTCScene scene, RTCRayHit& rayHit) noexcept { rtcIntersect1(scene, &rayHit, &intersect_); }
  void intersect(const int* valid, RTCScene scene, RTCRayHit4& rayHit) noexcept {
    rtcIntersect4(valid, scene, &rayHit, &intersect_);
  }
  void intersect(const int* valid, RTCScene scene, RTCRayHit8& rayHit) noexcept {
    rtcIntersect8(valid, scene, &rayHit, &intersect_);
  }
  void intersect(const int* valid, RTCScene scene, RTCRayHit16& rayHit) noexcept {
    rtcIntersect16(valid, scene, &rayHit, &intersect_);
  }
  void occluded(RTCScene scene, RTCRay& ray) noexcept { rtcOccluded1(scene, &ray, &occluded_); }
  void occluded(const int* valid, RTCScene scene, RTCRay4& ray) noexcept {
    rtcOccluded4(valid, scene, &ray, &occluded_);
  }
  void occluded(const int* valid, RTCScene scene, RTCRay8& ray) noexcept {
    rtcOccluded8(valid, scene, &ray, &occluded_);
  }
  void occluded(const int* valid, RTCScene scene, RTCRay16& ray) noexcept {
    rtcOccluded16(valid, scene, &ray, &occluded_);
  }
#else
  void intersect(RTCScene scene, RTCRayHit& rayHit) noexcept { rtcIntersect1(scene, &context_, &rayHit); }
  void intersect(const int* valid, RTCScene scene, RTCRayHit4& rayHit) noexcept {
    rtcIntersect4(valid, scene, &context_, &rayHit);
  }
  void intersect(const int* valid, RTCScene scene, RTCRayHit8& rayHit) noexcept {
    rtcIntersect8(valid, scene, &context_, &rayHit);
  }
  void intersect(const int* valid, RTCScene scene, RTCRayHit16& rayHit) noexcept {
    rtcIntersect16(valid, scene, &context_, &rayHit);
  }
  void occluded(RTCScene scene, RTCRay& ray) noexcept { rtcOccluded1(scene, &context_, &ray); }
  void occluded(const int* valid, RTCScene scene, RTCRay4& ray) noexcept {
    rtcOccluded4(valid, scene, &context_, &ray);
  }
  void occluded(const int* valid, RTCScene scene, RTCRay8& ray) noexcept {
    rtcOccluded8(valid, scene, &context_, &ray);
  }
  void occluded(const int* valid, RTCScene scene, RTCRay16& ray) noexcept {
    rtcOccluded16(valid, scene, &context_, &ray);
  }
#endif

 private:
  QueryContext context_;
#if REVOLVE_EMBREE_MAJOR == 4
  RTCIntersectArguments intersect_;
  RTCOccludedArguments occluded_;
#endif
};

// Embree's ray for revolve's conventions: every mask bit set, no hit yet (no geometry, no
// instance, as Embree requires before a query).
inline RTCRayHit newRayHit(float ox, float oy, float oz, float dx, float dy, float dz, float tnear,
                           float tfar) noexcept {
  RTCRayHit rayHit{};
  rayHit.ray.org_x = ox;
  rayHit.ray.org_y = oy;
  rayHit.ray.org_z = oz;
  rayHit.ray.dir_x = dx;
  rayHit.ray.dir_y = dy;
  rayHit.ray.dir_z = dz;
  rayHit.ray.tnear = tnear;
  rayHit.ray.tfar = tfar;
  rayHit.ray.mask = ~0u;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  for (unsigned level = 0; level < RTC_MAX_INSTANCE_LEVEL_COUNT; ++level)
    rayHit.hit.instID[level] = RTC_INVALID_GEOMETRY_ID;
  return rayHit;
}

}  // namespace revolve::embree
