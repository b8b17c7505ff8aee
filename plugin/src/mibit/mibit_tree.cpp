#include "mibit/mibit_tree.h"

#include "kernel/chord_band.h"
#include "util/rounding.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace revolve::detail {
namespace {

struct Extent {
  double zLow, zHigh, rMin, rMax;
};

Extent extentOf(std::span<const Point2> run) {
  Extent extent{run[0].z, run[0].z, run[0].r, run[0].r};
  for (const Point2& p : run) {
    extent.zLow = std::min(extent.zLow, p.z);
    extent.zHigh = std::max(extent.zHigh, p.z);
    extent.rMin = std::min(extent.rMin, p.r);
    extent.rMax = std::max(extent.rMax, p.r);
  }
  return extent;
}

// The band parallel to the chord that holds the run. Its normal is rounded to float first and its
// limits computed for that normal, so the stored band holds the run (up to the double rounding of
// the limits, which the shell test's margin covers).
Band chordBand(std::span<const Point2> run, std::span<const Point2> hull) {
  const Chord chord = chordOf(run);
  Band band = bandHolding(run, double(float(chord.uz)), double(float(-chord.ur)));
  // A curved run lies in its control hull: the band holds the inner control points too.
  for (const Point2& p : hull) {
    const double w = band.nr * p.r + band.nz * p.z;
    band.wLow = std::min(band.wLow, w);
    band.wHigh = std::max(band.wHigh, w);
  }
  return band;
}

double meanChord(double area, double perimeter) { return perimeter > 0.0 ? std::numbers::pi * area / perimeter : 0.0; }

// The paper's hybrid rule: keep the (cheaper) cylinder unless the truncated cone is more than four
// times tighter in area or in potential intersection interval. For the latter we use the mean
// chord length of the shell's meridian section, pi * area / perimeter (Cauchy's formula): the
// expected length of a random line's crossing, i.e. the stretch of ray the shell admits.
bool preferCylinder(const Extent& extent, const Band& band) {
  const double height = extent.zHigh - extent.zLow;
  const double cylinderWidth = extent.rMax - extent.rMin;
  const double cylinderArea = cylinderWidth * height;
  const double cylinderChord = meanChord(cylinderArea, 2.0 * (cylinderWidth + height));
  if (!(band.nr > 0.0)) return true;                            // a horizontal band is only a second z slab
  const double coneWidth = (band.wHigh - band.wLow) / band.nr;  // measured along r
  const double coneArea = coneWidth * height;
  const double coneChord = meanChord(coneArea, 2.0 * (coneWidth + height / band.nr));
  return cylinderArea <= 4.0 * coneArea && cylinderChord <= 4.0 * coneChord;
}

NodeShell chooseShell(ShellKind kind, const Extent& extent, const Band& band) {
  switch (kind) {
    case ShellKind::cylinder:
      return NodeShell::cylinder;
    case ShellKind::cone:
      return NodeShell::cone;
    case ShellKind::hybrid:
      return preferCylinder(extent, band) ? NodeShell::cylinder : NodeShell::cone;
  }
  return NodeShell::cylinder;
}

std::uint32_t ceilLog2(std::uint32_t n) { return n <= 1 ? 0 : std::bit_width(n - 1); }

// An explicit node under construction.
struct Draft {
  std::uint32_t segmentBegin, segmentEnd;
  std::int64_t left = -1, right = -1;
  MibitNode::Kind kind;
  std::uint32_t interval = 0;
};

class Builder {
 public:
  Builder(std::span<const Point2> points, std::span<const Point2> innerControls, const BuildOptions& options)
      : points_(points), innerControls_(innerControls), options_(options) {}

