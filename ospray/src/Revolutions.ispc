// The ISPC side of a "revolution" geometry: the intersect and postIntersect entries OSPRay's
// dispatch calls for a geometry type it does not know (GEOMETRY_TYPE_UNKNOWN). The exact work is
// revolve's C++ (revolution_hits.cpp): ISPC hands it the packet, or each active lane of a hit.
#include "common/DifferentialGeometry.ih"
#include "common/FilterIntersect.ih"
#include "common/Ray.ih"
#include "common/RayQueryContext.ih"
#include "geometry/Geometry.ih"
#include "RevolutionsShared.h"

extern "C" void revolveOsprayIntersect(const RTCIntersectFunctionNArguments *uniform args,
                                       uniform int32 occlusion);
extern "C" uniform bool revolveOsprayCrossing(const void *uniform geometryUserPtr, uniform uint32 primID,
                                              const uniform float origin[3], const uniform float direction[3],
                                              uniform float tnear, uniform float tfar, uniform float crossing[6]);
extern "C" void revolveOsprayShadingNormal(const void *uniform host, uniform uint32 primID, uniform float u,
                                           uniform float v, uniform float normal[3]);

// A clipping query (a group's "clippingGeometry") wants every crossing of the ray with the clipper,
// each handed to OSPRay's clipping filter, which notes it (entering or leaving, by Ng) and rejects it;
// the ray keeps its extent. Crossings come nearest first, each search starting at the next float
// after the last crossing (revolve's intersect accepts t >= tnear), so the loop ends: a profile
// has finitely many crossings with a ray, and a search finding none, or none ahead, stops it.
static void Revolutions_clip(const RTCIntersectFunctionNArguments *uniform args) {
  varying Ray *uniform ray = (varying Ray * uniform) args->rayhit;
  const float tfar = ray->t;
  float tnear = ray->t0;
  while (true) {
    bool found = false;
    float t = 0.f, nx = 0.f, ny = 0.f, nz = 0.f, u = 0.f, v = 0.f;
    foreach_active(lane) {
      const uniform float origin[3] = {extract(ray->org.x, lane), extract(ray->org.y, lane), extract(ray->org.z, lane)};
      const uniform float direction[3] = {extract(ray->dir.x, lane), extract(ray->dir.y, lane),
                                          extract(ray->dir.z, lane)};
      uniform float crossing[6];
      if (revolveOsprayCrossing(args->geometryUserPtr, args->primID, origin, direction, extract(tnear, lane),
                                extract(tfar, lane), crossing) &&
          crossing[0] >= extract(tnear, lane)) {
        found = insert(found, lane, true);
        t = insert(t, lane, crossing[0]);
        nx = insert(nx, lane, crossing[1]);
        ny = insert(ny, lane, crossing[2]);
        nz = insert(nz, lane, crossing[3]);
        u = insert(u, lane, crossing[4]);
        v = insert(v, lane, crossing[5]);
      }
    }
    if (!found) break;
    RTCHit hit;
    hit.Ng_x = nx;
    hit.Ng_y = ny;
    hit.Ng_z = nz;
    hit.u = u;
    hit.v = v;
    hit.primID = args->primID;
    hit.geomID = args->geomID;
    hit.instID[0] = args->context->instID[0];
    ray->t = t;  // the filter reads the crossing's distance from the ray
    filterCall(args, hit);
    ray->t = tfar;
    tnear = floatbits(intbits(t) + 1);  // t >= 0: the next float up
  }
}

// Embree hands the packet as OSPRay traced it (a varying Ray, Embree's RTCRayHitN of
// programCount lanes): the C++ side reads and writes it through Embree's accessors.
unmasked void Revolutions_intersect(const RTCIntersectFunctionNArguments *uniform args,
                                    const uniform bool isOcclusionTest) {
  const RayQueryContextDefault *uniform context = (const RayQueryContextDefault *uniform)args->context;
  if (context->type == RQCT_CLIPPING) {
    if (args->valid[programIndex] != 0) Revolutions_clip(args);
    return;
  }
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
