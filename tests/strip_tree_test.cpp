// Kajiya's (1983) strip tree, Ballard's (1981) strips over the profile (src/kajiya/strip_tree.h),
// checked node by node apart from the search: a full binary tree in pre-order whose skip links
// jump exactly past each subtree, leaves that are the segments in profile order (each once), every
// strip's z extent and two bands (across and along its chord) holding every vertex of its run, and
// each run split at its vertex farthest from the chord (Ballard's rule).
#include "kajiya/strip_tree.h"
#include "support/hard_profiles.h"
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

using detail::StripNode;
using detail::StripTree;

constexpr double u = detail::kUnitRoundoff;

class StripCheck {
 public:
  StripCheck(const StripTree& tree, std::span<const Point2> points) : tree_(tree), points_(points) {}

  void run() {
    const std::size_t segments = points_.size() - 1;
    ASSERT_EQ(tree_.nodes.size(), 2 * segments - 1) << "a full binary tree over the segments";
    const Run root = node(0);
    EXPECT_EQ(root.end, tree_.nodes.size()) << "the root's subtree is the whole tree";
    EXPECT_EQ(root.first, 0u);
    EXPECT_EQ(root.last, segments);
    // The leaves, in pre-order, are the segments in profile order, each once.
    ASSERT_EQ(leaves_.size(), segments);
    for (std::size_t k = 0; k < segments; ++k) ASSERT_EQ(leaves_[k], k) << "leaf " << k << " in pre-order";
  }

 private:
  struct Run {
    std::size_t first, last;  // vertices first to last
    std::size_t end;          // pre-order index past the subtree
  };

  // The subtree at pre-order index i: its run (from the leaves below it) and where it ends.
  Run node(std::size_t i) {
    if (i >= tree_.nodes.size() || ::testing::Test::HasFatalFailure()) return {0, 0, tree_.nodes.size()};
    const StripNode& n = tree_.nodes[i];
    Run run;
    if (n.segment != StripNode::kInner) {
      leaves_.push_back(n.segment);
      run = {n.segment, n.segment + 1, i + 1};
    } else {
      const Run left = node(i + 1);
      const Run right = node(left.end);  // the right child follows the left subtree
      EXPECT_EQ(left.last, right.first) << "node " << i << ": its children's runs are not neighbours";
      run = {left.first, right.last, right.end};
      checkSplit(i, run, left.last);
    }
    EXPECT_EQ(n.skip, run.end) << "node " << i << ": the skip link must land just past its subtree";
    checkStrip(i, n, run);
    return run;
  }

  // z extent: copies of the vertex heights, exact. Bands: nr r + nz z over the run's vertices,
  // computed by the builder in double (two roundings, 2 u (|nr r| + |nz z|)) and here in long
  // double (far below u): 3 u bounds both.
  void checkStrip(std::size_t i, const StripNode& n, const Run& run) {
    double zLow = INFINITY, zHigh = -INFINITY;
    for (std::size_t k = run.first; k <= run.last; ++k) {
      zLow = std::min(zLow, points_[k].z), zHigh = std::max(zHigh, points_[k].z);
    }
    EXPECT_EQ(n.zLow, zLow) << "node " << i;
    EXPECT_EQ(n.zHigh, zHigh) << "node " << i;
    for (const detail::Band* band : {&n.across, &n.along}) {
      EXPECT_GE(band->nr, 0.0) << "node " << i << ": nr < 0 breaks the band test's convexity";
      // The chord's unit vector rounds in hypot and the divisions, its squares in two more: 8 u.
      EXPECT_LE(std::abs(band->nr * band->nr + band->nz * band->nz - 1.0), 8 * u)
          << "node " << i << ": not a unit normal";
      for (std::size_t k = run.first; k <= run.last; ++k) {
        const long double w = (long double)band->nr * points_[k].r + (long double)band->nz * points_[k].z;
        const long double slack = 3 * u * (std::abs(band->nr * points_[k].r) + std::abs(band->nz * points_[k].z));
        ASSERT_TRUE(band->wLow - slack <= w && w <= band->wHigh + slack)
            << "node " << i << ": vertex " << k << " outside its strip (" << (band == &n.across ? "across" : "along")
            << ")";
      }
    }
    // A strip is a rectangle: its two bands are perpendicular.
    EXPECT_LE(std::abs(n.across.nr * n.along.nr + n.across.nz * n.along.nz), 4 * u) << "node " << i;
  }

  // Ballard's split: the interior vertex farthest from the chord of the run's ends (for a closed
  // loop, ends equal, from its first point to its farthest point). Distances here in long double
  // from the chord's definition; the builder's differ by rounding, a few u of the run's size.
  void checkSplit(std::size_t i, const Run& run, std::size_t split) {
    EXPECT_TRUE(run.first < split && split < run.last) << "node " << i;
    const Point2 a = points_[run.first];
    Point2 b = points_[run.last];
    long double size = 0;
    for (std::size_t k = run.first; k <= run.last; ++k) {
      size = std::max(size, std::hypot((long double)points_[k].r - a.r, (long double)points_[k].z - a.z));
    }
    if (a.r == b.r && a.z == b.z) {
      long double farthest = -1;
      for (std::size_t k = run.first; k <= run.last; ++k) {
        const long double d = std::hypot((long double)points_[k].r - a.r, (long double)points_[k].z - a.z);
        if (d > farthest) farthest = d, b = points_[k];
      }
    }
    const long double cr = (long double)b.r - a.r, cz = (long double)b.z - a.z, length = std::hypot(cr, cz);
    const auto distance = [&](std::size_t k) {
      return std::abs(((long double)points_[k].r - a.r) * cz - ((long double)points_[k].z - a.z) * cr) / length;
    };
    long double farthest = 0;
    for (std::size_t k = run.first + 1; k < run.last; ++k) farthest = std::max(farthest, distance(k));
    EXPECT_GE(distance(split), farthest - 16 * u * size)
        << "node " << i << ": split at " << split << ", not the farthest vertex";
  }

  const StripTree& tree_;
  std::span<const Point2> points_;
  std::vector<std::size_t> leaves_;
};

TEST(StripTree, LeavesCoverEverySegmentOnceAndEveryStripHoldsItsRun) {
  for (const std::uint64_t seed : testing::testSeeds({0x57a1})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::vector<testing::NamedProfile> profiles = testing::standardProfiles();
    for (const testing::ClosedProfile& p : testing::closedProfiles()) {
      profiles.push_back({p.name, p.points});
    }
    profiles.push_back({"zigzag column, 400 intervals", testing::zigzagColumn(200)});
    profiles.push_back({"one segment", {{0.0, 0.0}, {1.0, 1.0}}});
    profiles.push_back({"two segments", {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}});
    std::mt19937_64 random(seed);
    for (const int points : {4, 17, 200, 2000}) {
      profiles.push_back({"star-shaped, " + std::to_string(points) + " points", testing::starShaped(random, points)});
    }
    for (const testing::NamedProfile& profile : profiles) {
      SCOPED_TRACE(profile.name);
      const StripTree tree = detail::buildStripTree(profile.points);
      StripCheck(tree, profile.points).run();
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

}  // namespace
}  // namespace revolve
