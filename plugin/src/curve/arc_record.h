// A curved part's record of v (normalised arc length): what a hit's v needs of the part beyond its
// control points, steps + 2 doubles in detail::SplineData::arcRecords:
//   [0]          v per unit of arc length (the part's dv over its length)
//   [1]          v at the part's end (v0 + dv, the sum a hit's v is clamped to)
//   [2 + k]      v at u = k / steps, k = 0 .. steps - 1 (arc_table.h's table normalised; [2] is v0)
// The table's last entry, v at u = 1, is not kept: arcLengthFrom never reads it. Straight parts
// have no record (their v is their chord's, SegmentFrame's).
#pragma once

#include "util/isa.h"

#include "curve/arc_length.h"

#include <algorithm>
#include <cstdint>

namespace revolve::detail {

inline constexpr std::uint32_t kArcRecordScale = 0, kArcRecordEnd = 1, kArcRecordTable = 2;

// The record's length for a table of `steps` steps.
constexpr std::uint32_t arcRecordSize(std::uint32_t steps) noexcept { return steps + kArcRecordTable; }

inline namespace REVOLVE_ISA {

// v at the part's parameter u, within [v0, v0 + dv].
inline double arcRecordV(const double* record, std::uint32_t steps, const double r[4], const double z[4],
                         double u) noexcept {
  const double* table = record + kArcRecordTable;
  const double v = arcLengthFrom(table, steps, r, z, u, record[kArcRecordScale]);
  return std::clamp(v, table[0], record[kArcRecordEnd]);
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
