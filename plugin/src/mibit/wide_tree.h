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

#include <cstddef>
#include <cstdint>
#include <memory>
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

// All arrays sit in one allocation, each at an offset into it: a 64-point profile's tree was
// fourteen vectors, 336 bytes of headers and as many heap blocks, for arrays that are mostly empty.
static_assert(alignof(WideNode) == 4 && alignof(WideLeaf) == 4 && sizeof(WideLeaf) % 4 == 0 && sizeof(float) == 4);

class WideTree {
 public:
  static constexpr std::uint32_t kLeafBit = 0x80000000u;
  static constexpr std::uint32_t kLeafSegments = 32;  // a leaf's candidates fit one 64-bit mask
  static constexpr std::uint32_t kPadding = 8;        // entries past the end, for whole-register loads
  static constexpr int kStackEntries = 256;           // the search's stack: 63 entries a level at most
  // The float evaluation's error bound in rho^2, in units of R^2 (see wide_search.h), with room.
  static constexpr double kFloatSlack = 64.0 * 0x1p-24;
  // Profiles of at most kFlatSegments segments are scanned whole, without the tree.
  static constexpr std::uint32_t kFlatSegments = 64;
  // A scanned profile of more than kRunScan segments also has the union of each run of
  // kRunSegments segments' shells, then empty ones up to kFlatSegments / kRunSegments: a ray tests
  // these first, then only the segments of the runs whose union it meets.
  static constexpr std::uint32_t kRunScan = 32, kRunSegments = 8;

  // What the tree holds, as the builder (wide_tree.cpp) gathers it; the tree copies it into its
  // one allocation.
  struct Parts {
    std::vector<WideNode> nodes;
    std::vector<WideLeaf> leaves;
    // Children of all nodes, node by node: the slab zLow <= z <= zHigh and the cylinder shell
    // low2 <= rho^2 <= high2 of each (squared radii with the margin), then kPadding empty records
    // (low2 = +inf: no ray passes them), and what each child is (a node index, or kLeafBit | a leaf).
    std::vector<float> childZLow, childZHigh, childLow2, childHigh2;
    std::vector<std::uint32_t> childRef;
    // Each segment's own shell, then kPadding empty ones.
    std::vector<float> segmentZLow, segmentZHigh, segmentLow2, segmentHigh2;
    // The runs' unions (kRunScan < segments <= kFlatSegments), else empty.
    std::vector<float> runZLow, runZHigh, runLow2, runHigh2;
    std::uint32_t root = 0, depth = 0, flatSegments = 0;
  };

  WideTree() = default;
  explicit WideTree(const Parts& parts);

  std::uint32_t root = 0;          // a node index or kLeafBit | leaf index; meaningless when empty() or scanned
  std::uint32_t depth = 0;         // node levels above the leaves
  std::uint32_t flatSegments = 0;  // the segment count of a profile scanned whole, else 0

  std::span<const WideNode> nodes() const noexcept { return array<WideNode>(nodesAt(), nodeCount_); }
  std::span<const WideLeaf> leaves() const noexcept { return array<WideLeaf>(leavesAt(), leafCount_); }
  std::span<const float> childZLow() const noexcept { return floats(childrenAt(), 0, childRecords_); }
  std::span<const float> childZHigh() const noexcept { return floats(childrenAt(), 1, childRecords_); }
  std::span<const float> childLow2() const noexcept { return floats(childrenAt(), 2, childRecords_); }
  std::span<const float> childHigh2() const noexcept { return floats(childrenAt(), 3, childRecords_); }
  std::span<const std::uint32_t> childRef() const noexcept {
    return array<std::uint32_t>(childrenAt() + 4 * sizeof(float) * childRecords_, childRecords_);
  }
  std::span<const float> segmentZLow() const noexcept { return floats(0, 0, segmentRecords_); }
  std::span<const float> segmentZHigh() const noexcept { return floats(0, 1, segmentRecords_); }
  std::span<const float> segmentLow2() const noexcept { return floats(0, 2, segmentRecords_); }
  std::span<const float> segmentHigh2() const noexcept { return floats(0, 3, segmentRecords_); }
  std::span<const float> runZLow() const noexcept { return floats(runsAt(), 0, runRecords_); }
  std::span<const float> runZHigh() const noexcept { return floats(runsAt(), 1, runRecords_); }
  std::span<const float> runLow2() const noexcept { return floats(runsAt(), 2, runRecords_); }
  std::span<const float> runHigh2() const noexcept { return floats(runsAt(), 3, runRecords_); }

  // Not built (the shape's options or scale call for the binary tree). A scanned profile
  // (flatSegments > 0) has its segments' and runs' records and no nodes, leaves or children.
  // (A moved-from tree, whose storage went with the move, is empty too.)
  bool empty() const noexcept { return segmentRecords_ == 0 || storage_ == nullptr; }
  std::size_t memoryBytes() const noexcept {
    return bytesOf(segmentRecords_, runRecords_, childRecords_, nodeCount_, leafCount_);
  }

 private:
  // In the one allocation, in this order: the segments' records (four floats each, array by
  // array), the runs', the children's (four floats, then childRef), the nodes, the leaves. Every
  // element is trivially copyable, 4-byte aligned and a multiple of 4 bytes wide, so each array's
  // offset suits it; an array of std::byte provides storage in which the elements copied in begin
  // their lifetime. Offsets, in bytes, follow from the counts rather than being stored.
  static constexpr std::size_t kRecordBytes = 4 * sizeof(float), kChildBytes = kRecordBytes + sizeof(std::uint32_t);
  std::size_t runsAt() const noexcept { return kRecordBytes * segmentRecords_; }
  std::size_t childrenAt() const noexcept { return runsAt() + kRecordBytes * runRecords_; }
  std::size_t nodesAt() const noexcept { return childrenAt() + kChildBytes * childRecords_; }
  std::size_t leavesAt() const noexcept { return nodesAt() + sizeof(WideNode) * nodeCount_; }
  static std::size_t bytesOf(std::size_t segments, std::size_t runs, std::size_t children, std::size_t nodes,
                             std::size_t leaves) noexcept {
    return kRecordBytes * (segments + runs) + kChildBytes * children + sizeof(WideNode) * nodes +
           sizeof(WideLeaf) * leaves;
  }
  template <class T>
  std::span<const T> array(std::size_t at, std::uint32_t count) const noexcept {
    return {reinterpret_cast<const T*>(storage_.get() + at), count};
  }
  std::span<const float> floats(std::size_t at, int which, std::uint32_t count) const noexcept {
    return array<float>(at + std::size_t(which) * sizeof(float) * count, count);
  }

  std::unique_ptr<std::byte[]> storage_;
  std::uint32_t segmentRecords_ = 0, runRecords_ = 0, childRecords_ = 0, nodeCount_ = 0, leafCount_ = 0;
};

// `points` in the shape's local frame; `intervals` its monotone intervals; `frame` its bounding
// sphere and shell margin.
WideTree buildWideTree(std::span<const Point2> points, std::span<const MonotoneInterval> intervals,
                       const ShapeFrame& frame);

}  // namespace revolve::detail
