// The probe behind argumentsReachable (query_filters.h): one ray traced through a user geometry
// whose callbacks compare the arguments they find behind their own with the ones the probe passed.
#include "embree/query_filters.h"

#include <limits>
#include <mutex>

namespace revolve::detail {

#if REVOLVE_EMBREE_MAJOR == 4
namespace {

struct Probe {
  const void* intersectArguments = nullptr;
  const void* occludedArguments = nullptr;
  int intersectCalls = 0, intersectMatches = 0;
  int occludedCalls = 0, occludedMatches = 0;
};

// The raw field, without argumentsReachable's guard (which the probe is about to set).
template <class PublicArguments>
const void* fieldBehind(const PublicArguments* args) noexcept {
  const void* arguments;
  std::memcpy(&arguments,
              reinterpret_cast<const char*>(args) + offsetof(EmbreeCallbackRecord<PublicArguments>, arguments),
              sizeof arguments);
  return arguments;
}

void probeBounds(const RTCBoundsFunctionArguments* args) {
  *args->bounds_o = RTCBounds{-1.0f, -1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f};
}

void probeIntersect(const RTCIntersectFunctionNArguments* args) {
  auto& probe = *static_cast<Probe*>(args->geometryUserPtr);
  ++probe.intersectCalls;
  probe.intersectMatches += fieldBehind(args) == probe.intersectArguments;
}

void probeOccluded(const RTCOccludedFunctionNArguments* args) {
  auto& probe = *static_cast<Probe*>(args->geometryUserPtr);
  ++probe.occludedCalls;
  probe.occludedMatches += fieldBehind(args) == probe.occludedArguments;
}

bool probeArguments(RTCDevice device) {
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  if (scene == nullptr || geometry == nullptr) {
    if (geometry != nullptr) rtcReleaseGeometry(geometry);
    if (scene != nullptr) rtcReleaseScene(scene);
    return false;
  }
  Probe probe;
  rtcSetGeometryUserPrimitiveCount(geometry, 1);
  rtcSetGeometryUserData(geometry, &probe);
  rtcSetGeometryBoundsFunction(geometry, probeBounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, probeIntersect);
  rtcSetGeometryOccludedFunction(geometry, probeOccluded);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);

  // A single ray and an 8-wide packet (Embree's packet code fills the record the same way), each
  // straight through the box.
  RTCRayQueryContext context;
  rtcInitRayQueryContext(&context);
  RTCIntersectArguments intersect;
  rtcInitIntersectArguments(&intersect);
  intersect.context = &context;
  RTCOccludedArguments occluded;
  rtcInitOccludedArguments(&occluded);
  occluded.context = &context;
  probe.intersectArguments = &intersect;
  probe.occludedArguments = &occluded;
  const float inf = std::numeric_limits<float>::infinity();

  RTCRayHit single = embree::newRayHit(0.0f, 0.0f, -5.0f, 0.0f, 0.0f, 1.0f, 0.0f, inf);
  rtcIntersect1(scene, &single, &intersect);
  rtcOccluded1(scene, &single.ray, &occluded);

  alignas(32) int valid[8];
  alignas(32) RTCRayHit8 packet{};
  for (int i = 0; i < 8; ++i) {
    valid[i] = -1;
    packet.ray.org_z[i] = -5.0f;
    packet.ray.dir_z[i] = 1.0f;
    packet.ray.tfar[i] = inf;
    packet.ray.mask[i] = ~0u;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, scene, &packet, &intersect);
  for (int i = 0; i < 8; ++i) packet.ray.tfar[i] = inf;
  rtcOccluded8(valid, scene, &packet.ray, &occluded);
  rtcReleaseScene(scene);

  return probe.intersectCalls >= 2 && probe.intersectMatches == probe.intersectCalls && probe.occludedCalls >= 2 &&
         probe.occludedMatches == probe.occludedCalls;
}

}  // namespace

bool checkArgumentsReachable(RTCDevice device) {
  static std::once_flag once;
  std::call_once(once, [device] { argumentsReachable.store(probeArguments(device), std::memory_order_relaxed); });
  return argumentsReachable.load(std::memory_order_relaxed);
}

#else

bool checkArgumentsReachable(RTCDevice) { return true; }

#endif

}  // namespace revolve::detail
