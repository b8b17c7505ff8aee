// The MIBIT tree (src/mibit/mibit_tree.h; Baciu, Jia & Lam 2001) checked node by node, apart from
// any search: on every test profile, random ones and spline profiles' monotone parts, for each shell
// kind (CY, TC, HY), with and without the monotone split, refined to one segment a leaf and to three
// leaves an interval. What the searches rely on:
// - every segment is reached from the root exactly once (explicit nodes, then each monotone
//   interval's implicit MR tree), and every explicit node and interval exactly once;
// - every node's shell holds every segment below it: its z slab and radial extent (floats rounded
//   outwards: exact comparisons) and its truncated-cone band, and no node's slab is looser than a
//   float step (a shell that held everything would prune nothing);
// - the monotone intervals are monotone in r and in z, maximal, and tile the profile, so that an
//   implicit node's run lies in the box of its two end vertices (its CY shell and slab);
// - the depth is the longest root-to-leaf path, within the bound the pairwise grouping promises:
//   ceil(log2 intervals) + 1 + ceil(log2 leaves a interval), far below the searches' 64-entry stacks.
#include "mibit/mibit_tree.h"
#include <revolve/baselines.h>
#include "curve/monotone_parts.h"
#include "support/hard_profiles.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

using detail::MibitNode;
using detail::MibitTree;
using detail::MonotoneInterval;
using detail::NodeShell;

constexpr double u = detail::kUnitRoundoff;

std::uint32_t ceilLog2(std::uint64_t n) {
  std::uint32_t k = 0;
  while ((std::uint64_t{1} << k) < n) ++k;
  return k;
}

int sign(double x) { return (x > 0) - (x < 0); }

// Whether r and z are each monotone (non-decreasing or non-increasing) along segments
// [first, first + count) of `points`.
bool monotone(std::span<const Point2> points, std::size_t first, std::size_t count) {
  int dr = 0, dz = 0;
  for (std::size_t k = first; k < first + count; ++k) {
    const int sr = sign(points[k + 1].r - points[k].r), sz = sign(points[k + 1].z - points[k].z);
    if ((sr != 0 && dr != 0 && sr != dr) || (sz != 0 && dz != 0 && sz != dz)) return false;
    if (sr != 0) dr = sr;
    if (sz != 0) dz = sz;
  }
  return true;
}

// A profile to build trees over: its points, and for a spline's monotone parts their inner control
// points, two a part.
struct TreeInput {
  std::string name;
  std::vector<Point2> points;
  std::vector<Point2> innerControls;
};

std::vector<TreeInput> treeInputs(std::uint64_t seed) {
  std::vector<TreeInput> inputs;
  for (const testing::NamedProfile& p : testing::standardProfiles()) inputs.push_back({p.name, p.points, {}});
  for (const testing::ClosedProfile& p : testing::closedProfiles()) inputs.push_back({p.name, p.points, {}});
  inputs.push_back({"zigzag column, 400 intervals", testing::zigzagColumn(200), {}});
  inputs.push_back({"two segments", {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}, {}});
  inputs.push_back({"one segment", {{0.0, 0.0}, {1.0, 1.0}}, {}});
  std::mt19937_64 random(seed);
  for (const int points : {3, 7, 33, 100, 1000}) {
    inputs.push_back({"star-shaped, " + std::to_string(points) + " points", testing::starShaped(random, points), {}});
  }
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Spline spline(named.kind, named.points);
    double extent = 0.0;
    for (const Point2& p : spline.bezier()) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
    TreeInput input{named.name + " (monotone parts)", {}, {}};
    for (const detail::MonotonePart& part : detail::monotoneParts(spline.bezier(), extent)) {
      if (input.points.empty()) input.points.push_back(part.c[0]);
      input.points.push_back(part.c[3]);
      input.innerControls.push_back(part.c[1]);
      input.innerControls.push_back(part.c[2]);
    }
    inputs.push_back(std::move(input));
  }
  return inputs;
}

// Checks one tree; records failures with `what` (the profile and options).
class TreeCheck {
 public:
  TreeCheck(const MibitTree& tree, const TreeInput& input, const BuildOptions& options)
      : tree_(tree),
        points_(input.points),
        inner_(input.innerControls),
        options_(options),
        segmentSeen_(points_.size() - 1, 0),
        nodeSeen_(tree.nodes.size(), 0),
        intervalSeen_(tree.intervals.size(), 0) {}

