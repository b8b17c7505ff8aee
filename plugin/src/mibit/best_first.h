// Best-first branch and bound over the MIBIT tree's meridian boxes, for the queries that minimise a
// distance-like value over the profile's segments: closestPoint (queries.cpp) and
// cylinderClearance (clearance.cpp). Not on the ray path, which has its own searches.
#pragma once

#include "mibit/mibit_tree.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>

namespace revolve::detail {

// Visits the segments that may beat the best value found so far, nearer boxes first.
//   bound(rMin, rMax, zLow, zHigh): a lower bound of the value over every segment inside that box
//     of the meridian plane (shape-local coordinates);
//   pruned(b): whether a box bounded by b cannot hold anything better than the best so far;
//   visit(k): evaluates segment k (vertices k, k + 1) and keeps it if better.
// Node boxes are floats rounded outwards (mibit_tree.h), and inside a monotone interval a run's box
// is spanned by its end vertices, so every box holds its segments and no segment that could
// improve the best is skipped.
template <class Points, class Bound, class Pruned, class Visit>
void searchBestFirst(const MibitTree& tree, const Points& local, Bound bound, Pruned pruned, Visit visit) {
  struct NodeEntry {
    std::uint32_t node;
    double bound;
  };
  NodeEntry stack[64];  // depth + 1 entries at most, as in the ray search
  int top = 0;
  const auto nodeBound = [&](const MibitNode& node) { return bound(node.rMin, node.rMax, node.zLow, node.zHigh); };
  stack[top++] = {0, nodeBound(tree.nodes[0])};
  while (top > 0) {
    const NodeEntry current = stack[--top];
    if (pruned(current.bound)) continue;
    const MibitNode& node = tree.nodes[current.node];
    if (node.kind == MibitNode::Kind::segments) {
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) visit(k);
    } else if (node.kind == MibitNode::Kind::inner) {
      const NodeEntry a{node.first, nodeBound(tree.nodes[node.first])};
      const NodeEntry b{node.first + 1, nodeBound(tree.nodes[node.first + 1])};
      stack[top++] = a.bound <= b.bound ? b : a;  // the nearer is popped first
      stack[top++] = a.bound <= b.bound ? a : b;
    } else {
      // A monotone interval, refined implicitly: halve its uniform leaves.
      const MonotoneInterval& interval = tree.intervals[node.first];
      const auto runBound = [&](std::uint32_t a, std::uint32_t b) {
        const Point2 p = local[a], q = local[b];
        return bound(std::min(p.r, q.r), std::max(p.r, q.r), std::min(p.z, q.z), std::max(p.z, q.z));
      };
      struct RunEntry {
        std::uint32_t leafBegin, leafEnd;
        double bound;
      };
      RunEntry runs[64];
      int runTop = 0;
      runs[runTop++] = {0, interval.leaves, -std::numeric_limits<double>::infinity()};  // its node's box passed
      while (runTop > 0) {
        const RunEntry run = runs[--runTop];
        if (pruned(run.bound)) continue;
        const std::uint32_t a = MibitTree::leafVertex(interval, run.leafBegin);
        const std::uint32_t b = MibitTree::leafVertex(interval, run.leafEnd);
        if (run.leafEnd - run.leafBegin == 1) {
          for (std::uint32_t k = a; k < b; ++k) visit(k);
          continue;
        }
        const std::uint32_t middle = (run.leafBegin + run.leafEnd) / 2;
        const std::uint32_t m = MibitTree::leafVertex(interval, middle);
        const RunEntry left{run.leafBegin, middle, runBound(a, m)};
        const RunEntry right{middle, run.leafEnd, runBound(m, b)};
        runs[runTop++] = left.bound <= right.bound ? right : left;
        runs[runTop++] = left.bound <= right.bound ? left : right;
      }
    }
  }
}

}  // namespace revolve::detail
