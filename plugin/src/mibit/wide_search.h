// Searching the wide MIBIT tree (wide_tree.h): nearest children first, leaves scanned
// kFloatLanes segments at a time, the best hit so far pruning everything that begins after it.
//
// The shell test runs in single precision and is made conservative by error bounds; it only
// filters, and the double-precision leaves alone decide hits. With rho^2(s) = a (s - sAxis)^2 + beta
// (Lagrange's identity; sAxis = 0 and beta = rho^2 when the ray is parallel to the axis, a = 0):
//   - Stretch. A slab's plane crossing (z - oz) / dz, computed from float z (rounded outwards), oz and
//     1 / dz, is within 2^-24 (4 R |1/dz| + 2 |s|) of the leaves' double one; only crossings with
//     |s| <= 2R can reach [lo, hi] (|lo|, |hi| <= R), so widening the stretch by
//     2^-21 R (|1/dz| + 1) on each side, and rounding lo down and hi up, holds the leaves' bracket.
//   - Radius. Over that stretch rho^2 is convex, its range is spanned by the ends and the closest
//     approach to the axis. The float q = a (s - sAxis)^2 + beta at an end is within 13 2^-24 R^2 of
//     the true value (with sqrt(a) |s - sAxis| <= R and sqrt(a) |sAxis| <= R: 6 units from sAxis's
//     rounding and the subtraction, 3 from a's and the products', 2 from beta's, 2 from the sum);
//     the shells carry WideTree::kFloatSlack = 64 2^-24 R^2 on top of the leaves' own margin.
// So no shell prunes a segment whose leaf computation would report a hit, and entries (float, from
// the widened stretch) never lie after the true ones, so pruning by the best hit stays safe.
//
// Rays the float filter cannot serve (wideSearchServes) take the binary search; shapes whose
// bounding radius lies outside [2^-50, 2^50], where float's range would not hold R^2 with room,
// have no wide tree (shape.cpp).
#pragma once

#include "kernel/meridian_ray.h"
#include "mibit/wide_tree.h"
#include "util/isa.h"
#include "util/simd.h"

#include <cmath>
#include <cstdint>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

namespace wide_search_internal {

struct ShellRay {
  FloatLanes oz, invDz, lo, sAxis, a, beta, widen;
  float loScalar;
};

// hi rounded up to a float (the stretch must not lose its end to rounding).
inline float floatHi(double hi) noexcept { return float(hi + (std::abs(hi) * 0x1p-23 + 0x1p-140)); }

[[gnu::always_inline]] inline ShellRay shellRayOf(const MeridianRay& ray, double sphereRadius) noexcept {
  const bool parallel = !(ray.a > 0.0);
  const auto lo = float(ray.lo - (std::abs(ray.lo) * 0x1p-23 + 0x1p-140));  // a float below lo
  return {splatFloat(float(ray.oz)),
          splatFloat(float(ray.invDz)),
          splatFloat(lo),
          splatFloat(float(parallel ? 0.0 : ray.sAxis)),
          splatFloat(float(ray.a)),
          splatFloat(float(parallel ? ray.ox * ray.ox + ray.oy * ray.oy : ray.beta)),
          splatFloat(float(0x1p-21 * sphereRadius * (std::abs(ray.invDz) + 1.0))),
          lo};
}

// Which of kFloatLanes shells (slab [zLow, zHigh], cylinder [low2, high2]) the ray meets within
// [lo, hi]; `entry` receives where it enters each (never after the true entry).
[[gnu::always_inline]] inline unsigned shellsMet(const ShellRay& ray, FloatLanes hi, FloatLanes zLow, FloatLanes zHigh,
                                                 FloatLanes low2, FloatLanes high2, FloatLanes& entry) noexcept {
  const FloatLanes sA = (zLow - ray.oz) * ray.invDz, sB = (zHigh - ray.oz) * ray.invDz;
  const FloatLanes s0 = max(min(sA, sB) - ray.widen, ray.lo), s1 = min(max(sA, sB) + ray.widen, hi);
  const FloatLanes d0 = s0 - ray.sAxis, d1 = s1 - ray.sAxis;
  const FloatLanes q0 = ray.a * d0 * d0 + ray.beta, q1 = ray.a * d1 * d1 + ray.beta;
  // Not inside the inner cylinder throughout; and either an end within the outer one, or the
  // closest approach to the axis between the ends and within it.
  const FloatMask leavesInner = low2 <= max(q0, q1);
  const FloatMask reachesOuter = (min(q0, q1) <= high2) | ((s0 < ray.sAxis) & (ray.sAxis < s1) & (ray.beta <= high2));
  entry = s0;
  return bits((s0 <= s1) & leavesInner & reachesOuter);
}

struct Entry {
  std::uint32_t ref;
  float s;  // where the ray enters the subtree's shell, or before
};

}  // namespace wide_search_internal

