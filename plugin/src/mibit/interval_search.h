// Searching one monotone interval's implicit MR tree (the paper's SearchMRI).
//
// A node is a range of the interval's leaves, hence of its vertices. Because r and z are monotone
// along the interval, the node's run lies in the box spanned by its end vertices, and its z slab
// is bounded by their planes. Each node carries the ray's crossing of those two planes (s and
// rho^2 there); a split computes the middle vertex's crossing once and hands it to both children,
// so a level costs one plane evaluation and two cheap range comparisons. The planes are the exact
// vertex heights, the very ones the leaves' seam predicates use.
#pragma once

#include "util/isa.h"

#include "kernel/local_points.h"
#include "kernel/meridian_ray.h"
#include "kernel/shell_tests.h"
#include "mibit/mibit_tree.h"

#include <cstdint>
#include <span>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

namespace interval_search_internal {

struct Plane {
  double s;  // where the ray crosses the vertex's height (unused for rays in a horizontal plane)
  double q;  // rho^2 there
};

struct Node {
  std::uint32_t heap;  // heap number within the interval (root 1), indexes implicit shells
  std::uint32_t leafBegin, leafEnd;
  Plane first, last;  // crossings of the planes of the node's first and last vertices
  double entry;       // where the ray enters the node's stretch
};

}  // namespace interval_search_internal

// Visits the segments of `interval` the search cannot rule out, nearest first; returns true when
// visitSegment asked to stop. The caller has already tested the interval's own shell.
template <bool kCount, class VisitSegment>
inline bool searchInterval(const MibitTree& tree, const MonotoneInterval& interval, LocalPoints points,
                           bool rangeSearch, const MeridianRay& ray, double& hi, VisitSegment&& visitSegment,
                           Stats& stats) noexcept {
  using namespace interval_search_internal;
  const ImplicitShell* shells =
      tree.implicitShells.empty() ? nullptr : tree.implicitShells.data() + interval.shellOffset;
  const double lo = ray.lo, qLo = ray.rho2At(lo);
  double qHi = ray.rho2At(hi), qHiAt = hi;  // rho^2 at hi, refreshed whenever a hit lowers hi

  const auto plane = [&](std::uint32_t vertex) -> Plane {
    if (ray.inPlane) return {0.0, 0.0};
    const double s = ray.planeS(points[vertex].z);
    return {s, ray.rho2At(s)};
  };

  // The test of a child with end vertices a, b: overlap types 1 to 3, then its shell.
  const auto enter = [&](std::uint32_t heap, std::uint32_t a, std::uint32_t b, const Plane& pa, const Plane& pb,
                         double& entry) -> bool {
    double s0 = lo, s1 = hi, q0 = qLo, q1 = qHi;
    bool overlaps, contained = true;
    if (!ray.inPlane) {
      const bool aFirst = pa.s <= pb.s;
      const Plane& near = aFirst ? pa : pb;
      const Plane& far = aFirst ? pb : pa;
      s0 = std::max(near.s, lo);
      s1 = std::min(far.s, hi);
      overlaps = s0 <= s1;
      if (near.s >= lo) q0 = near.q;
      if (far.s <= hi) q1 = far.q;
      contained = near.s <= lo && hi <= far.s;
    } else {
      overlaps = std::min(points[a].z, points[b].z) <= ray.oz && ray.oz <= std::max(points[a].z, points[b].z);
    }
    entry = s0;
    if (rangeSearch && !overlaps) return false;  // overlap type 1
    if (rangeSearch && contained) return true;   // overlap type 3: the children will narrow it
    if constexpr (kCount) ++stats.shellTests;
    if (!overlaps) return false;
    if (shells != nullptr && shells[heap].shell == NodeShell::cone) {
      return bandPasses(ray, shells[heap].cone(), s0, s1, std::sqrt(q0), std::sqrt(q1));
    }
    const double ra = points[a].r, rb = points[b].r;
    return cylinderShellPasses(ray, std::min(ra, rb), std::max(ra, rb), s0, s1, q0, q1);
  };

  // Descends into the nearer child directly and keeps only the farther one on the stack (when both
  // can hold hits), so a ray following one path copies no node through memory.
  Node stack[64];  // depth + 1 entries at most (see searchMibit)
  int top = 0;
  Node node{1,
            0,
            interval.leaves,
            plane(MibitTree::leafVertex(interval, 0)),
            plane(MibitTree::leafVertex(interval, interval.leaves)),
            lo};
  for (;;) {
    bool descended = false;
    if (node.entry <= hi) {
      if constexpr (kCount) ++stats.nodesVisited;
      if (hi != qHiAt) qHi = ray.rho2At(hi), qHiAt = hi;
      const std::uint32_t a = MibitTree::leafVertex(interval, node.leafBegin);
      const std::uint32_t b = MibitTree::leafVertex(interval, node.leafEnd);
      if (node.leafEnd - node.leafBegin == 1) {
        for (std::uint32_t k = a; k < b; ++k) {
          if (visitSegment(k)) return true;
        }
      } else {
        const std::uint32_t middle = (node.leafBegin + node.leafEnd) / 2;
        const std::uint32_t m = MibitTree::leafVertex(interval, middle);
        const Plane pm = plane(m);
        double entryLeft, entryRight;
        const bool enterLeft = enter(2 * node.heap, a, m, node.first, pm, entryLeft);
        const bool enterRight = enter(2 * node.heap + 1, m, b, pm, node.last, entryRight);
        if (enterLeft && enterRight) {
          const bool leftFirst = entryLeft <= entryRight;
          const Node left{2 * node.heap, node.leafBegin, middle, node.first, pm, entryLeft};
          const Node right{2 * node.heap + 1, middle, node.leafEnd, pm, node.last, entryRight};
          stack[top++] = leftFirst ? right : left;
          node = leftFirst ? left : right;
          descended = true;
        } else if (enterLeft) {
          node = {2 * node.heap, node.leafBegin, middle, node.first, pm, entryLeft};
          descended = true;
        } else if (enterRight) {
          node = {2 * node.heap + 1, middle, node.leafEnd, pm, node.last, entryRight};
          descended = true;
        }
      }
    }
    if (descended) continue;
    if (top == 0) break;
    node = stack[--top];
  }
  return false;
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
