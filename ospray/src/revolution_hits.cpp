#include "revolution_hits.h"

#include "RevolutionsShared.h"
#include "geometry/Geometry.h"
#include "revolution_set.h"

#include <limits>
#include <vector>

namespace ospray::revolve_module {

namespace {

using Revolutions = std::vector<revolve::ospray_module::Revolution>;

const Revolutions& revolutionsOf(const void* geometryUserPtr) {
  return *static_cast<const Revolutions*>(static_cast<const ispc::Revolutions*>(geometryUserPtr)->host);
}

}  // namespace

void revolutionBounds(const RTCBoundsFunctionArguments* args) {
  const revolve::Bounds b = revolutionsOf(args->geometryUserPtr)[args->primID].shape.bounds();
  RTCBounds& out = *args->bounds_o;
  out.lower_x = b.lower.x, out.lower_y = b.lower.y, out.lower_z = b.lower.z;
  out.upper_x = b.upper.x, out.upper_y = b.upper.y, out.upper_z = b.upper.z;
}

}  // namespace ospray::revolve_module

// The packet is OSPRay's varying Ray, laid out as Embree's RTCRayHitN of args->N lanes (OSPRay's
// Ray.ih keeps that layout). Under an instance Embree hands the object-space ray.
extern "C" void revolveOsprayIntersect(const RTCIntersectFunctionNArguments* args, std::int32_t occlusion) {
  using namespace ospray::revolve_module;
  // A geometry re-committed with fewer revolutions, under a group not re-committed: Embree still
  // has the old primitives' bounds. One no longer there is missed.
  const Revolutions& revolutions = revolutionsOf(args->geometryUserPtr);
  if (args->primID >= revolutions.size()) return;
  const revolve::Shape& shape = revolutions[args->primID].shape;
  const unsigned n = args->N;
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, n);
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] == 0) continue;
    const revolve::Ray query{{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
                             {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)},
                             RTCRayN_tnear(ray, n, i),
                             RTCRayN_tfar(ray, n, i)};
    if (occlusion != 0) {
      // Embree's (and OSPRay's) mark of an occluded ray.
      if (revolve::occluded(shape, query)) RTCRayN_tfar(ray, n, i) = -std::numeric_limits<float>::infinity();
      continue;
    }
    const std::optional<revolve::Hit> found = revolve::intersect(shape, query);
    if (!found) continue;
    RTCRayN_tfar(ray, n, i) = found->t;
    RTCHitN_Ng_x(hit, n, i) = found->normal.x;
    RTCHitN_Ng_y(hit, n, i) = found->normal.y;
    RTCHitN_Ng_z(hit, n, i) = found->normal.z;
    RTCHitN_u(hit, n, i) = found->u;
    RTCHitN_v(hit, n, i) = found->v;
    RTCHitN_primID(hit, n, i) = args->primID;
    RTCHitN_geomID(hit, n, i) = args->geomID;
    RTCHitN_instID(hit, n, i, 0) = args->context->instID[0];
  }
}

extern "C" bool revolveOsprayCrossing(const void* geometryUserPtr, std::uint32_t primID, const float origin[3],
                                      const float direction[3], float tnear, float tfar, float crossing[6]) {
  using namespace ospray::revolve_module;
  const Revolutions& revolutions = revolutionsOf(geometryUserPtr);
  if (primID >= revolutions.size()) return false;  // see revolveOsprayIntersect
  const revolve::Ray query{{origin[0], origin[1], origin[2]}, {direction[0], direction[1], direction[2]}, tnear, tfar};
  const std::optional<revolve::Hit> found = revolve::intersect(revolutions[primID].shape, query);
  if (!found) return false;
  crossing[0] = found->t;
  crossing[1] = found->normal.x, crossing[2] = found->normal.y, crossing[3] = found->normal.z;
  crossing[4] = found->u, crossing[5] = found->v;
  return true;
}

extern "C" void revolveOsprayShadingNormal(const void* host, std::uint32_t primID, float u, float v, float normal[3]) {
  const auto& revolutions = *static_cast<const std::vector<revolve::ospray_module::Revolution>*>(host);
  // Past the end (see revolveOsprayIntersect): no hit comes from there; answer "use Ng".
  const std::optional<revolve::Vec3> shading =
      primID < revolutions.size() ? revolutions[primID].shadingNormal(u, v) : std::nullopt;
  normal[0] = shading ? shading->x : 0.0f;
  normal[1] = shading ? shading->y : 0.0f;
  normal[2] = shading ? shading->z : 0.0f;
}