  void run() {
    ASSERT_FALSE(tree_.nodes.empty());
    explicitNode(0, 1);
    for (std::size_t k = 0; k < segmentSeen_.size(); ++k) {
      ASSERT_EQ(segmentSeen_[k], 1) << "segment " << k << " reached";
    }
    for (std::size_t i = 0; i < nodeSeen_.size(); ++i) ASSERT_EQ(nodeSeen_[i], 1) << "node " << i << " reached";
    for (std::size_t i = 0; i < intervalSeen_.size(); ++i) {
      ASSERT_EQ(intervalSeen_[i], 1) << "interval " << i << " reached";
    }
    EXPECT_EQ(tree_.depth, longest_) << "the stored depth is the longest root-to-leaf path";
    EXPECT_LE(tree_.depth, depthBound());
    EXPECT_LT(tree_.depth, 64u) << "the searches' stacks hold 64 entries";
    if (options_.monotoneSplit) checkIntervals();
  }

 private:
  // The bound the grouping promises: intervals paired level by level (ceil(log2 n) levels above
  // them, the root at depth 1), each refined into a balanced tree of ceil(log2 leaves) levels below.
  std::uint32_t depthBound() const {
    if (!options_.monotoneSplit) {
      const std::uint64_t segments = points_.size() - 1;
      return 1 +
             ceilLog2(options_.subdivisions == 0 ? segments : std::min<std::uint64_t>(options_.subdivisions, segments));
    }
    std::uint32_t leaves = 1;
    for (const MonotoneInterval& interval : tree_.intervals) leaves = std::max(leaves, interval.leaves);
    return ceilLog2(tree_.intervals.size()) + 1 + ceilLog2(leaves);
  }

  // Segments [first, last) of the node; checks its shell holds them.
  std::pair<std::uint32_t, std::uint32_t> explicitNode(std::uint32_t index, std::uint32_t depth) {
    EXPECT_LT(index, tree_.nodes.size());
    if (index >= tree_.nodes.size()) return {0, 0};
    ++nodeSeen_[index];
    const MibitNode& node = tree_.nodes[index];
    std::pair<std::uint32_t, std::uint32_t> run;
    switch (node.kind) {
      case MibitNode::Kind::inner: {
        EXPECT_GE(node.first, 1u) << "a child before its parent";
        const auto left = explicitNode(node.first, depth + 1), right = explicitNode(node.first + 1, depth + 1);
        EXPECT_EQ(left.second, right.first) << "node " << index << ": its children's runs are not neighbours";
        run = {left.first, right.second};
        break;
      }
      case MibitNode::Kind::segments:
        EXPECT_FALSE(options_.monotoneSplit);
        EXPECT_GE(node.count, 1u);
        for (std::uint32_t k = node.first; k < node.first + node.count && k < segmentSeen_.size(); ++k) {
          ++segmentSeen_[k];
        }
        run = {node.first, node.first + node.count};
        longest_ = std::max(longest_, depth);
        break;
      case MibitNode::Kind::interval: {
        EXPECT_TRUE(options_.monotoneSplit);
        EXPECT_LT(node.first, tree_.intervals.size());
        if (node.first >= tree_.intervals.size()) return {0, 0};
        ++intervalSeen_[node.first];
        const MonotoneInterval& interval = tree_.intervals[node.first];
        EXPECT_EQ(node.count, interval.segmentCount);
        EXPECT_GE(interval.leaves, 1u);
        EXPECT_LE(interval.leaves, interval.segmentCount);
        if (options_.subdivisions != 0) {
          EXPECT_LE(interval.leaves, options_.subdivisions);
        }
        implicitNode(interval, 1, 0, interval.leaves, depth);
        run = {interval.firstSegment, interval.firstSegment + interval.segmentCount};
        break;
      }
    }
    checkExplicitShell(index, node, run.first, run.second);
    return run;
  }

