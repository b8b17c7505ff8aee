// The wide (SIMD) layout of the MIBIT tree (src/mibit/wide_tree.h) checked record by record, apart
// from the search, on every test profile and random ones, built as Shape builds it (local frame,
// padded bounding sphere, the profile's monotone intervals). What the search relies on:
// - every segment lies in exactly one leaf run, reached from the root exactly once; a run has 1 to
//   kLeafSegments segments of one monotone interval, and zAscending says which way z runs along it;
// - every child record's slab and squared-radius range hold its subtree's segments, widened by the
//   margin (the leaves' rho2Margin plus the float filter's kFloatSlack R^2) as the float bounds,
//   rounded outwards, promise; the same for each segment's own record and the flat scan's runs;
// - childCount <= kMaxChildren, every record belongs to one node, the padding records are empty;
// - the depth is the node levels above the leaves: the leaves grouped kMaxChildren at a time, level
//   by level, so every leaf lies at that depth and it is the ceiling of log64 of the leaf count;
// - a profile scanned whole (at most kFlatSegments segments) has no tree, only its records.
#include "mibit/wide_tree.h"
#include "mibit/mibit_tree.h"
#include "support/hard_profiles.h"
#include "support/test_profiles.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace revolve {
namespace {

using detail::WideLeaf;
using detail::WideNode;
using detail::WideTree;

constexpr double u = detail::kUnitRoundoff;

struct Built {
  std::vector<Point2> local;
  std::vector<detail::MonotoneInterval> intervals;
  detail::ShapeFrame frame;
  WideTree tree;
};

// As Shape builds it (shape.cpp): points about the centre of their z range, the bounding sphere
// through the farthest vertex padded by 2^-20.
Built build(std::span<const Point2> points) {
  Built b;
  double zMin = points[0].z, zMax = points[0].z;
  for (const Point2& p : points) zMin = std::min(zMin, p.z), zMax = std::max(zMax, p.z);
  const double zCentre = 0.5 * zMin + 0.5 * zMax;
  double radius = 0.0;
  for (const Point2& p : points) {
    b.local.push_back({p.r, p.z - zCentre});
    radius = std::max(radius, std::hypot(p.r, b.local.back().z));
  }
  b.frame = detail::makeShapeFrame(zCentre, radius * (1.0 + 0x1p-20));
  b.intervals = detail::monotoneIntervals(b.local);
  b.tree = detail::buildWideTree(b.local, b.intervals, b.frame);
  return b;
}

// The exact extent of segments [first, last) (their vertices first to last).
struct Extent {
  double zLow = INFINITY, zHigh = -INFINITY, rMin = INFINITY, rMax = -INFINITY;
  void add(Point2 p) {
    zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z), rMin = std::min(rMin, p.r), rMax = std::max(rMax, p.r);
  }
  void add(const Extent& e) {
    zLow = std::min(zLow, e.zLow), zHigh = std::max(zHigh, e.zHigh), rMin = std::min(rMin, e.rMin),
    rMax = std::max(rMax, e.rMax);
  }
};

// A record (zLow, zHigh, low2, high2) holds `extent` widened by `margin`: the slab exactly, and the
// squared radii within the double evaluation of r^2 -+ margin before its outward rounding (two
// roundings: 2 u (r^2 + margin)). And it is no looser than one float step beyond that: a record
// that held everything would prune nothing.
::testing::AssertionResult holds(float zLow, float zHigh, float low2, float high2, const Extent& e, double margin) {
  const long double lowExact = (long double)e.rMin * e.rMin - margin, highExact = (long double)e.rMax * e.rMax + margin;
  const long double lowSlack = 2 * u * ((long double)e.rMin * e.rMin + margin), highSlack = 2 * u * highExact;
  const auto step = [](long double x) { return std::ldexp(std::abs(x), -23); };  // two float ulps
  if (!(zLow <= e.zLow && e.zHigh <= zHigh)) return ::testing::AssertionFailure() << "slab misses a vertex";
  if (!(low2 <= lowExact + lowSlack && highExact - highSlack <= high2)) {
    return ::testing::AssertionFailure() << "[" << low2 << ", " << high2 << "] misses r^2 in [" << double(lowExact)
                                         << ", " << double(highExact) << "] with the margin";
  }
  if (!(e.zLow - zLow <= step(e.zLow) && zHigh - e.zHigh <= step(e.zHigh) &&
        lowExact - low2 <= step(lowExact) + lowSlack && high2 - highExact <= step(highExact) + highSlack)) {
    return ::testing::AssertionFailure() << "looser than a float step";
  }
  return ::testing::AssertionSuccess();
}

