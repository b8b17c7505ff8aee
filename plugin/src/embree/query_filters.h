// What the user-geometry callbacks do differently under Embree 3 and Embree 4: the instance ids a
// hit records, and how a candidate hit reaches the filter functions. The library's one place that
// tests Embree's version below the public revolve/embree_api.h.
//
// Embree calls no filter function for a user geometry by itself: the callback must offer each
// candidate hit. Embree 3's rtcFilterIntersection / rtcFilterOcclusion call both the geometry's
// filter and the intersect context's. Embree 4's rtcInvokeIntersectFilterFromGeometry /
// rtcInvokeOccludedFilterFromGeometry call the geometry's only, and the query's argument filter
// (RTCIntersectArguments::filter) is out of the callback's reach through the documented API
// (upstream Embree issue 478, "filter functions are never called for user defined geometries
// automatically"). Embree's CPU code passes the callbacks an RTCIntersectFunctionNArguments that
// is the head of a larger record ending in the query's arguments (kernels/common/accelset.h, the
// same from Embree 4.0 to 4.4): revolve reads the arguments from there, after checking once per
// process with a probe ray that the field holds exactly the arguments the probe passed
// (argumentsReachable). Where it does not, argument filters are not called on revolve's shapes,
// and Geometry::argumentFiltersSupported says so.
#pragma once

#include <revolve/embree_api.h>

#include "embree/payload.h"

#include <atomic>
#include <cstddef>
#include <cstring>

