// Searching the strip tree in profile order through skip links (see strip_tree.h).
#pragma once

#include "util/isa.h"

#include "kajiya/strip_tree.h"
#include "kernel/meridian_ray.h"
#include "kernel/shell_tests.h"

namespace revolve::detail {
inline namespace REVOLVE_ISA {

template <bool kCount>
inline bool stripAdmits(const StripNode& node, const MeridianRay& ray, double lo, double hi, Stats& stats) noexcept {
  if constexpr (kCount) ++stats.shellTests;
  double s0 = lo, s1 = hi;
  if (!ray.inPlane) {
    const double sLow = ray.planeS(node.zLow), sHigh = ray.planeS(node.zHigh);
    s0 = std::max(std::min(sLow, sHigh), lo);
    s1 = std::min(std::max(sLow, sHigh), hi);
    if (!(s0 <= s1)) return false;
  } else if (!(node.zLow <= ray.oz && ray.oz <= node.zHigh)) {
    return false;
  }
  return bandPasses(ray, node.across, s0, s1) && bandPasses(ray, node.along, s0, s1);
}

template <bool kCount, class VisitSegment>
inline void searchStripTree(const StripTree& tree, const MeridianRay& ray, double& hi, VisitSegment&& visitSegment,
                            Stats& stats) noexcept {
  const auto count = static_cast<std::uint32_t>(tree.nodes.size());
  for (std::uint32_t i = 0; i < count;) {
    const StripNode& node = tree.nodes[i];
    if constexpr (kCount) ++stats.nodesVisited;
    if (node.segment != StripNode::kInner) {
      // A leaf is its segment: Wang's quadratic is the conic-versus-segment test.
      if (visitSegment(node.segment)) return;
      i = node.skip;
    } else {
      i = stripAdmits<kCount>(node, ray, ray.lo, hi, stats) ? i + 1 : node.skip;
    }
  }
}

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