  MibitTree build() {
    const auto segments = static_cast<std::uint32_t>(points_.size() - 1);
    std::vector<std::int64_t> level;
    if (options_.monotoneSplit) {
      tree_.intervals = monotoneIntervals(points_);
      for (std::uint32_t i = 0; i < tree_.intervals.size(); ++i) {
        MonotoneInterval& interval = tree_.intervals[i];
        interval.leaves = leavesFor(interval.segmentCount);
        refineImplicitly(interval);
        drafts_.push_back({interval.firstSegment, interval.firstSegment + interval.segmentCount, -1, -1,
                           MibitNode::Kind::interval, i});
        level.push_back(std::int64_t(drafts_.size() - 1));
      }
    } else {
      // The paper's "no monotonic subdivision": a plain binary subdivision of the whole profile.
      const std::uint32_t leaves = leavesFor(segments);
      level.push_back(refineExplicitly(0, segments, 0, leaves, leaves));
    }
    // Monotonic grouping: combine neighbouring intervals pairwise, level by level, up to the root.
    while (level.size() > 1) {
      std::vector<std::int64_t> next;
      for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
        drafts_.push_back({drafts_[level[i]].segmentBegin, drafts_[level[i + 1]].segmentEnd, level[i], level[i + 1],
                           MibitNode::Kind::inner});
        next.push_back(std::int64_t(drafts_.size() - 1));
      }
      if (level.size() % 2 == 1) next.push_back(level.back());
      level = std::move(next);
    }
    linearise(level.front());
    // Cannot happen within Profile::kMaxPoints (depth <= ceil(log2(intervals)) + 1 + ceil(log2(leaves)) <= 34):
    // guards the 64-entry search stacks should that limit ever change.
    if (tree_.depth >= 64) throw std::logic_error("MIBIT depth exceeds the search stacks' 64 entries");
    return std::move(tree_);
  }

 private:
  std::uint32_t leavesFor(std::uint32_t segments) const {
    return options_.subdivisions == 0 ? segments : std::min(options_.subdivisions, segments);
  }

  // Shells of an interval's implicit MR nodes, by heap number, for TC and HY trees.
  void refineImplicitly(MonotoneInterval& interval) {
    interval.shellOffset = tree_.implicitShells.size();
    if (options_.shell == ShellKind::cylinder) return;
    tree_.implicitShells.resize(tree_.implicitShells.size() + (std::size_t{2} << ceilLog2(interval.leaves)));
    fillImplicit(interval, 1, 0, interval.leaves);
  }

  void fillImplicit(const MonotoneInterval& interval, std::uint64_t heap, std::uint64_t leafBegin,
                    std::uint64_t leafEnd) {
    const std::uint32_t first = MibitTree::leafVertex(interval, leafBegin),
                        last = MibitTree::leafVertex(interval, leafEnd);
    const std::span<const Point2> run = points_.subspan(first, last - first + 1);
    const Band band = chordBand(run, hullOf(first, last));
    ImplicitShell& shell = tree_.implicitShells[interval.shellOffset + heap];
    shell = {float(band.nr), float(band.nz), floatBelow(band.wLow), floatAbove(band.wHigh),
             run.size() == 2 ? NodeShell::cylinder : chooseShell(options_.shell, extentOf(run), band)};
    if (leafEnd - leafBegin == 1) return;
    const std::uint64_t middle = (leafBegin + leafEnd) / 2;
    fillImplicit(interval, 2 * heap, leafBegin, middle);
    fillImplicit(interval, 2 * heap + 1, middle, leafEnd);
  }

  // Explicit refinement (no monotone split): a balanced tree over `leaves` equal shares.
  std::int64_t refineExplicitly(std::uint32_t firstSegment, std::uint32_t segmentCount, std::uint64_t leafBegin,
                                std::uint64_t leafEnd, std::uint64_t leaves) {
    if (leafEnd - leafBegin == 1) {
      const auto share = [&](std::uint64_t leaf) {
        return firstSegment + static_cast<std::uint32_t>(leaf * segmentCount / leaves);
      };
      drafts_.push_back({share(leafBegin), share(leafEnd), -1, -1, MibitNode::Kind::segments});
      return std::int64_t(drafts_.size() - 1);
    }
    const std::uint64_t middle = (leafBegin + leafEnd) / 2;
    const std::int64_t left = refineExplicitly(firstSegment, segmentCount, leafBegin, middle, leaves);
    const std::int64_t right = refineExplicitly(firstSegment, segmentCount, middle, leafEnd, leaves);
    drafts_.push_back({drafts_[left].segmentBegin, drafts_[right].segmentEnd, left, right, MibitNode::Kind::inner});
    return std::int64_t(drafts_.size() - 1);
  }

