// Embree objects: the user geometry, filters, point queries, the tessellated mesh and Embree's own
// cone curve. The per-ray callbacks are in ray_callbacks.h (compiled per instruction set), and what
// differs between Embree 3 and 4 in query_filters.h and revolve/embree_api.h.
#include <revolve/embree_baselines.h>
#include "embree/callback_kernels.h"
#include "embree/cone_curve.h"
#include "embree/payload.h"
#include "embree/placed_callbacks.h"
#include "embree/query_filters.h"
#include "embree/tessellation.h"
#include "shape/queries.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace revolve {

namespace {

std::string deviceError(RTCDevice device) {
  return "Embree error " + std::to_string(static_cast<int>(rtcGetDeviceError(device)));
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto& payload = *static_cast<const detail::GeometryPayload*>(args->geometryUserPtr);
  const Bounds b = payload.shape->bounds;
  RTCBounds& out = *args->bounds_o;
  out.lower_x = b.lower.x;
  out.lower_y = b.lower.y;
  out.lower_z = b.lower.z;
  out.upper_x = b.upper.x;
  out.upper_y = b.upper.y;
  out.upper_z = b.upper.z;
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
  const detail::ShapeImpl& shape =
      *static_cast<const detail::GeometryPayload*>(rtcGetGeometryUserData(geometry->handle()))->shape;
  const Vec3 world{args->query->x, args->query->y, args->query->z};

  Vec3 point;
  float distance;
  std::uint32_t segment;
  const auto& payload = *static_cast<const detail::GeometryPayload*>(rtcGetGeometryUserData(geometry->handle()));
  if (payload.placement) {
    // Placed by the geometry itself (and perhaps instanced as well): as for an instance, the
    // closest point in object space carried to world space (the closest one under a similarity
    // transform), its distance measured there.
    const int level = int(context.instStackSize) - 1;
    const Vec3 inScene = instanced ? transformPoint(context.world2inst[level], world) : world;
    const SurfacePoint closest = detail::closestSurfacePoint(shape, detail::toObjectSpace(*payload.placement, inScene));
    const Vec3 placed = detail::toWorldSpace(*payload.placement, closest.point);
    point = instanced ? transformPoint(context.inst2world[level], placed) : placed;
    distance = distanceBetween(point, world);
    segment = closest.segment;
  } else if (!instanced) {
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
    : payload_(std::make_unique<detail::GeometryPayload>()) {
  payload_->shape = &detail::implOf(shape);
  // Before the first revolve geometry can be traced: whether argument filters can be reached.
  detail::checkArgumentsReachable(device);
  geometry_ = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  if (geometry_ == nullptr)
    throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_USER) failed: " + deviceError(device));
  rtcSetGeometryUserPrimitiveCount(geometry_, 1);
  rtcSetGeometryUserData(geometry_, payload_.get());
  rtcSetGeometryBoundsFunction(geometry_, boundsCallback, nullptr);
  const detail::CallbackKernels& kernels = detail::callbackKernels();
  const unsigned attributes = (options.normal ? 1u : 0u) | (options.uv ? 2u : 0u);  // CallbackKernels' order
  rtcSetGeometryIntersectFunction(geometry_, kernels.intersect[options.countStats][attributes]);
  rtcSetGeometryOccludedFunction(geometry_, kernels.occluded[options.countStats]);
  rtcCommitGeometry(geometry_);
}

Geometry::Geometry(RTCDevice device, const Shape& shape, const Placement& placement, Options options)
    : Geometry(device, shape, options) {
  payload_->placement = std::make_unique<detail::PlacementMaps>(detail::placementMaps(placement));
  const detail::CallbackKernels& kernels = detail::callbackKernels();
  const unsigned attributes = (options.normal ? 1u : 0u) | (options.uv ? 2u : 0u);  // CallbackKernels' order
  payload_->objectIntersect = kernels.intersect[options.countStats][attributes];
  payload_->objectOccluded = kernels.occluded[options.countStats];
  rtcSetGeometryBoundsFunction(geometry_, detail::placedBoundsCallback, nullptr);
  rtcSetGeometryIntersectFunction(geometry_, detail::placedIntersectCallback);
  rtcSetGeometryOccludedFunction(geometry_, detail::placedOccludedCallback);
  rtcCommitGeometry(geometry_);
}

Geometry::~Geometry() {
  if (geometry_ != nullptr) rtcReleaseGeometry(geometry_);
}

Geometry::Geometry(Geometry&& other) noexcept
    : geometry_(std::exchange(other.geometry_, nullptr)), payload_(std::move(other.payload_)) {}

Geometry& Geometry::operator=(Geometry&& other) noexcept {
  if (this != &other) {
    if (geometry_ != nullptr) rtcReleaseGeometry(geometry_);
    geometry_ = std::exchange(other.geometry_, nullptr);
    payload_ = std::move(other.payload_);
  }
  return *this;
}

void Geometry::setIntersectFilter(RTCFilterFunctionN filter) noexcept {
  rtcSetGeometryIntersectFilterFunction(geometry_, filter);
  payload_->intersectFilter = filter != nullptr;
}

void Geometry::setOcclusionFilter(RTCFilterFunctionN filter) noexcept {
  rtcSetGeometryOccludedFilterFunction(geometry_, filter);
  payload_->occlusionFilter = filter != nullptr;
}

void Geometry::enableFilterFunctionFromArguments(bool enable) noexcept {
  detail::enableArgumentFilter(geometry_, enable);
  payload_->argumentFilter = enable;
}

bool Geometry::argumentFiltersSupported(RTCDevice device) { return detail::checkArgumentsReachable(device); }

Stats Geometry::stats() const noexcept {
  Stats stats;
  stats.rays = payload_->rays.load(std::memory_order_relaxed);
  stats.nodesVisited = payload_->nodesVisited.load(std::memory_order_relaxed);
  stats.shellTests = payload_->shellTests.load(std::memory_order_relaxed);
  stats.quadratics = payload_->quadratics.load(std::memory_order_relaxed);
  return stats;
}

std::size_t Geometry::memoryBytes() const noexcept {
  return payload_ ? sizeof(detail::GeometryPayload) + (payload_->placement ? sizeof(detail::PlacementMaps) : 0) : 0;
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
  void* vertices =
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount);
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

std::optional<std::string> coneCurveLimitation(const Profile& profile, std::string_view pointName) {
  auto layout = detail::layOutConeCurve(profile, pointName);
  if (auto* reason = std::get_if<std::string>(&layout)) return std::move(*reason);
  return std::nullopt;
}

ConeCurveGeometry::ConeCurveGeometry(RTCDevice device, const Profile& profile) {
  auto laidOut = detail::layOutConeCurve(profile);
  if (auto* reason = std::get_if<std::string>(&laidOut)) throw std::invalid_argument(*reason);
  detail::ConeCurveLayout& layout = std::get<detail::ConeCurveLayout>(laidOut);
  geometry_ = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_CONE_LINEAR_CURVE);
  if (geometry_ == nullptr) {
    throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_CONE_LINEAR_CURVE) failed: " + deviceError(device));
  }
  const std::size_t vertexCount = layout.vertices.size() / 4, coneCount = layout.firstVertex.size();
  void* vertices =
      rtcSetNewGeometryBuffer(geometry_, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), vertexCount);
  void* indices =
      rtcSetNewGeometryBuffer(geometry_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(std::uint32_t), coneCount);
  void* flags = rtcSetNewGeometryBuffer(geometry_, RTC_BUFFER_TYPE_FLAGS, 0, RTC_FORMAT_UCHAR, 1, coneCount);
  if (vertices == nullptr || indices == nullptr || flags == nullptr) {
    rtcReleaseGeometry(geometry_);
    throw std::runtime_error("allocating a cone curve of " + std::to_string(coneCount) +
                             " cones failed: " + deviceError(device));
  }
  std::memcpy(vertices, layout.vertices.data(), layout.vertices.size() * sizeof(float));
  std::memcpy(indices, layout.firstVertex.data(), coneCount * sizeof(std::uint32_t));
  std::memcpy(flags, layout.flags.data(), coneCount);
  rtcCommitGeometry(geometry_);
  rising_ = std::move(layout.rising);
  firstSegment_ = layout.firstSegment;
  startDisc_ = layout.startDisc;
  endDisc_ = layout.endDisc;
}

ConeCurveGeometry::~ConeCurveGeometry() {
  if (geometry_ != nullptr) rtcReleaseGeometry(geometry_);
}

std::uint32_t ConeCurveGeometry::profileSegment(unsigned primID, float u, Vec3 ng) const noexcept {
  // Embree gives a disc's hit u = 0 (its first end) or 1 and Ng = -+(p1 - p0), along the axis; a
  // cone's hit has 0 < u < 1 before rounding and Ng off the axis.
  const bool onAxis = ng.x == 0.0f && ng.y == 0.0f;
  if (startDisc_ && primID == 0 && u == 0.0f && onAxis) return 0;
  if (endDisc_ && primID + 1 == coneCount() && u == 1.0f && onAxis) return firstSegment_ + coneCount();
  return firstSegment_ + primID;
}

}  // namespace revolve
