// revolve's Ray as Embree's ray record, for the applications and the benchmark that trace through
// Embree: every mask bit set, no hit yet (no geometry, no instance, as Embree requires).
#pragma once

#include <revolve/revolve.h>

namespace revolve::app {

inline RTCRayHit embreeRayHit(const Ray& ray) {
  return embree::newRayHit(ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
                           ray.tnear, ray.tfar);
}

}  // namespace revolve::app