  // An interval's implicit MR node: leaves [leafBegin, leafEnd), heap number `heap`.
  void implicitNode(const MonotoneInterval& interval, std::uint64_t heap, std::uint64_t leafBegin,
                    std::uint64_t leafEnd, std::uint32_t depth) {
    const std::uint32_t a = MibitTree::leafVertex(interval, leafBegin), b = MibitTree::leafVertex(interval, leafEnd);
    ASSERT_LT(a, b) << "an empty MR node";
    ASSERT_TRUE(interval.firstSegment <= a && b <= interval.firstSegment + interval.segmentCount);
    // The run lies in the box of its end vertices: the implicit node's CY shell and slab.
    const Point2 pa = points_[a], pb = points_[b];
    for (std::uint32_t k = a; k <= b; ++k) {
      ASSERT_TRUE(std::min(pa.r, pb.r) <= points_[k].r && points_[k].r <= std::max(pa.r, pb.r) &&
                  std::min(pa.z, pb.z) <= points_[k].z && points_[k].z <= std::max(pa.z, pb.z))
          << "vertex " << k << " outside the box of its MR node's end vertices " << a << ", " << b;
    }
    if (options_.shell == ShellKind::cylinder) {
      EXPECT_TRUE(tree_.implicitShells.empty());
    } else {
      const std::uint64_t slot = interval.shellOffset + heap;
      ASSERT_LT(slot, tree_.implicitShells.size());
      const detail::ImplicitShell& shell = tree_.implicitShells[slot];
      if (b - a == 1) {
        EXPECT_EQ(shell.shell, NodeShell::cylinder) << "a one-segment run is its own cone";
      } else if (options_.shell == ShellKind::cone) {
        EXPECT_EQ(shell.shell, NodeShell::cone);
      }
      checkBand(shell.cone(), a, b, "MR node " + std::to_string(heap));
    }
    if (leafEnd - leafBegin == 1) {
      for (std::uint32_t k = a; k < b; ++k) ++segmentSeen_[k];
      longest_ = std::max(longest_, depth);
      return;
    }
    const std::uint64_t middle = (leafBegin + leafEnd) / 2;
    implicitNode(interval, 2 * heap, leafBegin, middle, depth + 1);
    implicitNode(interval, 2 * heap + 1, middle, leafEnd, depth + 1);
  }

  void checkExplicitShell(std::uint32_t index, const MibitNode& node, std::uint32_t first, std::uint32_t last) {
    const std::string what =
        "node " + std::to_string(index) + " (segments " + std::to_string(first) + " to " + std::to_string(last) + ")";
    double zLow = INFINITY, zHigh = -INFINITY, rMin = INFINITY, rMax = -INFINITY;
    for (std::uint32_t k = first; k <= last; ++k) {
      zLow = std::min(zLow, points_[k].z), zHigh = std::max(zHigh, points_[k].z);
      rMin = std::min(rMin, points_[k].r), rMax = std::max(rMax, points_[k].r);
    }
    // Holds the run's vertices (a segment, and a monotone part, lies in the box of its ends), and is
    // no looser than the next float outwards.
    const auto tight = [](float bound, double value) {
      return std::abs(double(bound) - value) <= std::ldexp(std::abs(value), -23);
    };
    EXPECT_TRUE(node.zLow <= zLow && zHigh <= node.zHigh && node.rMin <= rMin && rMax <= node.rMax) << what;
    EXPECT_TRUE(tight(node.zLow, zLow) && tight(node.zHigh, zHigh) && tight(node.rMin, rMin) && tight(node.rMax, rMax))
        << what << ": [" << node.zLow << ", " << node.zHigh << "] x [" << node.rMin << ", " << node.rMax << "] around ["
        << zLow << ", " << zHigh << "] x [" << rMin << ", " << rMax << "]";
    if (options_.shell == ShellKind::cylinder) {
      EXPECT_TRUE(tree_.cones.empty()) << "a CY tree stores no cones";
    } else {
      ASSERT_EQ(tree_.cones.size(), tree_.nodes.size());
      checkBand(tree_.cones[index].cone(), first, last, what);
    }
    // The shell kinds the options ask for: a one-segment leaf needs none (it is its own cone), a
    // hybrid tree's root is a cylinder (the paper's cheapest first test).
    if (node.kind == MibitNode::Kind::segments && node.count == 1) {
      EXPECT_EQ(node.shell, NodeShell::none) << what;
    } else if (index == 0 && options_.shell == ShellKind::hybrid) {
      EXPECT_EQ(node.shell, NodeShell::cylinder) << what;
    } else if (options_.shell == ShellKind::cylinder) {
      EXPECT_EQ(node.shell, NodeShell::cylinder) << what;
    } else if (options_.shell == ShellKind::cone) {
      EXPECT_EQ(node.shell, NodeShell::cone) << what;
    } else {
      EXPECT_NE(node.shell, NodeShell::none) << what;
    }
  }

