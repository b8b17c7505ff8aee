// Everything that calls Embree lives here, so that a port to Embree 4 is this one file's work.
//
// User-geometry contract (Embree 3.13): callbacks receive N = 1, 4, 8 or 16 rays in SoA layout with a
// valid mask, rays already in object space for instanced geometry; on a hit they write tfar, Ng,
// u, v, primID, geomID and instID[0], and nothing on a miss; occluded writes tfar = -inf. Embree
// never calls filter functions for user geometry itself, so the callbacks call rtcFilter* per
// candidate, passing the very `args` they received (Embree reads a hidden field behind it).
#include "queries.h"
#include "shape_search.h"
#include "surface_hit.h"
#include "tessellation.h"

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>

namespace revolve {

struct Geometry::Payload {
  const Shape::Impl* shape;  // the heap part of the Shape: it stays put when the Shape is moved
  bool intersectFilter = false;
  bool occlusionFilter = false;
  std::atomic<std::uint64_t> rays{0}, nodesVisited{0}, shellTests{0}, quadratics{0};

  void add(const Stats& stats) noexcept {
    rays.fetch_add(stats.rays, std::memory_order_relaxed);
    nodesVisited.fetch_add(stats.nodesVisited, std::memory_order_relaxed);
    shellTests.fetch_add(stats.shellTests, std::memory_order_relaxed);
    quadratics.fetch_add(stats.quadratics, std::memory_order_relaxed);
  }
};

namespace {

using detail::MeridianRay;

std::string deviceError(RTCDevice device) {
  return "Embree error " + std::to_string(static_cast<int>(rtcGetDeviceError(device)));
}

Ray laneRay(RTCRayN* rays, unsigned N, unsigned i) noexcept {
  return {{RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i)},
          {RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i)},
          RTCRayN_tnear(rays, N, i),
          RTCRayN_tfar(rays, N, i)};
}

RTCHit embreeHit(const Hit& hit, unsigned geomID, const RTCIntersectContext* context) noexcept {
  RTCHit out{};
  out.Ng_x = hit.normal.x;
  out.Ng_y = hit.normal.y;
  out.Ng_z = hit.normal.z;
  out.u = hit.u;
  out.v = hit.v;
  out.primID = hit.segment;  // the profile segment, as documented in revolve.h
  out.geomID = geomID;
  for (unsigned level = 0; level < RTC_MAX_INSTANCE_LEVEL_COUNT; ++level) out.instID[level] = context->instID[level];
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
template <bool kCount>
struct FilteredNearest {
  const RTCIntersectFunctionNArguments* args;
  const Shape::Impl& shape;
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
    const detail::SegmentHits hits = detail::hitsOfSegment<kCount>(shape, ray, k, leafHi, stats);
    for (int j = 0; j < hits.count; ++j) {
      if (hits.s[j] > hi || (hits.s[j] == hi && k >= acceptedSegment)) break;
      if (offer(detail::surfaceHit(shape, ray, caller, hits.s[j], k))) {
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
    RTCFilterFunctionNArguments filter{view.valid, args->geometryUserPtr, args->context, rays, view.hits(), N};
    rtcFilterIntersection(args, &filter);
    if (view.valid[lane] != -1) {
      tfar = previous;
      return false;
    }
    const RTCHit accepted = rtcGetHitFromHitN(view.hits(), N, lane);  // the filter may have edited it
    rtcCopyHitToHitN(RTCRayHitN_HitN(args->rayhit, N), &accepted, N, lane);
    return true;
  }
};

template <bool kCount>
struct FilteredAny {
  const RTCOccludedFunctionNArguments* args;
  const Shape::Impl& shape;
  const MeridianRay& ray;
  const Ray& caller;
  unsigned lane;
  Stats& stats;
  bool found = false;

  bool operator()(std::uint32_t k) noexcept {
    const detail::SegmentHits hits = detail::hitsOfSegment<kCount>(shape, ray, k, ray.hi, stats);
    for (int j = 0; j < hits.count && !found; ++j) found = offer(detail::surfaceHit(shape, ray, caller, hits.s[j], k));
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
    RTCFilterFunctionNArguments filter{view.valid, args->geometryUserPtr, args->context, args->ray, view.hits(), N};
    rtcFilterOcclusion(args, &filter);
    tfar = previous;  // the caller sets -inf on acceptance
    return view.valid[lane] == -1;
  }
};

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto& payload = *static_cast<const Geometry::Payload*>(args->geometryUserPtr);
  const Bounds b = payload.shape->bounds;
  RTCBounds& out = *args->bounds_o;
  out.lower_x = b.lower.x;
  out.lower_y = b.lower.y;
  out.lower_z = b.lower.z;
  out.upper_x = b.upper.x;
  out.upper_y = b.upper.y;
  out.upper_z = b.upper.z;
}

template <bool kCount>
void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  auto& payload = *static_cast<Geometry::Payload*>(args->geometryUserPtr);
  const Shape::Impl& shape = *payload.shape;
  const unsigned N = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, N);
  const bool filtered = payload.intersectFilter || args->context->filter != nullptr;
  Stats stats;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    if constexpr (kCount) ++stats.rays;
    const Ray ray = laneRay(rays, N, i);
    MeridianRay meridian;
    if (!detail::setUpMeridianRay(shape.frame, ray, meridian)) continue;
    double hi = meridian.hi;
    if (filtered) {
      FilteredNearest<kCount> visitor{args, shape, meridian, ray, i, hi, stats};
      detail::searchShape<kCount>(shape, meridian, hi, visitor, stats);
      continue;
    }
    detail::NearestHit<kCount> nearest{shape, meridian, hi, stats};
    detail::searchShape<kCount>(shape, meridian, hi, nearest, stats);
    if (!nearest.found()) continue;
    const Hit hit = detail::surfaceHit(shape, meridian, ray, nearest.s, nearest.segment);
    const RTCHit out = embreeHit(hit, args->geomID, args->context);
    RTCRayN_tfar(rays, N, i) = hit.t;
    rtcCopyHitToHitN(hits, &out, N, i);
  }
  if constexpr (kCount) payload.add(stats);
}

