// Exact geometric predicates on double coordinates (floating-point filter, exact fallback).
#pragma once

#include <revolve/core.h>

namespace revolve::detail {

// Sign of the orientation of (a, b, c): +1 when c lies to the left of the directed line a -> b
// (counter-clockwise turn, with r as the first and z as the second axis), -1 to the right, 0 when
// the three points are exactly collinear. Exact for all finite inputs.
int orient2d(Point2 a, Point2 b, Point2 c);

}  // namespace revolve::detail
