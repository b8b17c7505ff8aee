// The benchmark's ground truth: where a ray meets the smooth surface of revolution itself.
//
// Along a ray with unit direction the signed distance to the surface, SD(s), is 1-Lipschitz (the
// meridian point moves no faster than the ray). So an interval [a, b] with SD of one sign at both
// ends and |SD(a)| + |SD(b)| > b - a holds no root, and every other interval is split. That
// branch-and-bound finds the first root of SD, and so the first hit, or proves there is none, with
// nothing assumed about the curve beyond the exact distance (smooth_profile.h). A ray that comes
// within `grazeTolerance` of the surface and is never proven to cross it cannot be decided this
// way and is reported as grazing; the error measures leave such rays out of the hit/miss comparison.
#pragma once

#include "smooth_profile.h"

#include <revolve/revolve.h>

namespace revolve::bench {

struct ReferenceHit {
  bool hit = false;
  bool grazing = false;  // no crossing proven, but came within grazeTolerance of the surface
  double t = 0.0;        // in the caller's units of the ray's direction
  double point[3] = {0, 0, 0};
  double normal[3] = {0, 0, 0};  // unit, the smooth surface's (revolve's orientation)
};

class ReferenceTracer {
 public:
  explicit ReferenceTracer(const SmoothProfile& profile);
  ReferenceHit trace(const Ray& ray) const;

  // Meridian view of a 3-D point: its exact distance from the surface and the normal there.
  ClosestPoint closestTo(const double p[3]) const;
  double grazeTolerance() const { return grazeTolerance_; }

 private:
  const SmoothProfile& profile_;
  double zCentre_, radius_;  // a sphere holding the solid
  double rootTolerance_, grazeTolerance_;
};

}  // namespace revolve::bench
