// Exact equality of profile points, as validation and the self-intersection sweep use it.
#pragma once

#include <revolve/core.h>

namespace revolve::detail {

inline bool samePoint(Point2 a, Point2 b) { return a.r == b.r && a.z == b.z; }

}  // namespace revolve::detail
