#include "kajiya/strip_tree.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {
namespace {

// The band {w : wLow <= n . p <= wHigh} holding the run, for the unit normal (nr, nz) oriented so
// that nr >= 0 (the orientation that keeps nr rho + nz z convex along a ray).
Band bandHolding(std::span<const Point2> run, double nr, double nz) {
  if (nr < 0.0 || (nr == 0.0 && nz < 0.0)) nr = -nr, nz = -nz;
  Band band{nr, nz, 0.0, 0.0};
  band.wLow = band.wHigh = nr * run[0].r + nz * run[0].z;
  for (const Point2& p : run) {
    const double w = nr * p.r + nz * p.z;
    band.wLow = std::min(band.wLow, w);
    band.wHigh = std::max(band.wHigh, w);
  }
  return band;
}

struct Chord {
  double ur, uz;  // unit direction
};

// The chord of a run; for a closed loop (end points equal) the direction to the farthest point.
Chord chordOf(std::span<const Point2> run) {
  Point2 to = run.back();
  const Point2 from = run.front();
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

// Ballard's split: the interior point farthest from the chord (first of equals).
std::size_t farthestFromChord(std::span<const Point2> run, Chord chord) {
  std::size_t best = 1;
  double bestDistance = -1.0;
  for (std::size_t i = 1; i + 1 < run.size(); ++i) {
    const double d = std::abs((run[i].r - run[0].r) * chord.uz - (run[i].z - run[0].z) * chord.ur);
    if (d > bestDistance) bestDistance = d, best = i;
  }
  return best;
}

}  // namespace

StripTree buildStripTree(std::span<const Point2> points) {
  StripTree tree;
  const std::size_t segments = points.size() - 1;
  tree.nodes.resize(2 * segments - 1);  // a full binary tree over the segments
  // Explicit work list instead of recursion: the tree can be as deep as the profile is long.
  struct Work {
    std::size_t first, last;  // point range [first, last]
    std::size_t node;
  };
  std::vector<Work> work{{0, segments, 0}};
  while (!work.empty()) {
    const Work item = work.back();
    work.pop_back();
    const std::span<const Point2> run = points.subspan(item.first, item.last - item.first + 1);
    StripNode& node = tree.nodes[item.node];
    const auto [zLow, zHigh] = std::minmax_element(run.begin(), run.end(),
                                                   [](const Point2& a, const Point2& b) { return a.z < b.z; });
    node.zLow = zLow->z;
    node.zHigh = zHigh->z;
    const Chord chord = chordOf(run);
    node.across = bandHolding(run, chord.uz, -chord.ur);
    node.along = bandHolding(run, chord.ur, chord.uz);
    const std::size_t subtreeSize = 2 * (item.last - item.first) - 1;
    node.skip = static_cast<std::uint32_t>(item.node + subtreeSize);
    if (item.last - item.first == 1) {
      node.segment = static_cast<std::uint32_t>(item.first);
      continue;
    }
    node.segment = StripNode::kInner;
    const std::size_t split = item.first + farthestFromChord(run, chord);
    const std::size_t leftSize = 2 * (split - item.first) - 1;
    work.push_back({split, item.last, item.node + 1 + leftSize});
    work.push_back({item.first, split, item.node + 1});
  }
  return tree;
}

}  // namespace revolve::detail
