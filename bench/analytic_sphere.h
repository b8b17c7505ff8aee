// The floor of what any Embree user geometry costs: a sphere, one quadratic a ray in double
// precision, writing t and a unit Ng (u and v left 0: no surface parameters computed).
#pragma once

#include <revolve/embree_api.h>

namespace revolve::bench {

struct AnalyticSphere {
  double centre[3];
  double radius;
};

// A committed user geometry tracing `sphere`, which must outlive it.
RTCGeometry newAnalyticSphereGeometry(RTCDevice device, const AnalyticSphere& sphere);

}  // namespace revolve::bench