  // Lays the drafts out breadth first with each node's children adjacent, and fits the shells.
  void linearise(std::int64_t root) {
    tree_.nodes.resize(drafts_.size());
    if (options_.shell != ShellKind::cylinder) tree_.cones.resize(drafts_.size());
    struct Pending {
      std::int64_t draft;
      std::uint32_t node, depth;
    };
    std::vector<Pending> queue{{root, 0, 1}};
    std::uint32_t next = 1;
    for (std::size_t i = 0; i < queue.size(); ++i) {
      const Pending pending = queue[i];
      const Draft& draft = drafts_[pending.draft];
      MibitNode& node = tree_.nodes[pending.node];
      fitShell(draft, pending.node, node);
      node.kind = draft.kind;
      switch (draft.kind) {
        case MibitNode::Kind::inner:
          node.first = next;
          node.count = 0;
          queue.push_back({draft.left, next, pending.depth + 1});
          queue.push_back({draft.right, next + 1, pending.depth + 1});
          next += 2;
          tree_.depth = std::max(tree_.depth, pending.depth);
          break;
        case MibitNode::Kind::segments:
          node.first = draft.segmentBegin;
          node.count = draft.segmentEnd - draft.segmentBegin;
          tree_.depth = std::max(tree_.depth, pending.depth);
          break;
        case MibitNode::Kind::interval:
          node.first = draft.interval;
          node.count = draft.segmentEnd - draft.segmentBegin;
          tree_.depth = std::max(tree_.depth, pending.depth + ceilLog2(tree_.intervals[draft.interval].leaves));
          break;
      }
    }
  }

  void fitShell(const Draft& draft, std::uint32_t index, MibitNode& node) {
    const bool isRoot = index == 0;
    const std::span<const Point2> run = points_.subspan(draft.segmentBegin, draft.segmentEnd - draft.segmentBegin + 1);
    const Extent extent = extentOf(run);
    // CY trees store no band and choose no shell by it: their build skips the fit.
    const Band band =
        options_.shell == ShellKind::cylinder ? Band{} : chordBand(run, hullOf(draft.segmentBegin, draft.segmentEnd));
    node.zLow = floatBelow(extent.zLow);
    node.zHigh = floatAbove(extent.zHigh);
    node.rMin = floatBelow(extent.rMin);
    node.rMax = floatAbove(extent.rMax);
    if (!tree_.cones.empty())
      tree_.cones[index] = {float(band.nr), float(band.nz), floatBelow(band.wLow), floatAbove(band.wHigh)};
    if (draft.kind == MibitNode::Kind::segments && run.size() == 2) {
      node.shell = NodeShell::none;  // a single segment is its own truncated cone
    } else if (isRoot && options_.shell == ShellKind::hybrid) {
      node.shell = NodeShell::cylinder;  // the paper starts from a cylinder, the cheapest first test
    } else {
      node.shell = chooseShell(options_.shell, extent, band);
    }
  }

  // The inner control points of segments first to last - 1 (none for a polyline).
  std::span<const Point2> hullOf(std::size_t first, std::size_t last) const {
    if (innerControls_.empty()) return {};
    return innerControls_.subspan(2 * first, 2 * (last - first));
  }

  std::span<const Point2> points_;
  std::span<const Point2> innerControls_;
  const BuildOptions& options_;
  std::vector<Draft> drafts_;
  MibitTree tree_;
};

}  // namespace

std::vector<MonotoneInterval> monotoneIntervals(std::span<const Point2> points) {
  std::vector<MonotoneInterval> intervals;
  std::uint32_t begin = 0;
  int runR = 0, runZ = 0;  // directions of the current run; 0 = not yet fixed
  const auto segments = static_cast<std::uint32_t>(points.size() - 1);
  for (std::uint32_t k = 0; k < segments; ++k) {
    const int dr = signOf(points[k + 1].r - points[k].r);
    const int dz = signOf(points[k + 1].z - points[k].z);
    if ((runR != 0 && dr != 0 && dr != runR) || (runZ != 0 && dz != 0 && dz != runZ)) {
      intervals.push_back({begin, k - begin, 0, 0});
      begin = k;
      runR = runZ = 0;
    }
    if (dr != 0) runR = dr;
    if (dz != 0) runZ = dz;
  }
  intervals.push_back({begin, segments - begin, 0, 0});
  return intervals;
}

MibitTree buildMibitTree(std::span<const Point2> points, const BuildOptions& options,
                         std::span<const Point2> innerControls) {
  return Builder(points, innerControls, options).build();
}

}  // namespace revolve::detail