  // The TC band wLow <= nr r + nz z <= wHigh holds vertices first to last and, for a spline's parts,
  // their inner control points (a part lies in its control hull). The builder evaluates w in double
  // for the float normal (two roundings, 2 u (|nr r| + |nz z|)) before rounding the limits
  // outwards; this long-double evaluation rounds far below u: 3 u bounds both.
  void checkBand(const detail::Band& band, std::uint32_t first, std::uint32_t last, const std::string& what) {
    EXPECT_GE(band.nr, 0.0) << what << ": nr < 0 breaks the band test's convexity";
    EXPECT_LE(std::abs(band.nr * band.nr + band.nz * band.nz - 1.0), 0x1p-22) << what << ": the normal is not unit";
    const auto holds = [&](Point2 p) {
      const long double w = (long double)band.nr * p.r + (long double)band.nz * p.z;
      const long double slack = 3 * u * (std::abs(band.nr * p.r) + std::abs(band.nz * p.z));
      return band.wLow - slack <= w && w <= band.wHigh + slack;
    };
    for (std::uint32_t k = first; k <= last; ++k) {
      ASSERT_TRUE(holds(points_[k])) << what << ": vertex " << k << " outside its band";
    }
    if (!inner_.empty()) {
      for (std::uint32_t k = 2 * first; k < 2 * last; ++k) {
        ASSERT_TRUE(holds(inner_[k])) << what << ": control " << k << " outside";
      }
    }
  }

  // Monotone, maximal, tiling the profile.
  void checkIntervals() {
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < tree_.intervals.size(); ++i) {
      const MonotoneInterval& interval = tree_.intervals[i];
      ASSERT_EQ(interval.firstSegment, next) << "interval " << i;
      ASSERT_GE(interval.segmentCount, 1u) << "interval " << i;
      EXPECT_TRUE(monotone(points_, interval.firstSegment, interval.segmentCount))
          << "interval " << i << " is not monotone";
      next = interval.firstSegment + interval.segmentCount;
      if (next < points_.size() - 1) {
        EXPECT_FALSE(monotone(points_, interval.firstSegment, interval.segmentCount + 1))
            << "interval " << i << " could take the next segment";
      }
    }
    EXPECT_EQ(next, points_.size() - 1);
  }

  const MibitTree& tree_;
  std::span<const Point2> points_, inner_;
  const BuildOptions& options_;
  std::vector<int> segmentSeen_, nodeSeen_, intervalSeen_;
  std::uint32_t longest_ = 0;
};

TEST(MibitTree, EverySegmentReachedOnceEveryShellHoldsItsSegmentsDepthWithinItsBound) {
  for (const std::uint64_t seed : testing::testSeeds({0x3b17})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::size_t trees = 0;
    for (const TreeInput& input : treeInputs(seed)) {
      for (const ShellKind shell : {ShellKind::cylinder, ShellKind::cone, ShellKind::hybrid}) {
        for (const bool monotoneSplit : {true, false}) {
          for (const std::uint32_t subdivisions : {0u, 3u}) {
            const BuildOptions options{.shell = shell, .subdivisions = subdivisions, .monotoneSplit = monotoneSplit};
            SCOPED_TRACE(input.name + ", shell " + std::to_string(int(shell)) + ", split " +
                         std::to_string(monotoneSplit) + ", subdivisions " + std::to_string(subdivisions));
            const MibitTree tree = detail::buildMibitTree(input.points, options, input.innerControls);
            TreeCheck(tree, input, options).run();
            ++trees;
            if (::testing::Test::HasFatalFailure()) return;
          }
        }
      }
    }
    EXPECT_GT(trees, 300u);
  }
}

TEST(MibitTree, MonotoneIntervalsOfHandMadeProfiles) {
  // Up, out, down, in: a new interval wherever r or z turns back.
  const std::vector<Point2> square{{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0.5, 0}};
  const std::vector<MonotoneInterval> intervals = detail::monotoneIntervals(square);
  ASSERT_EQ(intervals.size(), 2u);
  EXPECT_EQ(intervals[0].firstSegment, 0u);
  EXPECT_EQ(intervals[0].segmentCount, 2u);  // up, then out: r and z both non-decreasing
  EXPECT_EQ(intervals[1].firstSegment, 2u);
  EXPECT_EQ(intervals[1].segmentCount, 2u);  // down, then in: both non-increasing
  // A zero change fits either way: horizontal and vertical runs join whatever follows.
  const std::vector<Point2> stairs{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1.5, 3}};
  ASSERT_EQ(detail::monotoneIntervals(stairs).size(), 2u);
  EXPECT_EQ(detail::monotoneIntervals(stairs)[1].firstSegment, 4u);
  // One segment: one interval.
  EXPECT_EQ(detail::monotoneIntervals(std::vector<Point2>{{0, 0}, {1, 1}}).size(), 1u);
}

}  // namespace
}  // namespace revolve
