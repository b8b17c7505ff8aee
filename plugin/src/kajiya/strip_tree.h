// Kajiya's baseline (1983): a strip tree (Ballard, CACM 24(5), 1981) over the profile.
//
// A strip is the rectangle, aligned with the chord of a run of profile points, that holds the run;
// a run is split at the point farthest from its chord. Kajiya maps the ray into the meridian plane,
// where it becomes a hyperbola, and prunes the strips the hyperbola misses; at a leaf (one segment)
// he intersects the hyperbola with the segment, which is Wang's ray/cone quadratic. Every visited
// node costs a conic-versus-rectangle test: here the ray's stretch within the strip's z extent,
// then the two bands of the rectangle (across and along the chord), each tested exactly by the
// convexity of nr rho + nz z along the ray (shell_tests.h). Nodes are visited in profile order,
// through skip links, as Kajiya's search did: no stack, hence no depth limit, which matters because
// Ballard's farthest-point split can make the tree as deep as the profile is long.
#pragma once

#include <revolve/core.h>

#include "kernel/shell_tests.h"

#include <cstdint>
#include <span>
#include <vector>

namespace revolve::detail {

struct StripNode {
  double zLow, zHigh;     // z extent of the run (copies of vertex heights)
  Band across;            // the strip's width: normal to the chord
  Band along;             // the strip's length: along the chord
  std::uint32_t skip;     // pre-order index of the node after this subtree
  std::uint32_t segment;  // leaf: the segment; inner node: kInner (its children follow it)
  static constexpr std::uint32_t kInner = 0xffffffffu;
};

struct StripTree {
  std::vector<StripNode> nodes;  // pre-order; nodes[0] is the root
};

StripTree buildStripTree(std::span<const Point2> points);

}  // namespace revolve::detail
