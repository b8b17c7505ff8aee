// The ISPC side of a "revolution" geometry: the intersect and postIntersect entries OSPRay's
// dispatch calls for a geometry type it does not know (GEOMETRY_TYPE_UNKNOWN). The exact work is
// revolve's C++ (revolution_hits.cpp): ISPC hands it the packet, or each active lane of a hit.
#include "common/DifferentialGeometry.ih"
#include "common/Ray.ih"
#include "common/RayQueryContext.ih"
#include "geometry/Geometry.ih"
#include "RevolutionsShared.h"

extern "C" void revolveOsprayIntersect(const RTCIntersectFunctionNArguments *uniform args,
                                       uniform int32 occlusion);
extern "C" void revolveOsprayShadingNormal(const void *uniform host, uniform uint32 primID, uniform float u,
                                           uniform float v, uniform float normal[3]);

// Embree hands the packet as OSPRay traced it (a varying Ray, Embree's RTCRayHitN of
// programCount lanes): the C++ side reads and writes it through Embree's accessors.
// A clipping query (a group's "clippingGeometry") wants every crossing handed to OSPRay's clipping
// filter, not a hit: this geometry does not clip, so it reports none there (a hit written as an
// ordinary one would leave the clipper's geomID in the ray, naming a model the renderer lacks).
unmasked void Revolutions_intersect(const RTCIntersectFunctionNArguments *uniform args,
                                    const uniform bool isOcclusionTest) {
  const RayQueryContextDefault *uniform context = (const RayQueryContextDefault *uniform)args->context;
  if (context->type == RQCT_CLIPPING) return;
  revolveOsprayIntersect(args, isOcclusionTest ? 1 : 0);
}

// The hit's attributes, in object space (OSPRay's instance transforms them): Ng as the callback
// wrote it (the exact surface's normal), Ns the curve's normal for a spline traced as its
// polyline, st = revolve's (u, v).
void Revolutions_postIntersect(const Geometry *uniform geometry, varying DifferentialGeometry &dg,
                               const varying Ray &ray, uniform int64 flags) {
  const Revolutions *uniform self = (const Revolutions *uniform)geometry;
  dg.Ng = ray.Ng;
  dg.Ns = ray.Ng;
  if (flags & DG_NS) {
    foreach_active(lane) {
      uniform float normal[3];
      revolveOsprayShadingNormal(self->host, extract(ray.primID, lane), extract(ray.u, lane),
                                 extract(ray.v, lane), normal);
      // A polyline revolution (no curve behind it) answers its Ng: leave dg.Ns as set.
      if (normal[0] != 0.f || normal[1] != 0.f || normal[2] != 0.f) {
        dg.Ns.x = insert(dg.Ns.x, lane, normal[0]);
        dg.Ns.y = insert(dg.Ns.y, lane, normal[1]);
        dg.Ns.z = insert(dg.Ns.z, lane, normal[2]);
      }
    }
  }
  if (flags & DG_TEXCOORD) dg.st = make_vec2f(ray.u, ray.v);
}

export void *uniform Revolutions_intersect_addr() { return Revolutions_intersect; }

export void *uniform Revolutions_postIntersect_addr() { return Revolutions_postIntersect; }
