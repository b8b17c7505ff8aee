// How far each method's answers are from the smooth surface, on a set of rays.
#pragma once

#include "reference_tracer.h"

#include <embree3/rtcore.h>
#include <revolve/revolve.h>

#include <cstddef>
#include <vector>

namespace revolve::bench {

// Distances are relative to the object's size (SmoothProfile::size()).
struct ErrorSummary {
  std::size_t rays = 0, hits = 0;
  // Meridian residual of each hit point o + t d (float t, as a caller reconstructs it): its exact
  // distance from the smooth surface. Includes t's float rounding, about 1e-7 of the size here.
  double residualMax = 0, residualP99 = 0, residualRms = 0;
  double normalMaxDegrees = 0, normalP99Degrees = 0;  // Ng against the smooth surface's normal there
  // Rays whose hit/miss differs from the reference's, among the rays the reference decides.
  std::size_t disagreements = 0, decided = 0;
  double disagreementFraction() const { return decided > 0 ? double(disagreements) / double(decided) : 0.0; }
};

// The reference's answer for every ray (in parallel).
std::vector<ReferenceHit> referenceHits(const ReferenceTracer& tracer, const std::vector<Ray>& rays);

// Traces every ray through `scene` with rtcIntersect1 and compares with the reference.
ErrorSummary measureErrors(RTCScene scene, const std::vector<Ray>& rays, const std::vector<ReferenceHit>& reference,
                           const ReferenceTracer& tracer, double size);

}  // namespace revolve::bench
