// How far each method's answers are from the smooth surface, on a set of rays.
#pragma once

#include "reference_tracer.h"

#include <revolve/embree_api.h>
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
  // Hits on another sheet of the surface than the reference's first hit (a wall passed through, or
  // a surface that is not there), which the residual cannot see: the hit lies more than
  // kOtherSheet of the size off the tangent plane there. Counted among the decided rays both hit.
  static constexpr double kOtherSheet = 0.01;
  std::size_t otherSheet = 0, bothHit = 0;
  double otherSheetFraction() const { return bothHit > 0 ? double(otherSheet) / double(bothHit) : 0.0; }
};

// The reference's answer for every ray (in parallel).
std::vector<ReferenceHit> referenceHits(const ReferenceTracer& tracer, const std::vector<Ray>& rays);

// Traces every ray through `scene` with rtcIntersect1 and compares with the reference. Without
// `orientedNormals` (a method whose Ng has no inside or outside), normals are compared up to sign.
ErrorSummary measureErrors(RTCScene scene, const std::vector<Ray>& rays, const std::vector<ReferenceHit>& reference,
                           const ReferenceTracer& tracer, double size, bool orientedNormals = true);

}  // namespace revolve::bench