bool monotone(std::span<const Point2> points, std::size_t first, std::size_t count) {
  int dr = 0, dz = 0;
  const auto sign = [](double x) { return (x > 0) - (x < 0); };
  for (std::size_t k = first; k < first + count; ++k) {
    const int sr = sign(points[k + 1].r - points[k].r), sz = sign(points[k + 1].z - points[k].z);
    if ((sr != 0 && dr != 0 && sr != dr) || (sz != 0 && dz != 0 && sz != dz)) return false;
    if (sr != 0) dr = sr;
    if (sz != 0) dz = sz;
  }
  return true;
}

class WideCheck {
 public:
  explicit WideCheck(const Built& b)
      : b_(b),
        tree_(b.tree),
        points_(b.local),
        margin_(b.frame.rho2Margin + WideTree::kFloatSlack * b.frame.sphereRadius * b.frame.sphereRadius),
        segmentSeen_(points_.size() - 1, 0),
        leafSeen_(tree_.leaves().size(), 0),
        nodeSeen_(tree_.nodes().size(), 0),
        recordOwner_(tree_.childRef().size() >= WideTree::kPadding ? tree_.childRef().size() - WideTree::kPadding : 0,
                     0) {}

  void run() {
    const std::size_t segments = points_.size() - 1;
    ASSERT_FALSE(tree_.empty());
    checkSegmentRecords();
    checkFlatScan();
    if (tree_.flatSegments > 0) {
      // Scanned whole: no tree (the search reads none), only the segments' records and the runs'.
      EXPECT_TRUE(tree_.nodes().empty() && tree_.leaves().empty() && tree_.childRef().empty());
      EXPECT_EQ(tree_.depth, 0u);
      checkPadding();
      return;
    }
    subtree(tree_.root, 0);
    for (std::size_t k = 0; k < segments; ++k) ASSERT_EQ(segmentSeen_[k], 1) << "segment " << k << " in leaves";
    for (std::size_t i = 0; i < leafSeen_.size(); ++i) ASSERT_EQ(leafSeen_[i], 1) << "leaf " << i << " reached";
    for (std::size_t i = 0; i < nodeSeen_.size(); ++i) ASSERT_EQ(nodeSeen_[i], 1) << "node " << i << " reached";
    for (std::size_t i = 0; i < recordOwner_.size(); ++i) {
      ASSERT_EQ(recordOwner_[i], 1) << "child record " << i << " owned";
    }
    checkDepth();
    checkPadding();
  }

 private:
  Extent subtree(std::uint32_t ref, std::uint32_t depth) {
    Extent extent;
    if (ref & WideTree::kLeafBit) {
      const std::uint32_t index = ref & ~WideTree::kLeafBit;
      EXPECT_LT(index, tree_.leaves().size());
      if (index >= tree_.leaves().size()) return extent;
      ++leafSeen_[index];
      EXPECT_EQ(depth, tree_.depth) << "leaf " << index << " not at the tree's depth";
      const WideLeaf& leaf = tree_.leaves()[index];
      checkLeaf(index, leaf);
      for (std::uint32_t k = leaf.firstSegment; k < leaf.firstSegment + leaf.segmentCount && k < segmentSeen_.size();
           ++k) {
        ++segmentSeen_[k];
        extent.add(points_[k]);
        extent.add(points_[k + 1]);
      }
      return extent;
    }
    EXPECT_LT(ref, tree_.nodes().size());
    if (ref >= tree_.nodes().size()) return extent;
    ++nodeSeen_[ref];
    const WideNode& node = tree_.nodes()[ref];
    EXPECT_GE(node.childCount, 1u);
    EXPECT_LE(node.childCount, WideNode::kMaxChildren);
    EXPECT_LE(node.firstChild + node.childCount, recordOwner_.size())
        << "node " << ref << "'s records run into the padding";
    for (std::uint32_t c = node.firstChild; c < node.firstChild + node.childCount && c < recordOwner_.size(); ++c) {
      ++recordOwner_[c];
      const Extent child = subtree(tree_.childRef()[c], depth + 1);
      EXPECT_TRUE(holds(tree_.childZLow()[c], tree_.childZHigh()[c], tree_.childLow2()[c], tree_.childHigh2()[c], child,
                        margin_))
          << "node " << ref << ", child record " << c;
      extent.add(child);
    }
    return extent;
  }

