// Searching the wide MIBIT tree (wide_tree.h): nearest children first, leaves scanned kLanes
// segments at a time, the best hit so far pruning everything that begins after it.
//
// The shells are tested with rho^2(s) = a (s - sAxis)^2 + beta (Lagrange's identity; sAxis = 0 and
// beta = rho^2 when the ray is parallel to the axis, a = 0), two multiplications fewer than
// |o + s d|^2. Both are sums of non-negative terms; within the bounding sphere this one is within
// 32 u R^2 of the true rho^2 (the errors of a, sAxis and beta each contribute at most ~9 u R^2, since
// sqrt(a) |s - sAxis| <= rho <= R and sqrt(a) |sAxis| <= R), and the leaves' |o + s d|^2 within
// 40 u R^2 (MeridianRay): the shells' margin, 128 u R^2, covers both, so no shell prunes a segment
// whose leaf computation would report a hit. Slab ends are the leaves' own plane crossings.
//
// Rays in a horizontal plane (dz = 0) take the binary search, whose half-open height rule they need.
#pragma once

#include "kernel/meridian_ray.h"
#include "mibit/wide_tree.h"
#include "util/isa.h"
#include "util/simd.h"

#include <cstdint>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

namespace wide_search_internal {

struct ShellRay {
  Lanes oz, invDz, lo, sAxis, a, beta;
};

inline ShellRay shellRayOf(const MeridianRay& ray) noexcept {
  const bool parallel = !(ray.a > 0.0);
  return {splat(ray.oz),  splat(ray.invDz), splat(ray.lo),
          splat(parallel ? 0.0 : ray.sAxis), splat(ray.a),
          splat(parallel ? ray.ox * ray.ox + ray.oy * ray.oy : ray.beta)};
}

// Which of kLanes slabs [zA, zB] (either order) with cylinder shells [low2, high2] the ray meets
// within [lo, hi]; `entry` receives where it enters each.
[[gnu::always_inline]] inline unsigned shellsMet(const ShellRay& ray, Lanes hi, Lanes zA, Lanes zB, Lanes low2, Lanes high2,
                                                 Lanes& entry) noexcept {
  const Lanes sA = (zA - ray.oz) * ray.invDz, sB = (zB - ray.oz) * ray.invDz;
  const Lanes s0 = max(min(sA, sB), ray.lo), s1 = min(max(sA, sB), hi);
  const Lanes d0 = s0 - ray.sAxis, d1 = s1 - ray.sAxis;
  const Lanes q0 = ray.a * d0 * d0 + ray.beta, q1 = ray.a * d1 * d1 + ray.beta;
  // Not inside the inner cylinder throughout; and either an end within the outer one, or the
  // closest approach to the axis between the ends and within it.
  const LaneMask leavesInner = low2 <= max(q0, q1);
  const LaneMask reachesOuter = (min(q0, q1) <= high2) | ((s0 < ray.sAxis) & (ray.sAxis < s1) & (ray.beta <= high2));
  entry = s0;
  return bits((s0 <= s1) & leavesInner & reachesOuter);
}

struct Entry {
  std::uint32_t ref;
  double s;  // where the ray enters the subtree's shell
};

}  // namespace wide_search_internal

// Calls visitSegment(k) for every segment k the search cannot rule out, nearest regions first;
// visitSegment returns true to end the search and may lower `hi`. The ray must not be in-plane.
template <bool kCount, class VisitSegment>
inline void searchWide(const WideTree& tree, const MeridianRay& ray, double& hi, VisitSegment&& visitSegment,
                       Stats& stats) noexcept {
  using namespace wide_search_internal;
  const ShellRay shellRay = shellRayOf(ray);
  const bool dzPositive = ray.dz > 0.0;
  Entry stack[WideTree::kStackEntries];
  int top = 0;
  Entry current{tree.root, ray.lo};
  for (;;) {
    if (current.s <= hi) {
      if constexpr (kCount) ++stats.nodesVisited;
      const Lanes hiLanes = splat(hi);
      if (current.ref & WideTree::kLeafBit) {
        // A monotone run: candidates in index order are candidates in ray order.
        const WideLeaf& leaf = tree.leaves[current.ref & ~WideTree::kLeafBit];
        const std::uint32_t first = leaf.firstSegment, count = leaf.segmentCount;
        double entries[WideTree::kLeafSegments + kLanes];
        std::uint64_t candidates = 0;
        for (std::uint32_t c = 0; c < count; c += kLanes) {
          const std::uint32_t k = first + c;
          Lanes entry;
          const unsigned met = shellsMet(shellRay, hiLanes, load(&tree.vertexZ[k]), load(&tree.vertexZ[k + 1]),
                                         load(&tree.segmentLow2[k]), load(&tree.segmentHigh2[k]), entry);
          store(&entries[c], entry);
          candidates |= std::uint64_t(met) << c;
        }
        if constexpr (kCount) stats.shellTests += count;
        if (count < 64) candidates &= (std::uint64_t{1} << count) - 1;  // lanes past the run
        const bool forward = leaf.zAscending == dzPositive;
        while (candidates != 0) {
          const int j = forward ? __builtin_ctzll(candidates) : 63 - __builtin_clzll(candidates);
          candidates ^= std::uint64_t{1} << j;
          if (entries[j] > hi) break;  // and so is every later one
          if (visitSegment(first + std::uint32_t(j))) return;
        }
      } else {
        const WideNode& node = tree.nodes[current.ref];
        double entries[WideNode::kWidth];
        unsigned met = 0;
        for (int c = 0; c < WideNode::kWidth; c += kLanes) {
          Lanes entry;
          met |= shellsMet(shellRay, hiLanes, load(&node.zLow[c]), load(&node.zHigh[c]), load(&node.low2[c]),
                           load(&node.high2[c]), entry)
                 << c;
          store(&entries[c], entry);
        }
        if constexpr (kCount) stats.shellTests += node.childCount;
        if (met != 0) {
          // Nearest first: the nearest becomes current, the others go on the stack farthest first.
          Entry children[WideNode::kWidth];
          int count = 0;
          for (; met != 0; met &= met - 1) {
            const int j = __builtin_ctz(met);
            Entry child{node.child[j], entries[j]};
            int i = count++;
            for (; i > 0 && children[i - 1].s < child.s; --i) children[i] = children[i - 1];
            children[i] = child;
          }
          for (int i = 0; i + 1 < count; ++i) stack[top++] = children[i];
          current = children[count - 1];
          continue;
        }
      }
    }
    if (top == 0) return;
    current = stack[--top];
  }
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
