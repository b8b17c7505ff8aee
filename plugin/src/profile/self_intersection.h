// Detects whether a profile polyline crosses or touches itself, in O(n log n).
#pragma once

#include <revolve/core.h>

#include <cstddef>
#include <optional>
#include <span>

namespace revolve::detail {

// Two segments that share a point they must not share. Segment i joins points i and i + 1.
struct SegmentPair {
  std::size_t first;  // first < second
  std::size_t second;
};

// Precondition: `points` is a polyline of at least two points (fewer return nothing), with all
// coordinates finite and no two consecutive points equal (checked by assert in debug builds).
// Neighbouring segments (i, i + 1) may share only their common vertex; when the first and last
// points are equal (a closed loop), the first and last segments may share only that point. Any
// other shared point — a crossing, a touch, a vertex on another segment, collinear overlap — is
// a self-intersection. Returns one such pair (the first found by a sweep in order of increasing r,
// then z), or nothing.
// Exact: decisions use exact orientation predicates, never a tolerance.
std::optional<SegmentPair> findSelfIntersection(std::span<const Point2> points);

}  // namespace revolve::detail
