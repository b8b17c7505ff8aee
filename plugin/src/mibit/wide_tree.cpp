#include "mibit/wide_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace revolve::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A subtree as its parent sees it: where it is and what bounds it.
struct Child {
  std::uint32_t ref;
  double zLow, zHigh, rMin, rMax;
};

class Builder {
 public:
  Builder(std::span<const Point2> points, double margin, WideTree& tree) : points_(points), margin_(margin), tree_(tree) {}

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

  // MG and the MR levels above the leaves: neighbours along the profile grouped eight at a time,
  // level by level, up to one root.
  void group() {
    while (level_.size() > 1) {
      std::vector<Child> next;
      const std::size_t groups = (level_.size() + WideNode::kWidth - 1) / WideNode::kWidth;
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
    WideNode node{};
    node.childCount = std::uint32_t(children.size());
    Child bounds{std::uint32_t(tree_.nodes.size()), kInfinity, -kInfinity, kInfinity, -kInfinity};
    for (int j = 0; j < WideNode::kWidth; ++j) {
      if (std::size_t(j) < children.size()) {
        const Child& c = children[j];
        node.zLow[j] = c.zLow;
        node.zHigh[j] = c.zHigh;
        node.low2[j] = c.rMin * c.rMin - margin_;
        node.high2[j] = c.rMax * c.rMax + margin_;
        node.child[j] = c.ref;
        bounds.zLow = std::min(bounds.zLow, c.zLow);
        bounds.zHigh = std::max(bounds.zHigh, c.zHigh);
        bounds.rMin = std::min(bounds.rMin, c.rMin);
        bounds.rMax = std::max(bounds.rMax, c.rMax);
      } else {
        node.zLow[j] = node.zHigh[j] = 0.0;
        node.low2[j] = kInfinity;
        node.high2[j] = -kInfinity;
        node.child[j] = 0;
      }
    }
    tree_.nodes.push_back(node);
    return bounds;
  }

  std::span<const Point2> points_;
  double margin_;
  WideTree& tree_;
  std::vector<Child> level_;
};

}  // namespace

std::size_t WideTree::memoryBytes() const noexcept {
  return nodes.capacity() * sizeof(WideNode) + leaves.capacity() * sizeof(WideLeaf) +
         (vertexZ.capacity() + segmentLow2.capacity() + segmentHigh2.capacity()) * sizeof(double);
}

WideTree buildWideTree(std::span<const Point2> points, std::span<const MonotoneInterval> intervals, double rho2Margin) {
  WideTree tree;
  const std::size_t segments = points.size() - 1;
  tree.vertexZ.reserve(points.size() + WideTree::kPadding);
  for (const Point2& p : points) tree.vertexZ.push_back(p.z);
  tree.vertexZ.insert(tree.vertexZ.end(), WideTree::kPadding, points.back().z);
  tree.segmentLow2.reserve(segments + WideTree::kPadding);
  tree.segmentHigh2.reserve(segments + WideTree::kPadding);
  for (std::size_t k = 0; k < segments; ++k) {
    const double rMin = std::min(points[k].r, points[k + 1].r), rMax = std::max(points[k].r, points[k + 1].r);
    tree.segmentLow2.push_back(rMin * rMin - rho2Margin);
    tree.segmentHigh2.push_back(rMax * rMax + rho2Margin);
  }
  tree.segmentLow2.insert(tree.segmentLow2.end(), WideTree::kPadding, kInfinity);
  tree.segmentHigh2.insert(tree.segmentHigh2.end(), WideTree::kPadding, -kInfinity);

  Builder builder(points, rho2Margin, tree);
  for (const MonotoneInterval& interval : intervals) builder.addInterval(interval);
  builder.group();
  // Each level pushes at most 7 entries; within Profile::kMaxPoints the depth stays below 12.
  if (7 * int(tree.depth) + 1 > WideTree::kStackEntries) throw std::logic_error("wide MIBIT deeper than its search stack");
  return tree;
}

}  // namespace revolve::detail
