// revolve's Ray as Embree's ray record, for the applications and the benchmark that trace through
// Embree: every mask bit set, no hit yet (no geometry, no instance, as Embree requires). Also one
// lane of Embree's 8-wide packet record, written from and read back into the single ray's record,
// so that a packet's lane holds exactly what rtcIntersect1 would have been given.
#pragma once

#include <revolve/revolve.h>

namespace revolve::app {

inline RTCRayHit embreeRayHit(const Ray& ray) {
  return embree::newRayHit(ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
                           ray.tnear, ray.tfar);
}

// Lane `k` of `packet` set to the single ray `one` (its ray and its empty hit).
inline void setPacketLane(RTCRayHit8& packet, int k, const RTCRayHit& one) noexcept {
  packet.ray.org_x[k] = one.ray.org_x;
  packet.ray.org_y[k] = one.ray.org_y;
  packet.ray.org_z[k] = one.ray.org_z;
  packet.ray.dir_x[k] = one.ray.dir_x;
  packet.ray.dir_y[k] = one.ray.dir_y;
  packet.ray.dir_z[k] = one.ray.dir_z;
  packet.ray.tnear[k] = one.ray.tnear;
  packet.ray.tfar[k] = one.ray.tfar;
  packet.ray.time[k] = one.ray.time;
  packet.ray.mask[k] = one.ray.mask;
  packet.ray.id[k] = one.ray.id;
  packet.ray.flags[k] = one.ray.flags;
  packet.hit.Ng_x[k] = one.hit.Ng_x;
  packet.hit.Ng_y[k] = one.hit.Ng_y;
  packet.hit.Ng_z[k] = one.hit.Ng_z;
  packet.hit.u[k] = one.hit.u;
  packet.hit.v[k] = one.hit.v;
  packet.hit.primID[k] = one.hit.primID;
  packet.hit.geomID[k] = one.hit.geomID;
  for (unsigned level = 0; level < RTC_MAX_INSTANCE_LEVEL_COUNT; ++level)
    packet.hit.instID[level][k] = one.hit.instID[level];
}

// Lane `k` of `packet` as the single ray's record, after a query.
inline RTCRayHit packetLane(const RTCRayHit8& packet, int k) noexcept {
  RTCRayHit one{};
  one.ray.org_x = packet.ray.org_x[k];
  one.ray.org_y = packet.ray.org_y[k];
  one.ray.org_z = packet.ray.org_z[k];
  one.ray.dir_x = packet.ray.dir_x[k];
  one.ray.dir_y = packet.ray.dir_y[k];
  one.ray.dir_z = packet.ray.dir_z[k];
  one.ray.tnear = packet.ray.tnear[k];
  one.ray.tfar = packet.ray.tfar[k];
  one.ray.time = packet.ray.time[k];
  one.ray.mask = packet.ray.mask[k];
  one.ray.id = packet.ray.id[k];
  one.ray.flags = packet.ray.flags[k];
  one.hit.Ng_x = packet.hit.Ng_x[k];
  one.hit.Ng_y = packet.hit.Ng_y[k];
  one.hit.Ng_z = packet.hit.Ng_z[k];
  one.hit.u = packet.hit.u[k];
  one.hit.v = packet.hit.v[k];
  one.hit.primID = packet.hit.primID[k];
  one.hit.geomID = packet.hit.geomID[k];
  for (unsigned level = 0; level < RTC_MAX_INSTANCE_LEVEL_COUNT; ++level)
    one.hit.instID[level] = packet.hit.instID[level][k];
  return one;
}

}  // namespace revolve::app
