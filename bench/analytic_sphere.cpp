#include "analytic_sphere.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace revolve::bench {
namespace {

void sphereBounds(const RTCBoundsFunctionArguments* args) {
  const auto& sphere = *static_cast<const AnalyticSphere*>(args->geometryUserPtr);
  RTCBounds& b = *args->bounds_o;
  b.lower_x = float(sphere.centre[0] - sphere.radius);
  b.lower_y = float(sphere.centre[1] - sphere.radius);
  b.lower_z = float(sphere.centre[2] - sphere.radius);
  b.upper_x = float(sphere.centre[0] + sphere.radius);
  b.upper_y = float(sphere.centre[1] + sphere.radius);
  b.upper_z = float(sphere.centre[2] + sphere.radius);
}

// The nearest root of |o + t d - c|^2 = R^2 in [tnear, tfar], in double, or a negative value.
template <class Lane>
bool sphereRoot(const AnalyticSphere& sphere, const Lane& lane, double& t) {
  const double ox = lane.ox - sphere.centre[0], oy = lane.oy - sphere.centre[1], oz = lane.oz - sphere.centre[2];
  const double a = double(lane.dx) * lane.dx + double(lane.dy) * lane.dy + double(lane.dz) * lane.dz;
  const double b = ox * lane.dx + oy * lane.dy + oz * lane.dz;
  const double c = ox * ox + oy * oy + oz * oz - sphere.radius * sphere.radius;
  const double discriminant = b * b - a * c;
  if (!(discriminant >= 0.0)) return false;
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  double t0 = q / a, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 >= lane.tnear && t0 <= lane.tfar) return t = t0, true;
  if (t1 >= lane.tnear && t1 <= lane.tfar) return t = t1, true;
  return false;
}

struct Lane {
  float ox, oy, oz, dx, dy, dz, tnear, tfar;
};

Lane laneOf(RTCRayN* rays, unsigned N, unsigned i) {
  return {RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i), RTCRayN_dir_x(rays, N, i),
          RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i), RTCRayN_tnear(rays, N, i), RTCRayN_tfar(rays, N, i)};
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
  const auto& sphere = *static_cast<const AnalyticSphere*>(args->geometryUserPtr);
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const Lane lane = laneOf(rays, args->N, i);
    double t;
    if (!sphereRoot(sphere, lane, t)) continue;
    const double nx = (lane.ox + t * lane.dx - sphere.centre[0]) / sphere.radius;
    const double ny = (lane.oy + t * lane.dy - sphere.centre[1]) / sphere.radius;
    const double nz = (lane.oz + t * lane.dz - sphere.centre[2]) / sphere.radius;
    RTCRayN_tfar(rays, args->N, i) = float(t);
    RTCHitN_Ng_x(hits, args->N, i) = float(nx);
    RTCHitN_Ng_y(hits, args->N, i) = float(ny);
    RTCHitN_Ng_z(hits, args->N, i) = float(nz);
    RTCHitN_u(hits, args->N, i) = 0.0f;  // the floor: no surface parameters computed
    RTCHitN_v(hits, args->N, i) = 0.0f;
    RTCHitN_primID(hits, args->N, i) = 0;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
  const auto& sphere = *static_cast<const AnalyticSphere*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    double t;
    if (sphereRoot(sphere, laneOf(args->ray, args->N, i), t)) {
      RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
    }
  }
}

}  // namespace

RTCGeometry newAnalyticSphereGeometry(RTCDevice device, const AnalyticSphere& sphere) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  if (geometry == nullptr) throw std::runtime_error("rtcNewGeometry(RTC_GEOMETRY_TYPE_USER) failed");
  rtcSetGeometryUserPrimitiveCount(geometry, 1);
  rtcSetGeometryUserData(geometry, const_cast<AnalyticSphere*>(&sphere));
  rtcSetGeometryBoundsFunction(geometry, sphereBounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, sphereIntersect);
  rtcSetGeometryOccludedFunction(geometry, sphereOccluded);
  rtcCommitGeometry(geometry);
  return geometry;
}

}  // namespace revolve::bench