template <bool kCount>
void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  auto& payload = *static_cast<Geometry::Payload*>(args->geometryUserPtr);
  const Shape::Impl& shape = *payload.shape;
  const unsigned N = args->N;
  const bool filtered = payload.occlusionFilter || args->context->filter != nullptr;
  Stats stats;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    if constexpr (kCount) ++stats.rays;
    const Ray ray = laneRay(args->ray, N, i);
    MeridianRay meridian;
    if (!detail::setUpMeridianRay(shape.frame, ray, meridian)) continue;
    double hi = meridian.hi;
    bool found;
    if (filtered) {
      FilteredAny<kCount> visitor{args, shape, meridian, ray, i, stats};
      detail::searchShape<kCount>(shape, meridian, hi, visitor, stats);
      found = visitor.found;
    } else {
      detail::AnyHit<kCount> any{shape, meridian, stats};
      detail::searchShape<kCount>(shape, meridian, hi, any, stats);
      found = any.found;
    }
    if (found) RTCRayN_tfar(args->ray, N, i) = -std::numeric_limits<float>::infinity();
  }
  if constexpr (kCount) payload.add(stats);
}

// Point queries: Embree hands over the world-space query, the instance stack, and no
// geometry user data, so the caller's lookup names the Geometry.
struct PointQueryState {
  GeometryLookup lookup;
  void* user;
  std::optional<ScenePoint> best;
};

Vec3 transformPoint(const float m[16], Vec3 p) noexcept {  // column-major 4x4
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

float distanceBetween(Vec3 a, Vec3 b) noexcept {
  const double dx = double(a.x) - b.x, dy = double(a.y) - b.y, dz = double(a.z) - b.z;
  return float(std::sqrt(dx * dx + dy * dy + dz * dz));
}

bool pointQueryCallback(RTCPointQueryFunctionArguments* args) {
  auto& state = *static_cast<PointQueryState*>(args->userPtr);
  const RTCPointQueryContext& context = *args->context;
  const bool instanced = context.instStackSize > 0;
  const unsigned instID = instanced ? context.instID[0] : RTC_INVALID_GEOMETRY_ID;
  const Geometry* geometry = state.lookup(state.user, instID, args->geomID);
  if (geometry == nullptr) return false;
  const Shape::Impl& shape = *static_cast<const Geometry::Payload*>(rtcGetGeometryUserData(geometry->handle()))->shape;
  const Vec3 world{args->query->x, args->query->y, args->query->z};

  Vec3 point;
  float distance;
  std::uint32_t segment;
  if (!instanced) {
    const SurfacePoint closest = detail::closestSurfacePoint(shape, world);
    point = closest.point, distance = closest.distance, segment = closest.segment;
  } else {
    // Exact under a similarity transform (distances scale uniformly); under any other transform
    // the object-space closest point, carried to world space, is a surface point but may not be
    // the closest one.
    const float* toObject = context.world2inst[context.instStackSize - 1];
    const float* toWorld = context.inst2world[context.instStackSize - 1];
    const SurfacePoint closest = detail::closestSurfacePoint(shape, transformPoint(toObject, world));
    point = transformPoint(toWorld, closest.point);
    distance = args->similarityScale > 0.0f ? closest.distance / args->similarityScale : distanceBetween(point, world);
    segment = closest.segment;
  }
  if (!(distance < args->query->radius)) return false;
  args->query->radius = distance;
  state.best = ScenePoint{point, distance, args->geomID, instID, segment};
  return true;
}

}  // namespace

