#include "kernel/chord_band.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {

Chord chordOf(std::span<const Point2> run) {
  const Point2 from = run.front();
  Point2 to = run.back();
  if (from.r == to.r && from.z == to.z) {
    double farthest = -1.0;
    for (const Point2& p : run) {
      const double d = std::hypot(p.r - from.r, p.z - from.z);
      if (d > farthest) farthest = d, to = p;
    }
  }
  const double length = std::hypot(to.r - from.r, to.z - from.z);
  return {(to.r - from.r) / length, (to.z - from.z) / length};
}

Band bandHolding(std::span<const Point2> run, double nr, double nz) {
  if (nr < 0.0 || (nr == 0.0 && nz < 0.0)) nr = -nr, nz = -nz;
  Band band{nr, nz, nr * run[0].r + nz * run[0].z, nr * run[0].r + nz * run[0].z};
  for (const Point2& p : run) {
    const double w = nr * p.r + nz * p.z;
    band.wLow = std::min(band.wLow, w);
    band.wHigh = std::max(band.wHigh, w);
  }
  return band;
}

}  // namespace revolve::detail