  void checkLeaf(std::uint32_t index, const WideLeaf& leaf) {
    const std::string what = "leaf " + std::to_string(index) + " (segments " + std::to_string(leaf.firstSegment) +
                             " + " + std::to_string(leaf.segmentCount) + ")";
    EXPECT_GE(leaf.segmentCount, 1u) << what;
    EXPECT_LE(leaf.segmentCount, WideTree::kLeafSegments) << what;
    // Within one monotone interval (itself monotone: mibit_tree_test.cpp checks them)...
    bool within = false;
    for (const detail::MonotoneInterval& interval : b_.intervals) {
      within = within || (interval.firstSegment <= leaf.firstSegment &&
                          leaf.firstSegment + leaf.segmentCount <= interval.firstSegment + interval.segmentCount);
    }
    EXPECT_TRUE(within) << what << " spans two monotone intervals";
    EXPECT_TRUE(monotone(points_, leaf.firstSegment, leaf.segmentCount)) << what;
    // ...with z running the stated way: the search meets the run's segments in index order.
    const std::uint32_t end = leaf.firstSegment + leaf.segmentCount;
    for (std::uint32_t k = leaf.firstSegment; k < end; ++k) {
      const double dz = points_[k + 1].z - points_[k].z;
      EXPECT_TRUE(leaf.zAscending ? dz >= 0.0 : dz <= 0.0) << what << ": segment " << k << " runs against zAscending";
    }
    if (points_[end].z != points_[leaf.firstSegment].z) {
      EXPECT_EQ(leaf.zAscending, points_[end].z > points_[leaf.firstSegment].z) << what;
    }
  }

  // The leaves grouped kMaxChildren at a time until one is left: that many levels, and the leaf
  // count each interval's refinement into runs of at most kLeafSegments gives.
  void checkDepth() {
    std::size_t leaves = 0;
    for (const detail::MonotoneInterval& interval : b_.intervals) {
      leaves += (interval.segmentCount + WideTree::kLeafSegments - 1) / WideTree::kLeafSegments;
    }
    EXPECT_EQ(tree_.leaves().size(), leaves);
    std::uint32_t levels = 0;
    for (std::size_t n = leaves; n > 1; n = (n + WideNode::kMaxChildren - 1) / WideNode::kMaxChildren) ++levels;
    EXPECT_EQ(tree_.depth, levels);
    EXPECT_LE(63 * int(tree_.depth) + 1, WideTree::kStackEntries) << "the search's stack";
  }

  // kPadding empty records after the children's and the segments' own (low2 = +inf: no rho^2
  // reaches them), for the search's whole-register loads.
  void checkPadding() {
    const std::size_t records = recordOwner_.size();
    // A scanned profile has no child records at all, padding included.
    const std::size_t padding = tree_.flatSegments > 0 ? 0 : WideTree::kPadding;
    for (const std::span<const float> v :
         {tree_.childZLow(), tree_.childZHigh(), tree_.childLow2(), tree_.childHigh2()}) {
      ASSERT_EQ(v.size(), records + padding);
    }
    ASSERT_EQ(tree_.childRef().size(), records + padding);
    for (std::size_t i = records; i < records + padding; ++i) {
      EXPECT_EQ(tree_.childLow2()[i], INFINITY) << "padding record " << i;
      EXPECT_EQ(tree_.childHigh2()[i], -INFINITY) << "padding record " << i;
    }
    const std::size_t segments = points_.size() - 1;
    for (const std::span<const float> v :
         {tree_.segmentZLow(), tree_.segmentZHigh(), tree_.segmentLow2(), tree_.segmentHigh2()}) {
      ASSERT_EQ(v.size(), segments + WideTree::kPadding);
    }
    for (std::size_t k = segments; k < segments + WideTree::kPadding; ++k) {
      EXPECT_EQ(tree_.segmentLow2()[k], INFINITY) << "padding segment " << k;
      EXPECT_EQ(tree_.segmentHigh2()[k], -INFINITY) << "padding segment " << k;
    }
  }

