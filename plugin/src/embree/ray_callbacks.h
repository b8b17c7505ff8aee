// Embree's intersect and occluded callbacks for a revolve::Geometry: packets of 1, 4, 8 and 16
// rays with valid masks, filter functions, instance IDs. Compiled per instruction set (util/isa.h).
//
// User-geometry contract (the same in Embree 3.13 and 4.x): callbacks receive N = 1, 4, 8 or 16
// rays in SoA layout with a valid mask, rays already in object space for instanced geometry; on a
// hit they write tfar, Ng, u, v, primID, geomID and the instance ids, and nothing on a miss;
// occluded writes tfar = -inf. Embree never calls filter functions for user geometry itself, so
// the callbacks offer each candidate to them (embree/query_filters.h).
#pragma once

#include "embree/payload.h"
#include "embree/query_filters.h"
#include "kernel/meridian_rays.h"
#include "shape/shape_search.h"
#include "shape/surface_hit.h"
#include "util/isa.h"

#include <limits>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

[[gnu::always_inline]] inline Ray laneRay(RTCRayN* rays, unsigned N, unsigned i) noexcept {
  return {{RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i)},
          {RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i)},
          RTCRayN_tnear(rays, N, i),
          RTCRayN_tfar(rays, N, i)};
}

inline RTCHit embreeHit(const Hit& hit, unsigned geomID, const embree::QueryContext* context) noexcept {
  RTCHit out{};
  out.Ng_x = hit.normal.x;
  out.Ng_y = hit.normal.y;
  out.Ng_z = hit.normal.z;
  out.u = hit.u;
  out.v = hit.v;
  out.primID = hit.segment;  // the profile segment, as documented in revolve.h
  out.geomID = geomID;
  recordInstance(out, context);
  return out;
}

// A one-lane view for a filter call: a valid mask with only lane i on, and an N-wide hit buffer.
struct FilterLane {
  alignas(64) int valid[16] = {};
  alignas(64) float hit[16 * sizeof(RTCHit) / sizeof(float)];  // RTCHitN with stride N <= 16
  RTCHitN* hits() noexcept { return reinterpret_cast<RTCHitN*>(hit); }
};

// Visits candidate hits of lane i in search order and offers each one, nearest first within a
// segment, to the intersection filters; an accepted one becomes the lane's hit and lowers hi.
template <bool kCount, bool kCurve>
struct FilteredNearest {
  const RTCIntersectFunctionNArguments* args;
  const GeometryPayload& payload;
  const ShapeImpl& shape;
  const MeridianRay& ray;
  const Ray& caller;
  unsigned lane;
  double& hi;
  Stats& stats;
  const double leafHi = hi;

  std::uint32_t acceptedSegment = 0xffffffffu;

  // Candidates are offered nearest first within a segment; across segments, as in NearestHit, a
  // candidate must beat the accepted hit in (s, segment) order, so ties go to the lower segment.
  bool operator()(std::uint32_t k) noexcept {
    const auto hits = leafHits<kCurve, kCount>(shape, ray, k, leafHi, stats);
    for (int j = 0; j < hits.count; ++j) {
      if (hits.s[j] > hi || (hits.s[j] == hi && k >= acceptedSegment)) break;
      if (offer(leafSurfaceHit<kCurve>(shape, ray, caller, hits.s[j], k, leafParameter(hits, j)))) {
        hi = hits.s[j];
        acceptedSegment = k;
        break;
      }
    }
    return false;
  }

  bool offer(const Hit& hit) noexcept {
    const unsigned N = args->N;
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
    FilterLane view;
    view.valid[lane] = -1;
    const RTCHit candidate = embreeHit(hit, args->geomID, args->context);
    rtcCopyHitToHitN(view.hits(), &candidate, N, lane);
    float& tfar = RTCRayN_tfar(rays, N, lane);
    const float previous = tfar;
    tfar = hit.t;  // the filter sees the candidate's distance
    const RTCFilterFunctionNArguments filter{view.valid, args->geometryUserPtr, args->context, rays, view.hits(), N};
    offerToIntersectFilters(args, &filter, payload, lane);
    if (view.valid[lane] != -1) {
      tfar = previous;
      return false;
    }
    const RTCHit accepted = rtcGetHitFromHitN(view.hits(), N, lane);  // the filter may have edited it
    rtcCopyHitToHitN(RTCRayHitN_HitN(args->rayhit, N), &accepted, N, lane);
    return true;
  }
};

