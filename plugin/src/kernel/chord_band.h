// Bands aligned with a run's chord: the TC shells of the MIBIT tree and the strips of Kajiya's tree.
#pragma once

#include "kernel/shell_tests.h"

#include <revolve/core.h>

#include <span>

namespace revolve::detail {

struct Chord {
  double ur, uz;  // unit direction
};

// The chord of a run's end points; for a closed loop (end points equal), the direction from its
// first point to its farthest point.
Chord chordOf(std::span<const Point2> run);

// The band {wLow <= nr r + nz z <= wHigh} holding the run, for the normal (nr, nz) turned so that
// nr >= 0 (the orientation that keeps nr rho + nz z convex along a ray; see shell_tests.h).
Band bandHolding(std::span<const Point2> run, double nr, double nz);

}  // namespace revolve::detail