  void checkSegmentRecords() {
    for (std::size_t k = 0; k + 1 < points_.size(); ++k) {
      Extent e;
      e.add(points_[k]);
      e.add(points_[k + 1]);
      ASSERT_TRUE(holds(tree_.segmentZLow()[k], tree_.segmentZHigh()[k], tree_.segmentLow2()[k],
                        tree_.segmentHigh2()[k], e, margin_))
          << "segment " << k << "'s own record";
    }
  }

  // A profile of at most kFlatSegments segments is scanned whole; beyond kRunScan of them, by runs of
  // kRunSegments whose unions hold their segments' records (the unused runs empty).
  void checkFlatScan() {
    const std::size_t segments = points_.size() - 1;
    EXPECT_EQ(tree_.flatSegments, segments <= WideTree::kFlatSegments ? segments : 0u);
    if (!(segments > WideTree::kRunScan && segments <= WideTree::kFlatSegments)) {
      EXPECT_TRUE(tree_.runLow2().empty());
      return;
    }
    const std::size_t runs = WideTree::kFlatSegments / WideTree::kRunSegments;
    ASSERT_EQ(tree_.runZLow().size(), runs);
    ASSERT_EQ(tree_.runLow2().size(), runs);
    for (std::size_t run = 0; run < runs; ++run) {
      const std::size_t first = run * WideTree::kRunSegments;
      if (first >= segments) {
        EXPECT_EQ(tree_.runLow2()[run], INFINITY) << "unused run " << run;
        continue;
      }
      for (std::size_t k = first; k < std::min(segments, first + WideTree::kRunSegments); ++k) {
        EXPECT_TRUE(tree_.runZLow()[run] <= tree_.segmentZLow()[k] &&
                    tree_.segmentZHigh()[k] <= tree_.runZHigh()[run] &&
                    tree_.runLow2()[run] <= tree_.segmentLow2()[k] && tree_.segmentHigh2()[k] <= tree_.runHigh2()[run])
            << "run " << run << " misses segment " << k;
      }
    }
  }

  const Built& b_;
  const WideTree& tree_;
  std::span<const Point2> points_;
  double margin_;
  std::vector<int> segmentSeen_, leafSeen_, nodeSeen_, recordOwner_;
};

TEST(WideTree, EverySegmentInOneLeafRunEveryRecordHoldsItsSubtreeDepthAsDocumented) {
  for (const std::uint64_t seed : testing::testSeeds({0x31de})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::vector<testing::NamedProfile> profiles = testing::standardProfiles();
    for (const testing::ClosedProfile& p : testing::closedProfiles()) profiles.push_back({p.name, p.points});
    profiles.push_back({"zigzag column, 400 intervals", testing::zigzagColumn(200)});
    profiles.push_back({"sphere, 48 segments (scanned by runs)", testing::sphereLike(1.0, 48)});
    profiles.push_back({"sphere, 65 segments (the first tree)", testing::sphereLike(1.0, 65)});
    profiles.push_back({"vase, 140,001 points (three levels)", testing::manyPointVase(140001)});
    profiles.push_back({"one segment", {{0.0, 0.0}, {1.0, 1.0}}});
    std::mt19937_64 random(seed);
    for (const int points : {5, 40, 64, 300, 5000}) {
      profiles.push_back({"star-shaped, " + std::to_string(points) + " points", testing::starShaped(random, points)});
    }
    std::uint32_t deepest = 0;
    for (const testing::NamedProfile& profile : profiles) {
      SCOPED_TRACE(profile.name);
      const Built b = build(profile.points);
      WideCheck(b).run();
      deepest = std::max(deepest, b.tree.depth);
      if (::testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GE(deepest, 3u) << "some profile must exercise nodes above nodes";
  }
}

}  // namespace
}  // namespace revolve