template <bool kCount, bool kCurve>
struct FilteredAny {
  const RTCOccludedFunctionNArguments* args;
  const GeometryPayload& payload;
  const ShapeImpl& shape;
  const MeridianRay& ray;
  const Ray& caller;
  unsigned lane;
  Stats& stats;
  bool found = false;

  bool operator()(std::uint32_t k) noexcept {
    const auto hits = leafHits<kCurve, kCount>(shape, ray, k, ray.hi, stats);
    for (int j = 0; j < hits.count && !found; ++j) {
      found = offer(leafSurfaceHit<kCurve>(shape, ray, caller, hits.s[j], k, leafParameter(hits, j)));
    }
    return found;
  }

  bool offer(const Hit& hit) noexcept {
    const unsigned N = args->N;
    FilterLane view;
    view.valid[lane] = -1;
    const RTCHit candidate = embreeHit(hit, args->geomID, args->context);
    rtcCopyHitToHitN(view.hits(), &candidate, N, lane);
    float& tfar = RTCRayN_tfar(args->ray, N, lane);
    const float previous = tfar;
    tfar = hit.t;
    const RTCFilterFunctionNArguments filter{view.valid, args->geometryUserPtr, args->context,
                                             args->ray,  view.hits(),           N};
    offerToOcclusionFilters(args, &filter, payload, lane);
    tfar = previous;  // the caller sets -inf on acceptance
    return view.valid[lane] == -1;
  }
};

// The nearest hit of lane i, its MeridianRay set up, written into the packet.
template <bool kCount, bool kCurve>
inline void intersectLane(const RTCIntersectFunctionNArguments* args, const GeometryPayload& payload, bool filtered,
                          const MeridianRay& meridian, unsigned i, Stats& stats) noexcept {
  const ShapeImpl& shape = *payload.shape;
  const unsigned N = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  const Ray ray = laneRay(rays, N, i);
  double hi = meridian.hi;
  if (filtered) {
    FilteredNearest<kCount, kCurve> visitor{args, payload, shape, meridian, ray, i, hi, stats};
    searchShape<kCount>(shape, meridian, hi, visitor, stats);
    return;
  }
  NearestHit<kCount, kCurve> nearest{shape, meridian, hi, stats};
  searchShape<kCount>(shape, meridian, hi, nearest, stats);
  if (!nearest.found()) return;
  const Hit hit = leafSurfaceHit<kCurve>(shape, meridian, ray, nearest.s, nearest.segment, nearest.u);
  const RTCHit out = embreeHit(hit, args->geomID, args->context);
  RTCRayN_tfar(rays, N, i) = hit.t;
  rtcCopyHitToHitN(RTCRayHitN_HitN(args->rayhit, N), &out, N, i);
}

// The packet's lanes as setUpMeridianRays reads them, from lane `first` on.
inline RayLanes rayLanes(RTCRayN* rays, unsigned N, unsigned first) noexcept {
  return {&RTCRayN_org_x(rays, N, first), &RTCRayN_org_y(rays, N, first), &RTCRayN_org_z(rays, N, first),
          &RTCRayN_dir_x(rays, N, first), &RTCRayN_dir_y(rays, N, first), &RTCRayN_dir_z(rays, N, first),
          &RTCRayN_tnear(rays, N, first), &RTCRayN_tfar(rays, N, first)};
}

// Writes a hit into lane i of the packet.
inline void writeHit(const RTCIntersectFunctionNArguments* args, unsigned i, float t, float nx, float ny, float nz,
                     float u, float v, std::uint32_t segment) noexcept {
  const unsigned N = args->N;
  RTCRayN_tfar(RTCRayHitN_RayN(args->rayhit, N), N, i) = t;
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, N);
  RTCHitN_Ng_x(hits, N, i) = nx;
  RTCHitN_Ng_y(hits, N, i) = ny;
  RTCHitN_Ng_z(hits, N, i) = nz;
  RTCHitN_u(hits, N, i) = u;
  RTCHitN_v(hits, N, i) = v;
  RTCHitN_primID(hits, N, i) = segment;  // the profile segment, as documented in revolve.h
  RTCHitN_geomID(hits, N, i) = args->geomID;
  recordInstance(hits, N, i, args->context);
}

