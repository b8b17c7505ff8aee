// The least signed distance from an axis-aligned rectangle of the meridian plane (a cylinder seen
// in its meridian; a point when degenerate) to a monotone cubic part: what closestPoint and
// cylinderClearance need of a spline shape's part, as segmentMinimum gives it for a segment.
#pragma once

#include <revolve/core.h>

namespace revolve::detail {

struct MeridianRect {
  double rLow, rHigh, zLow, zHigh;
};

struct PartMinimum {
  double value;  // the signed distance: Euclidean outside the rectangle, minus the depth inside
  double r, z;   // the part's point realising it
  double u;      // its parameter
};

// `r`, `z`: the part's control values (monotone in both). Exact up to rounding: inside, the depth is
// the least of four monotone functions of u, two never decreasing and two never increasing, so its
// maximum is where those two groups cross (bisection) or at an end; apart, the nearest feature of
// the rectangle to a point of the part is a side, whose distance is monotone along the part (least
// at an end or where the part enters that side's strip), or a corner, whose distance is least at an
// end, a strip boundary or a root of (c(u) - corner) . c'(u), found from its Bernstein coefficients.
PartMinimum partMinimum(const MeridianRect& rect, const double r[4], const double z[4]);

// Signed distance from (r, z) to the rectangle (see PartMinimum::value).
double rectSignedDistance(const MeridianRect& rect, double r, double z);

}  // namespace revolve::detail
