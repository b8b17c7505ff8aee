// Whether a curve, given as its monotone parts, crosses or touches itself: conservatively, by
// subdividing parts against each other until their control hulls are provably apart.
#pragma once

#include "curve/monotone_parts.h"

#include <cstddef>
#include <optional>
#include <span>

namespace revolve::detail {

struct PartPair {
  std::size_t first, second;  // indices into the parts, first < second
};

// Two parts are apart when their boxes are (a monotone part lies in the box of its ends), or when
// their chords lie farther apart than their control points' distances from them (a control hull
// lies within that distance of its chord), in both cases by more than 2^-48 of `extent`: twice the
// rounding of a point evaluated on the curve (kCubicAtError), which also covers a part's overshoot
// of its box where monotoneParts skipped a split, so that chords between points computed on two
// parts that are apart never meet. Parts meeting at a join (consecutive parts, and the last and first of a closed loop)
// are apart when the cones from the join holding their control hulls meet only there. Parts are subdivided (de
// Casteljau) until one of these holds; parts still unresolved at 2^-40 of `extent`, or after 2^16 subdivisions of the
// pair (2^16 + 256 a part for the whole curve), count as touching. So a curve coming within about that distance of
// itself, running that close to itself for a long stretch, or folding back on itself at a cusp (also a hairpin narrower
// than rounding), is reported; a curve that crosses or touches itself always is. Returns one such pair.
std::optional<PartPair> findCurveSelfIntersection(std::span<const MonotonePart> parts, double extent);

}  // namespace revolve::detail
