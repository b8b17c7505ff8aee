// revolve's Ray as Embree's ray record, for the applications and the benchmark that trace through
// Embree: every mask bit set, no hit yet (no geometry, no instance, as Embree requires).
#pragma once

#include <revolve/revolve.h>

#include <embree3/rtcore.h>

namespace revolve::app {

inline RTCRayHit embreeRayHit(const Ray& ray) {
  RTCRayHit rayHit{};
  rayHit.ray.org_x = ray.origin.x;
  rayHit.ray.org_y = ray.origin.y;
  rayHit.ray.org_z = ray.origin.z;
  rayHit.ray.dir_x = ray.direction.x;
  rayHit.ray.dir_y = ray.direction.y;
  rayHit.ray.dir_z = ray.direction.z;
  rayHit.ray.tnear = ray.tnear;
  rayHit.ray.tfar = ray.tfar;
  rayHit.ray.mask = ~0u;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rayHit;
}

}  // namespace revolve::app