// A packet: the lanes set up kLanes at a time, searched one by one, and their hits' attributes
// computed kLanes at a time (surfaceHitLanes, equal to surfaceHit bit for bit; spline shapes' one
// at a time). kAttributes: which attributes unfiltered hits carry (surface_hit.h); a filter is
// always offered every attribute, and the hit it accepts is written with every attribute.
template <bool kCount, bool kCurve, unsigned kAttributes>
inline void intersectPacket(const RTCIntersectFunctionNArguments* args, const GeometryPayload& payload, bool filtered,
                            Stats& stats) noexcept {
  const ShapeImpl& shape = *payload.shape;
  const unsigned N = args->N;  // 4, 8 or 16: a multiple of kLanes
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  MeridianRay meridians[16];
  struct Found {
    unsigned lane;
    double s;
    std::uint32_t segment;
    double u;
  };
  Found found[16];
  int foundCount = 0;
  for (unsigned first = 0; first < N; first += kLanes) {
    unsigned active = 0;
    for (int lane = 0; lane < kLanes; ++lane) active |= unsigned(args->valid[first + lane] == -1) << lane;
    if (active == 0) continue;
    if constexpr (kCount) stats.rays += unsigned(__builtin_popcount(active));
    active &= setUpMeridianRays(shape.frame, rayLanes(rays, N, first), &meridians[first]);
    for (; active != 0; active &= active - 1) {
      const unsigned i = first + unsigned(__builtin_ctz(active));
      if (filtered) {
        intersectLane<kCount, kCurve>(args, payload, true, meridians[i], i, stats);
        continue;
      }
      double hi = meridians[i].hi;
      NearestHit<kCount, kCurve> nearest{shape, meridians[i], hi, stats};
      searchShape<kCount>(shape, meridians[i], hi, nearest, stats);
      if (nearest.found()) found[foundCount++] = {i, nearest.s, nearest.segment, nearest.u};
    }
  }
  if constexpr (kCurve) {
    for (int j = 0; j < foundCount; ++j) {
      const Found& f = found[j];
      const Hit hit =
          curveSurfaceHit<kAttributes>(shape, meridians[f.lane], laneRay(rays, N, f.lane), f.s, f.segment, f.u);
      writeHit(args, f.lane, hit.t, hit.normal.x, hit.normal.y, hit.normal.z, hit.u, hit.v, hit.segment);
    }
    return;
  }
  for (int first = 0; first < foundCount; first += kLanes) {
    HitLanes in;
    for (int lane = 0; lane < kLanes; ++lane) {
      const Found& f = found[std::min(first + lane, foundCount - 1)];
      in.ray[lane] = &meridians[f.lane];
      in.s[lane] = f.s;
      in.segment[lane] = f.segment;
      in.tnear[lane] = RTCRayN_tnear(rays, N, f.lane);
      in.tfar[lane] = RTCRayN_tfar(rays, N, f.lane);
    }
    HitAttributes out{};
    const unsigned scaled = surfaceHitLanes<kAttributes>(shape, in, out);
    for (int lane = 0; lane < kLanes && first + lane < foundCount; ++lane) {
      const Found& f = found[first + lane];
      if ((scaled >> lane) & 1) {  // within 1e-154 of the axis: the scalar path's scaling
        const Hit hit = surfaceHit<kAttributes>(shape, meridians[f.lane], laneRay(rays, N, f.lane), f.s, f.segment);
        writeHit(args, f.lane, hit.t, hit.normal.x, hit.normal.y, hit.normal.z, hit.u, hit.v, hit.segment);
      } else {
        writeHit(args, f.lane, out.t[lane], out.nx[lane], out.ny[lane], out.nz[lane], out.u[lane], out.v[lane],
                 f.segment);
      }
    }
  }
}

