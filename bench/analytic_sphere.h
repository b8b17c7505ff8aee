// The floor of what any Embree user geometry costs: a sphere, one quadratic a ray, writing the
// same attributes revolve writes (t, a unit Ng, u from the azimuth, v from the height).
#pragma once

#include <embree3/rtcore.h>

namespace revolve::bench {

struct AnalyticSphere {
  double centre[3];
  double radius;
};

// A committed user geometry tracing `sphere`, which must outlive it.
RTCGeometry newAnalyticSphereGeometry(RTCDevice device, const AnalyticSphere& sphere);

}  // namespace revolve::bench