Geometry::Geometry(RTCDevice device, const Shape& shape, Options options)
    : payload_(std::make_unique<Payload>()) {
  payload_->shape = &shape.impl();
  geometry_ = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  if (geometry_ == nullptr) throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_USER) failed: " + deviceError(device));
  rtcSetGeometryUserPrimitiveCount(geometry_, 1);
  rtcSetGeometryUserData(geometry_, payload_.get());
  rtcSetGeometryBoundsFunction(geometry_, boundsCallback, nullptr);
  rtcSetGeometryIntersectFunction(geometry_, options.countStats ? intersectCallback<true> : intersectCallback<false>);
  rtcSetGeometryOccludedFunction(geometry_, options.countStats ? occludedCallback<true> : occludedCallback<false>);
  rtcCommitGeometry(geometry_);
}

Geometry::~Geometry() {
  if (geometry_ != nullptr) rtcReleaseGeometry(geometry_);
}


void Geometry::setIntersectFilter(RTCFilterFunctionN filter) noexcept {
  rtcSetGeometryIntersectFilterFunction(geometry_, filter);
  payload_->intersectFilter = filter != nullptr;
}

void Geometry::setOcclusionFilter(RTCFilterFunctionN filter) noexcept {
  rtcSetGeometryOccludedFilterFunction(geometry_, filter);
  payload_->occlusionFilter = filter != nullptr;
}

Stats Geometry::stats() const noexcept {
  Stats stats;
  stats.rays = payload_->rays.load(std::memory_order_relaxed);
  stats.nodesVisited = payload_->nodesVisited.load(std::memory_order_relaxed);
  stats.shellTests = payload_->shellTests.load(std::memory_order_relaxed);
  stats.quadratics = payload_->quadratics.load(std::memory_order_relaxed);
  return stats;
}

std::optional<ScenePoint> closestPoint(RTCScene scene, Vec3 p, float maxDistance, GeometryLookup lookup, void* user) {
  RTCPointQuery query;
  query.x = p.x;
  query.y = p.y;
  query.z = p.z;
  query.time = 0.0f;
  query.radius = maxDistance;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  PointQueryState state{lookup, user, std::nullopt};
  rtcPointQuery(scene, &query, &context, pointQueryCallback, &state);
  return state.best;
}

RTCGeometry newTessellatedGeometry(RTCDevice device, const Profile& profile, std::uint32_t slices) {
  const detail::TriangleMesh mesh = detail::tessellate(profile, slices);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (geometry == nullptr) {
    throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_TRIANGLE) failed: " + deviceError(device));
  }
  const std::size_t vertexCount = mesh.vertices.size() / 3, triangleCount = mesh.indices.size() / 3;
  void* vertices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                           3 * sizeof(float), vertexCount);
  void* indices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                          3 * sizeof(std::uint32_t), triangleCount);
  if (vertices == nullptr || indices == nullptr) {
    rtcReleaseGeometry(geometry);
    throw std::runtime_error("allocating a tessellated mesh of " + std::to_string(triangleCount) +
                             " triangles failed: " + deviceError(device));
  }
  std::memcpy(vertices, mesh.vertices.data(), mesh.vertices.size() * sizeof(float));
  std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  rtcCommitGeometry(geometry);
  return geometry;
}

}  // namespace revolve
