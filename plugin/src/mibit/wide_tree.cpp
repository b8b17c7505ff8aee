#include "mibit/wide_tree.h"

#include "util/rounding.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>

namespace revolve::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A subtree as its parent sees it: where it is and what bounds it (exact, before rounding).
struct Child {
  std::uint32_t ref;
  double zLow, zHigh, rMin, rMax;
};

// A shell in single precision, rounded outwards: the slab widened to the floats around it, the
// squared radii widened by `margin` and rounded away from the shell.
struct FloatShell {
  float zLow, zHigh, low2, high2;
};

FloatShell floatShell(const Child& c, double margin) {
  return {floatBelow(c.zLow), floatAbove(c.zHigh), floatBelow(c.rMin * c.rMin - margin),
          floatAbove(c.rMax * c.rMax + margin)};
}

class Builder {
 public:
  Builder(std::span<const Point2> points, double margin, WideTree::Parts& tree)
      : points_(points), margin_(margin), tree_(tree) {}

  // MR: an interval refined uniformly into leaves of at most kLeafSegments segments.
  void addInterval(const MonotoneInterval& interval) {
    const std::uint32_t count = interval.segmentCount;
    const std::uint32_t parts = (count + WideTree::kLeafSegments - 1) / WideTree::kLeafSegments;
    for (std::uint32_t part = 0; part < parts; ++part) {
      const std::uint32_t begin = interval.firstSegment + std::uint32_t(std::uint64_t(part) * count / parts);
      const std::uint32_t end = interval.firstSegment + std::uint32_t(std::uint64_t(part + 1) * count / parts);
      const Point2 a = points_[begin], b = points_[end];  // a monotone run is bounded by its end vertices
      tree_.leaves.push_back({begin, end - begin, b.z > a.z});
      level_.push_back({WideTree::kLeafBit | std::uint32_t(tree_.leaves.size() - 1), std::min(a.z, b.z),
                        std::max(a.z, b.z), std::min(a.r, b.r), std::max(a.r, b.r)});
    }
  }

  // MG and the MR levels above the leaves: neighbours along the profile grouped up to kMaxChildren
  // at a time, level by level, up to one root.
  void group() {
    while (level_.size() > 1) {
      std::vector<Child> next;
      const std::size_t groups = (level_.size() + WideNode::kMaxChildren - 1) / WideNode::kMaxChildren;
      for (std::size_t g = 0; g < groups; ++g) {
        const std::size_t begin = g * level_.size() / groups, end = (g + 1) * level_.size() / groups;
        next.push_back(node(std::span<const Child>(level_).subspan(begin, end - begin)));
      }
      level_ = std::move(next);
      ++tree_.depth;
    }
    tree_.root = level_.front().ref;
  }

 private:
  Child node(std::span<const Child> children) {
    tree_.nodes.push_back({std::uint32_t(tree_.childRef.size()), std::uint32_t(children.size())});
    Child bounds{std::uint32_t(tree_.nodes.size() - 1), INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (const Child& c : children) {
      const FloatShell shell = floatShell(c, margin_);
      tree_.childZLow.push_back(shell.zLow);
      tree_.childZHigh.push_back(shell.zHigh);
      tree_.childLow2.push_back(shell.low2);
      tree_.childHigh2.push_back(shell.high2);
      tree_.childRef.push_back(c.ref);
      bounds.zLow = std::min(bounds.zLow, c.zLow);
      bounds.zHigh = std::max(bounds.zHigh, c.zHigh);
      bounds.rMin = std::min(bounds.rMin, c.rMin);
      bounds.rMax = std::max(bounds.rMax, c.rMax);
    }
    return bounds;
  }

  std::span<const Point2> points_;
  double margin_;
  WideTree::Parts& tree_;
  std::vector<Child> level_;
};

}  // namespace

namespace {
// Appends `values` to `storage` at `at`, and moves `at` past them.
template <class T>
void put(std::byte* storage, std::size_t& at, const std::vector<T>& values) {
  if (!values.empty()) std::memcpy(storage + at, values.data(), values.size() * sizeof(T));
  at += values.size() * sizeof(T);
}
}  // namespace