// Whether the wide search serves this ray: 1 / dz and a within float's normal range (not in or
// within 2^-64 of a horizontal plane; parallel to the axis or at least 2^-50 away from it).
inline bool wideSearchServes(const MeridianRay& ray) noexcept {
  return std::abs(ray.invDz) <= 0x1p64 && (ray.a == 0.0 || ray.a >= 0x1p-100);
}

// Calls visitSegment(k) for every segment k the search cannot rule out, nearest regions first;
// visitSegment returns true to end the search and may lower `hi`. Requires wideSearchServes(ray).
template <bool kCount, class VisitSegment>
inline void searchWide(const WideTree& tree, const MeridianRay& ray, double sphereRadius, double& hi,
                       VisitSegment&& visitSegment, Stats& stats) noexcept {
  using namespace wide_search_internal;
  const ShellRay shellRay = shellRayOf(ray, sphereRadius);
  const bool dzPositive = ray.dz > 0.0;
  // The arrays' addresses, once: they lie at offsets into the tree's one allocation.
  const float *segmentZLow = tree.segmentZLow().data(), *segmentZHigh = tree.segmentZHigh().data(),
              *segmentLow2 = tree.segmentLow2().data(), *segmentHigh2 = tree.segmentHigh2().data();
  if (tree.flatSegments > 0) {
    // A small profile: every segment's shell at once, no tree; the few candidates sorted by entry.
    const FloatLanes hiLanes = splatFloat(floatHi(hi));
    float entries[64 + kFloatLanes];
    std::uint64_t candidates = 0;
    if (tree.flatSegments <= WideTree::kRunScan) {
      for (std::uint32_t c = 0; c < tree.flatSegments; c += kFloatLanes) {
        FloatLanes entry;
        const unsigned met = shellsMet(shellRay, hiLanes, load(&segmentZLow[c]), load(&segmentZHigh[c]),
                                       load(&segmentLow2[c]), load(&segmentHigh2[c]), entry);
        store(&entries[c], entry);
        candidates |= std::uint64_t(met) << c;
      }
      if constexpr (kCount) stats.shellTests += tree.flatSegments;
    } else {
      // The runs' unions first, then the segments of the runs the ray meets: a ray meets few of
      // them (2.6 of the 8 runs of a 64-point vase, on average over the benchmark's rays).
      constexpr std::uint32_t kRuns = WideTree::kFlatSegments / WideTree::kRunSegments;
      static_assert(kRuns <= 8 && WideTree::kRunSegments % kFloatLanes == 0);
      unsigned runs = 0;
      for (std::uint32_t c = 0; c < kRuns; c += kFloatLanes) {
        FloatLanes entry;
        runs |= shellsMet(shellRay, hiLanes, load(&tree.runZLow()[c]), load(&tree.runZHigh()[c]),
                          load(&tree.runLow2()[c]), load(&tree.runHigh2()[c]), entry)
                << c;
      }
      if constexpr (kCount) stats.shellTests += kRuns + WideTree::kRunSegments * unsigned(__builtin_popcount(runs));
      for (; runs != 0; runs &= runs - 1) {
        const std::uint32_t first = std::uint32_t(__builtin_ctz(runs)) * WideTree::kRunSegments;
        for (std::uint32_t c = first; c < first + WideTree::kRunSegments; c += kFloatLanes) {
          FloatLanes entry;
          const unsigned met = shellsMet(shellRay, hiLanes, load(&segmentZLow[c]), load(&segmentZHigh[c]),
                                         load(&segmentLow2[c]), load(&segmentHigh2[c]), entry);
          store(&entries[c], entry);
          candidates |= std::uint64_t(met) << c;
        }
      }
    }
    if constexpr (kCount) ++stats.nodesVisited;
    candidates &= (std::uint64_t{2} << (tree.flatSegments - 1)) - 1;
    Entry sorted[64];
    int count = 0;
    for (; candidates != 0; candidates &= candidates - 1) {
      const int j = __builtin_ctzll(candidates);
      const Entry candidate{std::uint32_t(j), entries[j]};
      int i = count++;
      for (; i > 0 && sorted[i - 1].s > candidate.s; --i) sorted[i] = sorted[i - 1];
      sorted[i] = candidate;
    }
    for (int i = 0; i < count; ++i) {
      if (sorted[i].s > hi) break;
      if (visitSegment(sorted[i].ref)) return;
    }
    return;
  }
  const float *childZLow = tree.childZLow().data(), *childZHigh = tree.childZHigh().data(),
              *childLow2 = tree.childLow2().data(), *childHigh2 = tree.childHigh2().data();
  const std::uint32_t* childRef = tree.childRef().data();
  const WideNode* nodes = tree.nodes().data();
  const WideLeaf* leaves = tree.leaves().data();
  Entry stack[WideTree::kStackEntries];
  int top = 0;
  Entry current{tree.root, shellRay.loScalar};
  for (;;) {
    if (current.s <= hi) {
      if constexpr (kCount) ++stats.nodesVisited;
      const FloatLanes hiLanes = splatFloat(floatHi(hi));
      if (current.ref & WideTree::kLeafBit) {
        // A monotone run: candidates in index order are candidates in ray order.
        const WideLeaf& leaf = leaves[current.ref & ~WideTree::kLeafBit];
        const std::uint32_t first = leaf.firstSegment, count = leaf.segmentCount;
        float entries[WideTree::kLeafSegments + kFloatLanes];
        std::uint64_t candidates = 0;
        for (std::uint32_t c = 0; c < count; c += kFloatLanes) {
          const std::uint32_t k = first + c;
          FloatLanes entry;
          const unsigned met = shellsMet(shellRay, hiLanes, load(&segmentZLow[k]), load(&segmentZHigh[k]),
                                         load(&segmentLow2[k]), load(&segmentHigh2[k]), entry);
          store(&entries[c], entry);
          candidates |= std::uint64_t(met) << c;
        }
        if constexpr (kCount) stats.shellTests += count;
        candidates &= (std::uint64_t{2} << (count - 1)) - 1;  // lanes past the run
        const bool forward = leaf.zAscending == dzPositive;
        while (candidates != 0) {
          const int j = forward ? __builtin_ctzll(candidates) : 63 - __builtin_clzll(candidates);
          candidates ^= std::uint64_t{1} << j;
          if (entries[j] > hi) break;  // and so is every later one
          if (visitSegment(first + std::uint32_t(j))) return;
        }
      } else {
        const WideNode& node = nodes[current.ref];
        const std::uint32_t first = node.firstChild, count = node.childCount;
        float entries[WideNode::kMaxChildren + kFloatLanes];
        std::uint64_t met = 0;
        for (std::uint32_t c = 0; c < count; c += kFloatLanes) {
          const std::uint32_t k = first + c;
          FloatLanes entry;
          met |= std::uint64_t(shellsMet(shellRay, hiLanes, load(&childZLow[k]), load(&childZHigh[k]),
                                         load(&childLow2[k]), load(&childHigh2[k]), entry))
                 << c;
          store(&entries[c], entry);
        }
        if constexpr (kCount) stats.shellTests += count;
        met &= (std::uint64_t{2} << (count - 1)) - 1;  // records past the node's
        if (met != 0) {
          // Nearest first: the nearest becomes current, the others go on the stack farthest first.
          Entry children[WideNode::kMaxChildren];
          int passed = 0;
          for (; met != 0; met &= met - 1) {
            const int j = __builtin_ctzll(met);
            const Entry child{childRef[first + std::uint32_t(j)], entries[j]};
            int i = passed++;
            for (; i > 0 && children[i - 1].s < child.s; --i) children[i] = children[i - 1];
            children[i] = child;
          }
          for (int i = 0; i + 1 < passed; ++i) stack[top++] = children[i];
          current = children[passed - 1];
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
