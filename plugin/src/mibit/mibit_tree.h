// The Monotonic Interval Binary Index Tree (MIBIT) of Baciu, Jia & Lam (2001).
//
// The profile is split into monotone intervals (r and z each non-decreasing or non-increasing),
// grouped pairwise up to the root (MG, "monotonic grouping", nodes), and each interval is refined
// into uniform subintervals (MR, "monotonic refinement", nodes: a balanced binary tree over equal
// shares of its segments). Every node bounds its run of the profile with a z slab and a shell:
// cylinder (CY), truncated cone (TC) or, in the hybrid scheme (HY), whichever the paper's
// criteria pick.
//
// As the paper observes, a run inside a monotone interval is bounded by its two end vertices
// alone. So MR nodes are implicit: a node is a range of the interval's vertices, its CY shell
// and slab come from the end vertices, and siblings share the plane of the vertex that splits
// them (mibit/interval_search.h). Only MG nodes, and the MR nodes of the paper's "no monotone
// split" variant (where runs are not monotone), are stored.
#pragma once

#include <revolve/baselines.h>
#include <revolve/core.h>

#include "kernel/shell_tests.h"

#include <cstdint>
#include <span>
#include <vector>

namespace revolve::detail {

enum class NodeShell : std::uint8_t { none, cylinder, cone };

// An explicit node, 28 bytes. Bounds are floats rounded outwards: a shell need only contain its
// run, and since planeS is monotone in z an outward-rounded slab still gives a superset of the
// ray's stretch (the leaves alone decide hits, with the exact vertex heights).
struct MibitNode {
  enum class Kind : std::uint8_t {
    inner,     // children at first, first + 1
    segments,  // a leaf: `count` segments from `first` (the no-monotone-split variant)
    interval,  // a leaf: monotone interval number `first`, refined implicitly
  };
  float zLow, zHigh;  // z slab
  float rMin, rMax;   // radial extent: the CY shell, and the meridian box of closest-point queries
  std::uint32_t first;
  std::uint32_t count;
  NodeShell shell;
  Kind kind;
};

// A node's TC shell: coneWLow <= nr rho + nz z <= coneWHigh, nr >= 0. Kept apart from the nodes,
// and only for TC and HY trees: the default cylinder-shell trees never read one.
struct NodeCone {
  float coneNr, coneNz, coneWLow, coneWHigh;
  Band cone() const noexcept { return {coneNr, coneNz, coneWLow, coneWHigh}; }
};

// The shell of an implicit MR node, for TC and HY trees (CY shells need nothing stored).
struct ImplicitShell {
  float coneNr, coneNz, coneWLow, coneWHigh;
  NodeShell shell;
  Band cone() const noexcept { return {coneNr, coneNz, coneWLow, coneWHigh}; }
};

struct MonotoneInterval {
  std::uint32_t firstSegment, segmentCount;
  std::uint32_t leaves;       // MR leaves: uniform shares of the segments
  std::uint64_t shellOffset;  // into MibitTree::implicitShells, indexed by heap number (root 1): up to
                              // 4 entries a segment, past 32 bits for the largest profiles
};

// Maximal runs of segments along which r and z are each monotone (a zero change fits either way).
// Only firstSegment and segmentCount are set.
std::vector<MonotoneInterval> monotoneIntervals(std::span<const Point2> points);

struct MibitTree {
  std::vector<MibitNode> nodes;  // explicit nodes; nodes[0] is the root
  std::vector<NodeCone> cones;   // each explicit node's TC shell; empty for CY trees
  std::vector<MonotoneInterval> intervals;
  std::vector<ImplicitShell> implicitShells;  // empty for CY trees
  std::uint32_t depth = 0;                    // longest root-to-leaf path, explicit and implicit nodes together

  // Vertex index where leaf `leaf` of an interval begins (leaf == leaves: one past its end).
  static std::uint32_t leafVertex(const MonotoneInterval& interval, std::uint64_t leaf) noexcept {
    // One segment a leaf (the default) needs no division, which would cost tens of cycles a level.
    if (interval.leaves == interval.segmentCount) return interval.firstSegment + static_cast<std::uint32_t>(leaf);
    return interval.firstSegment + static_cast<std::uint32_t>(leaf * interval.segmentCount / interval.leaves);
  }
};

// `points` in the shape's local frame. Options used: shell, subdivisions, monotoneSplit. For a
// spline shape, `points` are its monotone parts' ends and `innerControls` the parts' inner control
// points, two a part, which cone shells then hold too (cylinder shells need only the ends: a
// monotone part lies in the box of its ends).
MibitTree buildMibitTree(std::span<const Point2> points, const BuildOptions& options,
                         std::span<const Point2> innerControls = {});

}  // namespace revolve::detail