WideTree::WideTree(const Parts& parts)
    : root(parts.root),
      depth(parts.depth),
      flatSegments(parts.flatSegments),
      segmentRecords_(std::uint32_t(parts.segmentZLow.size())),
      runRecords_(std::uint32_t(parts.runZLow.size())),
      childRecords_(std::uint32_t(parts.childRef.size())),
      nodeCount_(std::uint32_t(parts.nodes.size())),
      leafCount_(std::uint32_t(parts.leaves.size())) {
  const std::size_t bytes = memoryBytes();
  if (bytes == 0) return;
  storage_ = std::make_unique_for_overwrite<std::byte[]>(bytes);
  std::size_t at = 0;
  for (const auto* v : {&parts.segmentZLow, &parts.segmentZHigh, &parts.segmentLow2, &parts.segmentHigh2,
                        &parts.runZLow, &parts.runZHigh, &parts.runLow2, &parts.runHigh2, &parts.childZLow,
                        &parts.childZHigh, &parts.childLow2, &parts.childHigh2})
    put(storage_.get(), at, *v);
  put(storage_.get(), at, parts.childRef);
  put(storage_.get(), at, parts.nodes);
  put(storage_.get(), at, parts.leaves);
  if (at != bytes) throw std::logic_error("wide MIBIT's arrays do not fill its allocation");
}

WideTree buildWideTree(std::span<const Point2> points, std::span<const MonotoneInterval> intervals,
                       const ShapeFrame& frame) {
  WideTree::Parts tree;
  // The leaves' double-precision margin plus the float filter's own error (wide_search.h).
  const double margin = frame.rho2Margin + WideTree::kFloatSlack * frame.sphereRadius * frame.sphereRadius;
  const std::size_t segments = points.size() - 1;
  for (auto* v : {&tree.segmentZLow, &tree.segmentZHigh, &tree.segmentLow2, &tree.segmentHigh2}) {
    v->reserve(segments + WideTree::kPadding);
  }
  for (std::size_t k = 0; k < segments; ++k) {
    const Point2 a = points[k], b = points[k + 1];
    const FloatShell shell =
        floatShell({0, std::min(a.z, b.z), std::max(a.z, b.z), std::min(a.r, b.r), std::max(a.r, b.r)}, margin);
    tree.segmentZLow.push_back(shell.zLow);
    tree.segmentZHigh.push_back(shell.zHigh);
    tree.segmentLow2.push_back(shell.low2);
    tree.segmentHigh2.push_back(shell.high2);
  }
  tree.segmentZLow.insert(tree.segmentZLow.end(), WideTree::kPadding, 0.0f);
  tree.segmentZHigh.insert(tree.segmentZHigh.end(), WideTree::kPadding, 0.0f);
  tree.segmentLow2.insert(tree.segmentLow2.end(), WideTree::kPadding, kInfinity);
  tree.segmentHigh2.insert(tree.segmentHigh2.end(), WideTree::kPadding, -kInfinity);

  if (segments <= WideTree::kFlatSegments) tree.flatSegments = std::uint32_t(segments);
  if (segments <= WideTree::kFlatSegments && segments > WideTree::kRunScan) {
    for (std::size_t first = 0; first < segments; first += WideTree::kRunSegments) {
      float zLow = kInfinity, zHigh = -kInfinity, low2 = kInfinity, high2 = -kInfinity;
      for (std::size_t k = first; k < std::min<std::size_t>(segments, first + WideTree::kRunSegments); ++k) {
        zLow = std::min(zLow, tree.segmentZLow[k]), zHigh = std::max(zHigh, tree.segmentZHigh[k]);
        low2 = std::min(low2, tree.segmentLow2[k]), high2 = std::max(high2, tree.segmentHigh2[k]);
      }
      tree.runZLow.push_back(zLow), tree.runZHigh.push_back(zHigh), tree.runLow2.push_back(low2),
          tree.runHigh2.push_back(high2);
    }
    const std::size_t runs = WideTree::kFlatSegments / WideTree::kRunSegments;
    tree.runZLow.resize(runs, 0.0f), tree.runZHigh.resize(runs, 0.0f);
    tree.runLow2.resize(runs, kInfinity), tree.runHigh2.resize(runs, -kInfinity);
  }
  // A scanned profile needs no tree: its search never reads one (wide_search.h).
  if (tree.flatSegments == 0) {
    Builder builder(points, margin, tree);
    for (const MonotoneInterval& interval : intervals) builder.addInterval(interval);
    builder.group();
    tree.childZLow.insert(tree.childZLow.end(), WideTree::kPadding, 0.0f);
    tree.childZHigh.insert(tree.childZHigh.end(), WideTree::kPadding, 0.0f);
    tree.childLow2.insert(tree.childLow2.end(), WideTree::kPadding, kInfinity);
    tree.childHigh2.insert(tree.childHigh2.end(), WideTree::kPadding, -kInfinity);
    tree.childRef.insert(tree.childRef.end(), WideTree::kPadding, 0u);
  }
  // Each level pushes at most 63 entries; within Profile::kMaxPoints the depth stays below 4.
  if (63 * int(tree.depth) + 1 > WideTree::kStackEntries)
    throw std::logic_error("wide MIBIT deeper than its search stack");
  return WideTree(tree);
}

}  // namespace revolve::detail
