#include "kajiya/strip_tree.h"

#include "kernel/chord_band.h"

#include <algorithm>
#include <cmath>

namespace revolve::detail {
namespace {

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
    const auto [zLow, zHigh] =
        std::minmax_element(run.begin(), run.end(), [](const Point2& a, const Point2& b) { return a.z < b.z; });
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