// rtcIntersect1's case, without a filter: N = 1, where Embree's packet is exactly an RTCRayHit, so
// the fields are read and written directly rather than through the N-wide accessors.
template <bool kCount, bool kCurve, unsigned kAttributes>
inline void intersectOne(const RTCIntersectFunctionNArguments* args, const ShapeImpl& shape, Stats& stats) noexcept {
  RTCRayHit& rayHit = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  const Ray ray{{rayHit.ray.org_x, rayHit.ray.org_y, rayHit.ray.org_z},
                {rayHit.ray.dir_x, rayHit.ray.dir_y, rayHit.ray.dir_z},
                rayHit.ray.tnear,
                rayHit.ray.tfar};
  MeridianRay meridian;
  if (!setUpMeridianRay(shape.frame, ray, meridian)) return;
  double hi = meridian.hi;
  NearestHit<kCount, kCurve> nearest{shape, meridian, hi, stats};
  searchShape<kCount>(shape, meridian, hi, nearest, stats);
  if (!nearest.found()) return;
  const Hit hit = leafSurfaceHit<kCurve, kAttributes>(shape, meridian, ray, nearest.s, nearest.segment, nearest.u);
  rayHit.ray.tfar = hit.t;
  rayHit.hit.Ng_x = hit.normal.x;
  rayHit.hit.Ng_y = hit.normal.y;
  rayHit.hit.Ng_z = hit.normal.z;
  rayHit.hit.u = hit.u;
  rayHit.hit.v = hit.v;
  rayHit.hit.primID = hit.segment;  // the profile segment, as documented in revolve.h
  rayHit.hit.geomID = args->geomID;
  recordInstance(rayHit.hit, args->context);
}

template <bool kCount, bool kCurve, unsigned kAttributes>
void intersectWith(const RTCIntersectFunctionNArguments* args, GeometryPayload& payload) {
  const ShapeImpl& shape = *payload.shape;
  const bool filtered = intersectFiltered(args, payload);
  Stats stats;
  if (args->N == 1) {
    if (args->valid[0] == -1) {
      if constexpr (kCount) ++stats.rays;
      MeridianRay meridian;
      if (filtered) {
        if (setUpMeridianRay(shape.frame, laneRay(RTCRayHitN_RayN(args->rayhit, 1), 1, 0), meridian)) {
          intersectLane<kCount, kCurve>(args, payload, true, meridian, 0, stats);
        }
      } else {
        intersectOne<kCount, kCurve, kAttributes>(args, shape, stats);
      }
    }
  } else {
    intersectPacket<kCount, kCurve, kAttributes>(args, payload, filtered, stats);
  }
  if constexpr (kCount) payload.add(stats);
}

// kAttributes: Geometry::Options' normal and uv (kNormalAttribute | kUvAttribute for both), fixed
// when the geometry is created, so each choice is its own callback without a test per ray.
template <bool kCount, unsigned kAttributes>
void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  auto& payload = *static_cast<GeometryPayload*>(args->geometryUserPtr);
  if (payload.shape->curved()) {
    intersectWith<kCount, true, kAttributes>(args, payload);
  } else {
    intersectWith<kCount, false, kAttributes>(args, payload);
  }
}

template <bool kCount, bool kCurve>
void occludedWith(const RTCOccludedFunctionNArguments* args, GeometryPayload& payload) {
  const ShapeImpl& shape = *payload.shape;
  const unsigned N = args->N;
  const bool filtered = occlusionFiltered(args, payload);
  Stats stats;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    if constexpr (kCount) ++stats.rays;
    const Ray ray = laneRay(args->ray, N, i);
    MeridianRay meridian;
    if (!setUpMeridianRay(shape.frame, ray, meridian)) continue;
    double hi = meridian.hi;
    bool found;
    if (filtered) {
      FilteredAny<kCount, kCurve> visitor{args, payload, shape, meridian, ray, i, stats};
      searchShape<kCount>(shape, meridian, hi, visitor, stats);
      found = visitor.found;
    } else {
      AnyHit<kCount, kCurve> any{shape, meridian, stats};
      searchShape<kCount>(shape, meridian, hi, any, stats);
      found = any.found;
    }
    if (found) RTCRayN_tfar(args->ray, N, i) = -std::numeric_limits<float>::infinity();
  }
  if constexpr (kCount) payload.add(stats);
}

template <bool kCount>
void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  auto& payload = *static_cast<GeometryPayload*>(args->geometryUserPtr);
  if (payload.shape->curved()) {
    occludedWith<kCount, true>(args, payload);
  } else {
    occludedWith<kCount, false>(args, payload);
  }
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
