// Searching the MIBIT tree: the explicit nodes (the paper's SearchMGI), handing monotone intervals
// to their implicit search (SearchMRI, interval_search.h).
//
// A node's range is the stretch of the ray inside its z slab. Against the ray's current range
// [lo, hi] the paper's overlap types decide the work: type 1 (disjoint) prunes with two
// comparisons; type 3 (the ray's range lies within the node's) passes on without a shell test,
// the node's children will narrow it; type 2 (partial overlap) runs the shell test. Beyond the
// paper, children are visited nearest first and a node is skipped once the best hit so far lies
// before its entry, so a ray typically walks one root-to-leaf path per surface crossing.
#pragma once

#include "util/isa.h"

#include "kernel/local_points.h"
#include "kernel/meridian_ray.h"
#include "kernel/shell_tests.h"
#include "mibit/interval_search.h"
#include "mibit/mibit_tree.h"

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// Whether the ray can meet anything under explicit node `index` within [lo, hi]; `entry` is where it
// would start.
template <bool kCount>
inline bool enterMibitNode(const MibitTree& tree, std::uint32_t index, const MeridianRay& ray, double lo, double hi,
                           bool rangeSearch, double& entry, Stats& stats) noexcept {
  const MibitNode& node = tree.nodes[index];
  double s0 = lo, s1 = hi;
  bool overlaps = true;
  bool contained = true;  // overlap type 3
  if (!ray.inPlane) {
    const double sLow = ray.planeS(node.zLow), sHigh = ray.planeS(node.zHigh);
    const double slab0 = std::min(sLow, sHigh), slab1 = std::max(sLow, sHigh);
    s0 = std::max(slab0, lo);
    s1 = std::min(slab1, hi);
    overlaps = s0 <= s1;
    contained = slab0 <= lo && hi <= slab1;
  } else {
    // Closed slab: a superset of the half-open height ranges the leaves own.
    overlaps = node.zLow <= ray.oz && ray.oz <= node.zHigh;
  }
  if (rangeSearch && !overlaps) return false;  // overlap type 1
  entry = s0;
  if (node.shell == NodeShell::none || (rangeSearch && contained)) return overlaps;
  if constexpr (kCount) ++stats.shellTests;
  if (!overlaps) return false;  // without range search the slab is part of the shell test
  return node.shell == NodeShell::cylinder ? cylinderShellPasses(ray, node.rMin, node.rMax, s0, s1)
                                           : bandPasses(ray, tree.cones[index].cone(), s0, s1);
}

// Calls visitSegment(k) for every segment k the search cannot rule out, nearest regions first.
// visitSegment returns true to end the search (any-hit queries); it may lower `hi` (nearest hit).
template <bool kCount, class VisitSegment>
inline void searchMibit(const MibitTree& tree, LocalPoints points, bool rangeSearch, const MeridianRay& ray, double& hi,
                        VisitSegment&& visitSegment, Stats& stats) noexcept {
  struct Entry {
    std::uint32_t node;
    double s;
  };
  // Each level pushes at most the farther of two children and descends into the nearer directly,
  // so the stack holds at most depth entries; buildMibitTree keeps depth below 64 (about
  // log2(intervals) + log2(leaves per interval) + 2).
  Entry stack[64];
  int top = 0;
  Entry current{0, 0.0};
  if (!enterMibitNode<kCount>(tree, 0, ray, ray.lo, hi, rangeSearch, current.s, stats)) return;

  for (;;) {
    bool descended = false;
    if (current.s <= hi) {  // else the best hit so far lies before this node
      const MibitNode& node = tree.nodes[current.node];
      if constexpr (kCount) ++stats.nodesVisited;
      if (node.kind == MibitNode::Kind::interval) {
        if (searchInterval<kCount>(tree, tree.intervals[node.first], points, rangeSearch, ray, hi, visitSegment,
                                   stats)) {
          return;
        }
      } else if (node.kind == MibitNode::Kind::segments) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
          if (visitSegment(k)) return;
        }
      } else {
        double entryA = 0.0, entryB = 0.0;
        const bool a = enterMibitNode<kCount>(tree, node.first, ray, ray.lo, hi, rangeSearch, entryA, stats);
        const bool b = enterMibitNode<kCount>(tree, node.first + 1, ray, ray.lo, hi, rangeSearch, entryB, stats);
        if (a && b) {
          const bool aFirst = entryA <= entryB;
          stack[top++] = aFirst ? Entry{node.first + 1, entryB} : Entry{node.first, entryA};
          current = aFirst ? Entry{node.first, entryA} : Entry{node.first + 1, entryB};
          descended = true;
        } else if (a || b) {
          current = a ? Entry{node.first, entryA} : Entry{node.first + 1, entryB};
          descended = true;
        }
      }
    }
    if (descended) continue;
    if (top == 0) return;
    current = stack[--top];
  }
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
