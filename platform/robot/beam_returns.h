// From a beam's sub-ray hits to the returns a sensor reports. A pulse's echo from one surface is
// one return however many sub-rays of the footprint (robot/beam_footprint.h) hit it; echoes from
// surfaces farther apart than the sensor can separate are distinct returns. So the sub-ray hits,
// sorted by range, are cut into groups wherever two neighbours lie more than `separation` apart
// (single linkage: a slanted wall, its hits spread over more than `separation` in small steps,
// stays one return). A group's return has
//   - the range of its nearest hit (the echo's leading edge, which a threshold detector times),
//     and that hit's object;
//   - the group's share of the beam's light: the sum of its sub-rays' intensities over the number
//     of sub-rays (a beam wholly on one surface returns what its axis alone would).
// The sensor then reports, of the returns that pass its range gate, the first, the last, the
// strongest (the nearest of equals) or, with "all", the first max_returns in range order.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

namespace revolve::robot {

// One sub-ray's hit, or a group's return. Plain data, without initialisers: the per-beam arrays
// of it on the tracing path are left uninitialised until written.
struct Echo {
  double range;      // along the ray, in scene units
  double intensity;  // reflectivity |cos theta| / range^2 (a return's: its group's share)
  std::int32_t object;
};

// Groups `hits` (sorted here, in place) into returns written to `returns` (room for hits.size());
// `subrays` is the number of sub-rays the beam was sampled by (those that missed included).
// Returns the number of returns. Never allocates.
inline std::size_t groupEchoes(std::span<Echo> hits, double separation, int subrays, std::span<Echo> returns) noexcept {
  if (hits.empty()) return 0;
  std::sort(hits.begin(), hits.end(), [](const Echo& a, const Echo& b) { return a.range < b.range; });
  std::size_t count = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (i == 0 || hits[i].range - hits[i - 1].range > separation) {
      returns[count++] = {hits[i].range, 0, hits[i].object};
    }
    returns[count - 1].intensity += hits[i].intensity;
  }
  for (std::size_t i = 0; i < count; ++i) returns[i].intensity /= subrays;
  return count;
}

}  // namespace revolve::robot