// The functions the callbacks call on every ray are [[gnu::always_inline]]: they live outside the
// per-instruction-set namespace (util/isa.h), so a copy the compiler chose to keep out of line would
// be a weak symbol shared by the SSE2 and AVX2 objects, and the linker could hand the AVX2 one to a
// processor without AVX2 (tests/isa_symbols.sh; GCC 14 kept argumentFilter out of line).
namespace revolve::detail {

// Whether the callbacks may read the query's arguments behind their own (Embree 4); set once,
// before any revolve geometry exists, by Geometry's constructor through checkArgumentsReachable.
inline std::atomic<bool> argumentsReachable{REVOLVE_EMBREE_MAJOR == 3};

// Probes `device` the first time it is called in the process (Embree 4; Embree 3 needs no probe)
// and answers argumentsReachable. Thread-safe.
bool checkArgumentsReachable(RTCDevice device);

#if REVOLVE_EMBREE_MAJOR == 4

// The head of Embree 4's internal IntersectFunctionNArguments / OccludedFunctionNArguments.
template <class PublicArguments>
struct EmbreeCallbackRecord {
  PublicArguments head;
  void* geometry;
  RTCScene forwardScene;
  RTCIntersectArguments* arguments;  // the query's (an RTCOccludedArguments for occlusion: same head)
};

template <class PublicArguments>
[[gnu::always_inline]] inline const RTCIntersectArguments* queryArguments(const PublicArguments* args) noexcept {
  if (!argumentsReachable.load(std::memory_order_relaxed)) return nullptr;
  const RTCIntersectArguments* arguments;
  std::memcpy(&arguments,
              reinterpret_cast<const char*>(args) + offsetof(EmbreeCallbackRecord<PublicArguments>, arguments),
              sizeof arguments);
  return arguments;
}

// The argument filter Embree would call for a built-in geometry with this payload, or nullptr.
template <class PublicArguments>
[[gnu::always_inline]] inline RTCFilterFunctionN argumentFilter(const PublicArguments* args,
                                                                const GeometryPayload& payload) noexcept {
  const RTCIntersectArguments* arguments = queryArguments(args);
  if (arguments == nullptr || arguments->filter == nullptr) return nullptr;
  const bool forAll = (arguments->flags & RTC_RAY_QUERY_FLAG_INVOKE_ARGUMENT_FILTER) != 0;
  return forAll || payload.argumentFilter ? arguments->filter : nullptr;
}

[[gnu::always_inline]] inline bool intersectFiltered(const RTCIntersectFunctionNArguments* args,
                                                     const GeometryPayload& payload) noexcept {
  return payload.intersectFilter || argumentFilter(args, payload) != nullptr;
}
[[gnu::always_inline]] inline bool occlusionFiltered(const RTCOccludedFunctionNArguments* args,
                                                     const GeometryPayload& payload) noexcept {
  return payload.occlusionFilter || argumentFilter(args, payload) != nullptr;
}

// Embree's own switch for the geometry, so that Embree agrees on what it calls.
inline void enableArgumentFilter(RTCGeometry geometry, bool enable) noexcept {
  rtcSetGeometryEnableFilterFunctionFromArguments(geometry, enable);
}

// Offers the candidate in `filter` to the geometry's filter, then, if it is still valid, to the
// query's argument filter: Embree's own order for built-in geometries (kernels/geometry/filter.h).
[[gnu::always_inline]] inline void offerToIntersectFilters(const RTCIntersectFunctionNArguments* args,
                                                           const RTCFilterFunctionNArguments* filter,
                                                           const GeometryPayload& payload, unsigned lane) noexcept {
  if (payload.intersectFilter) {
    rtcInvokeIntersectFilterFromGeometry(args, filter);
    if (filter->valid[lane] == 0) return;
  }
  if (const RTCFilterFunctionN query = argumentFilter(args, payload)) query(filter);
}
[[gnu::always_inline]] inline void offerToOcclusionFilters(const RTCOccludedFunctionNArguments* args,
                                                           const RTCFilterFunctionNArguments* filter,
                                                           const GeometryPayload& payload, unsigned lane) noexcept {
  if (payload.occlusionFilter) {
    rtcInvokeOccludedFilterFromGeometry(args, filter);
    if (filter->valid[lane] == 0) return;
  }
  if (const RTCFilterFunctionN query = argumentFilter(args, payload)) query(filter);
}

#else  // Embree 3

// Embree 3 has no per-geometry switch: a context filter applies to every geometry.
inline void enableArgumentFilter(RTCGeometry, bool) noexcept {}

[[gnu::always_inline]] inline bool intersectFiltered(const RTCIntersectFunctionNArguments* args,
                                                     const GeometryPayload& payload) noexcept {
  return payload.intersectFilter || args->context->filter != nullptr;
}
[[gnu::always_inline]] inline bool occlusionFiltered(const RTCOccludedFunctionNArguments* args,
                                                     const GeometryPayload& payload) noexcept {
  return payload.occlusionFilter || args->context->filter != nullptr;
}
// Embree 3 calls the geometry's filter, then the context's (passing it the very `args` the callback
// received: Embree reads a hidden field behind it).
[[gnu::always_inline]] inline void offerToIntersectFilters(const RTCIntersectFunctionNArguments* args,
                                                           const RTCFilterFunctionNArguments* filter,
                                                           const GeometryPayload&, unsigned) noexcept {
  rtcFilterIntersection(args, filter);
}
[[gnu::always_inline]] inline void offerToOcclusionFilters(const RTCOccludedFunctionNArguments* args,
                                                           const RTCFilterFunctionNArguments* filter,
                                                           const GeometryPayload&, unsigned) noexcept {
  rtcFilterOcclusion(args, filter);
}

#endif

// The query context's instance stack, recorded in a hit (Embree 4 built with instance arrays also
// has instPrimID).
[[gnu::always_inline]] inline void recordInstance(RTCHit& hit, const embree::QueryContext* context) noexcept {
  for (unsigned level = 0; level < RTC_MAX_INSTANCE_LEVEL_COUNT; ++level) {
    hit.instID[level] = context->instID[level];
#if defined(RTC_GEOMETRY_INSTANCE_ARRAY)
    hit.instPrimID[level] = context->instPrimID[level];
#endif
  }
}
[[gnu::always_inline]] inline void recordInstance(RTCHitN* hits, unsigned N, unsigned i,
                                                  const embree::QueryContext* context) noexcept {
  for (unsigned level = 0; level < RTC_MAX_INSTANCE_LEVEL_COUNT; ++level) {
    RTCHitN_instID(hits, N, i, level) = context->instID[level];
#if defined(RTC_GEOMETRY_INSTANCE_ARRAY)
    RTCHitN_instPrimID(hits, N, i, level) = context->instPrimID[level];
#endif
  }
}

}  // namespace revolve::detail
