// A cubic Bezier curve split where r or z turns: parts along which both are monotone, so that each
// lies in the box of its two ends (what MIBIT's monotone intervals and cylinder shells rely on, and
// what lets a part take a segment's place in the search).
#pragma once

#include <revolve/core.h>

#include <cstdint>
#include <span>
#include <vector>

namespace revolve::detail {

struct MonotonePart {
  Point2 c[4];          // control points; c[0] and c[3] are the part's ends, shared exactly with its neighbours
  std::uint32_t piece;  // the Bezier piece it belongs to
  double u0, u1;        // its parameter range in that piece
};

// `bezier`: control points, 3n + 1 of them (Spline::bezier()); `extent`: the largest coordinate
// magnitude of the curve. Each piece is split at the parameters where dr/du or dz/du changes sign
// (the roots of the quadratic derivative, in closed form); at such a split the neighbouring control
// points are given the split point's r (or z) exactly, since the derivative vanishes there. A split
// closer to an end or to the previous split than 2^-50 of the extent (a few roundings of the
// coordinates) is skipped: the part then overshoots its box by no more than that.
std::vector<MonotonePart> monotoneParts(std::span<const Point2> bezier, double extent);

}  // namespace revolve::detail
