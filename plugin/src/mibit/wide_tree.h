// The MIBIT tree laid out for SIMD: the default search of cylinder-shell MIBIT.
//
// The tree is the paper's: monotone intervals, refined uniformly (MR), grouped (MG). What changes is
// its shape in memory. A leaf is a run of up to kLeafSegments segments of one monotone interval,
// and its segments' own cylinder shells are tested kLanes at a time before any Wang quadratic is
// set up; since z is monotone along the run, the segments that pass are met by the ray in index
// order, and the run is visited in that order with no sorting. Above the leaves, nodes of eight
// children test all their children's shells at once. A profile of up to 64 segments a monotone
// interval thus costs one node test and a scan; 16,384 points cost four levels instead of the
// binary tree's fourteen, each a handful of SIMD operations rather than a chain of branches.
//
// Shell bounds are the exact vertex heights and radii (doubles); the squared radii carry the shell
// margin (MeridianRay::rho2Margin), so a shell never prunes a segment the ray hits.
#pragma once

#include <revolve/revolve.h>

#include "mibit/mibit_tree.h"

#include <cstdint>
#include <span>
#include <vector>

namespace revolve::detail {

struct WideNode {
  static constexpr int kWidth = 8;
  // Per child: the slab zLow <= z <= zHigh and the cylinder shell low2 <= rho^2 <= high2 (squared
  // radii minus / plus the margin). An empty slot has low2 = +inf: no ray passes it.
  double zLow[kWidth], zHigh[kWidth], low2[kWidth], high2[kWidth];
  std::uint32_t child[kWidth];  // a node index, or kLeafBit | a leaf index
  std::uint32_t childCount;     // slots in use, from the first
};

struct WideLeaf {
  std::uint32_t firstSegment, segmentCount;  // 1 to kLeafSegments segments
  bool zAscending;                           // z grows with the segment index along the run
};

struct WideTree {
  static constexpr std::uint32_t kLeafBit = 0x80000000u;
  static constexpr std::uint32_t kLeafSegments = 32;  // a leaf's candidates fit one 64-bit mask
  static constexpr std::uint32_t kPadding = 8;        // entries past the end, for whole-register loads
  static constexpr int kStackEntries = 128;           // the search's stack: 7 entries a level at most

  std::vector<WideNode> nodes;
  std::vector<WideLeaf> leaves;
  std::vector<double> vertexZ;             // z of every vertex, then kPadding copies of the last
  std::vector<double> segmentLow2, segmentHigh2;  // each segment's own shell, then kPadding empty ones
  std::uint32_t root = 0;   // a node index or kLeafBit | leaf index; meaningless when empty()
  std::uint32_t depth = 0;  // node levels above the leaves

  bool empty() const noexcept { return leaves.empty(); }
  std::size_t memoryBytes() const noexcept;
};

// `points` in the shape's local frame; `intervals` its monotone intervals; `rho2Margin` the shape's
// shell margin (ShapeFrame::rho2Margin).
WideTree buildWideTree(std::span<const Point2> points, std::span<const MonotoneInterval> intervals, double rho2Margin);

}  // namespace revolve::detail
