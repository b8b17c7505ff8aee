// A curved part's record of v (normalised arc length): what a hit's v needs of the part beyond its
// control points and the profile's arc lengths, steps - 1 doubles in detail::SplineData::arcRecords:
//   [k - 1]  the part's arc length from u = 0 to u = k / steps, k = 1 .. steps - 1
// (arc_table.h's table without its ends: at u = 0 the length is 0, and at u = 1 v is the next
// part's v0, which the profile's arc lengths give). A part of one step keeps nothing. Straight
// parts have no record (their v is their chord's, SegmentFrame's).
#pragma once

#include "util/isa.h"

#include "curve/arc_length.h"

#include <algorithm>
#include <cstdint>

namespace revolve::detail {

// The record's length for a table of `steps` steps.
constexpr std::uint32_t arcRecordSize(std::uint32_t steps) noexcept { return steps - 1; }

inline namespace REVOLVE_ISA {

// v at the part's parameter u, within [v0, v1]: the part's arc length to u (arcLengthFrom) over
// the curve's `total`, from v0 = arcStart / total, the curve's length up to the part's start over
// its length, as segmentFrameOf computes it; v1 = arcEnd / total, the next part's v0, bit for bit.
inline double arcRecordV(const double* record, std::uint32_t steps, const double r[4], const double z[4], double u,
                         double arcStart, double arcEnd, double total) noexcept {
  const double v0 = arcStart / total, v1 = arcEnd / total;
  return std::clamp(v0 + arcLengthFrom(record, steps, r, z, u) / total, v0, v1);
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
