// The MIBIT tree laid out for SIMD: the default search of cylinder-shell MIBIT.
//
// The tree is the paper's: monotone intervals, refined uniformly (MR), grouped (MG). What changes is
// its shape in memory. A leaf is a run of up to kLeafSegments segments of one monotone interval,
// and its segments' own cylinder shells are tested kFloatLanes at a time (eight with AVX2, four
// with SSE2) before any Wang quadratic is set up; since z is monotone along the run, the segments
// that pass are met by the ray in index order, and the run is visited in that order with no
// sorting. Above the leaves, nodes of up to 64 children test all their children's shells the same
// way. A profile of up to kFlatSegments segments is scanned whole, as one run; 16,384 points cost
// a few node levels (64 children each) instead of the binary tree's fourteen, each a few SIMD
// operations rather than a chain of branches.
//
// The shells are a filter in single precision, made conservative: bounds rounded outwards, squared
// radii widened by the shell margin plus the float evaluation's error bound (wide_search.h), so a
// shell never prunes a segment whose double-precision leaf computation reports a hit.
#pragma once

#include <revolve/core.h>

#include "kernel/meridian_ray.h"
#include "mibit/mibit_tree.h"

#include <cstdint>
#include <span>
#include <vector>

namespace revolve::detail {

// A node: a range of child records (WideTree::child*), up to kMaxChildren, tested kFloatLanes at a
// time. Wide nodes keep the tree shallow: up to 2,048 segments need one node above the leaves.
struct WideNode {
  static constexpr std::uint32_t kMaxChildren = 64;  // a node's candidates fit one 64-bit mask
  std::uint32_t firstChild, childCount;
};

struct WideLeaf {
  std::uint32_t firstSegment, segmentCount;  // 1 to kLeafSegments segments
  bool zAscending;                           // z grows with the segment index along the run
};

struct WideTree {
  static constexpr std::uint32_t kLeafBit = 0x80000000u;
  static constexpr std::uint32_t kLeafSegments = 32;  // a leaf's candidates fit one 64-bit mask
  static constexpr std::uint32_t kPadding = 8;        // entries past the end, for whole-register loads
  static constexpr int kStackEntries = 256;           // the search's stack: 63 entries a level at most
  // The float evaluation's error bound in rho^2, in units of R^2 (see wide_search.h), with room.
  static constexpr double kFloatSlack = 64.0 * 0x1p-24;

  std::vector<WideNode> nodes;
  std::vector<WideLeaf> leaves;
  // Children of all nodes, node by node: the slab zLow <= z <= zHigh and the cylinder shell
  // low2 <= rho^2 <= high2 of each (squared radii with the margin), then kPadding empty records
  // (low2 = +inf: no ray passes them), and what each child is (a node index, or kLeafBit | a leaf).
  std::vector<float> childZLow, childZHigh, childLow2, childHigh2;
  std::vector<std::uint32_t> childRef;
  // Each segment's own shell, then kPadding empty ones.
  std::vector<float> segmentZLow, segmentZHigh, segmentLow2, segmentHigh2;
  std::uint32_t root = 0;   // a node index or kLeafBit | leaf index; meaningless when empty()
  std::uint32_t depth = 0;  // node levels above the leaves
  // Profiles of at most kFlatSegments segments are scanned whole, without the tree: their count.
  static constexpr std::uint32_t kFlatSegments = 64;
  std::uint32_t flatSegments = 0;
  // A scanned profile of more than kRunScan segments also has the union of each run of
  // kRunSegments segments' shells, then empty ones up to kFlatSegments / kRunSegments: a ray tests
  // these first, then only the segments of the runs whose union it meets.
  static constexpr std::uint32_t kRunScan = 32, kRunSegments = 8;
  std::vector<float> runZLow, runZHigh, runLow2, runHigh2;

  bool empty() const noexcept { return leaves.empty(); }
  std::size_t memoryBytes() const noexcept;
};

// `points` in the shape's local frame; `intervals` its monotone intervals; `frame` its bounding
// sphere and shell margin.
WideTree buildWideTree(std::span<const Point2> points, std::span<const MonotoneInterval> intervals,
                       const ShapeFrame& frame);

}  // namespace revolve::detail
