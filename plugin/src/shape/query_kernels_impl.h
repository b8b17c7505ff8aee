// The per-ray entry points of one instruction set: include once, from that set's translation unit
// (query_kernels_sse2.cpp, _avx2.cpp, _avx512.cpp), which defines its QueryKernels table from them.
#pragma once

#include "shape/query_kernels.h"
#include "shape/shape_search.h"
#include "shape/surface_hit.h"
#include "util/isa.h"

#include <cmath>
#include <cstdint>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

template <bool kCount, bool kCurve>
std::optional<Hit> nearestHit(const detail::ShapeImpl& shape, const Ray& ray, Stats& stats) noexcept {
  if constexpr (kCount) ++stats.rays;
  MeridianRay meridian;
  if (!setUpMeridianRay(shape.frame, ray, meridian)) return std::nullopt;
  double hi = meridian.hi;
  NearestHit<kCount, kCurve> nearest{shape, meridian, hi, stats};
  searchShape<kCount>(shape, meridian, hi, nearest, stats);
  if (!nearest.found()) return std::nullopt;
  return leafSurfaceHit<kCurve>(shape, meridian, ray, nearest.s, nearest.segment, nearest.u);
}

template <bool kCount, bool kCurve>
bool anyHit(const detail::ShapeImpl& shape, const Ray& ray, Stats& stats) noexcept {
  if constexpr (kCount) ++stats.rays;
  MeridianRay meridian;
  if (!setUpMeridianRay(shape.frame, ray, meridian)) return false;
  double hi = meridian.hi;
  AnyHit<kCount, kCurve> any{shape, meridian, stats};
  searchShape<kCount>(shape, meridian, hi, any, stats);
  return any.found;
}

// surfaceAttributes: segment k's hits over the range the search used ([lo, hi] of the same
// MeridianRay, as NearestHit takes them), so the same s and the same attributes. The nearest first
// (NearestHit's own kFirstOnly call, which gave the unfiltered hit); then, for a hit a filter chose
// or a ray not exactly the one traced, the hit of the segment whose t is nearest.
template <bool kCurve>
std::optional<Hit> hitOnLeaf(const detail::ShapeImpl& shape, const Ray& ray, std::uint32_t k, float t) noexcept {
  const std::size_t leaves = kCurve ? shape.parts.size() : shape.profile.segmentCount();
  MeridianRay meridian;
  if (k >= leaves || !setUpMeridianRay(shape.frame, ray, meridian)) return std::nullopt;
  Stats unused;
  const auto first = leafHits<kCurve, false, true>(shape, meridian, k, meridian.hi, unused);
  if (first.count == 0) return std::nullopt;
  const Hit nearest = leafSurfaceHit<kCurve>(shape, meridian, ray, first.s[0], k, leafParameter(first, 0));
  if (nearest.t == t) return nearest;
  const auto all = leafHits<kCurve, false, false>(shape, meridian, k, meridian.hi, unused);
  std::optional<Hit> best;
  for (int j = 0; j < all.count; ++j) {
    const Hit hit = leafSurfaceHit<kCurve>(shape, meridian, ray, all.s[j], k, leafParameter(all, j));
    if (!best || std::abs(double(hit.t) - t) < std::abs(double(best->t) - t)) best = hit;
  }
  return best ? best : nearest;
}

inline std::optional<Hit> attributesEntry(const detail::ShapeImpl& shape, const Ray& ray, std::uint32_t segment,
                                          float t) noexcept {
  return shape.curved() ? hitOnLeaf<true>(shape, ray, segment, t) : hitOnLeaf<false>(shape, ray, segment, t);
}

inline std::optional<Hit> intersectEntry(const detail::ShapeImpl& shape, const Ray& ray, Stats* stats) noexcept {
  Stats unused;
  if (shape.curved())
    return stats != nullptr ? nearestHit<true, true>(shape, ray, *stats) : nearestHit<false, true>(shape, ray, unused);
  return stats != nullptr ? nearestHit<true, false>(shape, ray, *stats) : nearestHit<false, false>(shape, ray, unused);
}

inline bool occludedEntry(const detail::ShapeImpl& shape, const Ray& ray, Stats* stats) noexcept {
  Stats unused;
  if (shape.curved())
    return stats != nullptr ? anyHit<true, true>(shape, ray, *stats) : anyHit<false, true>(shape, ray, unused);
  return stats != nullptr ? anyHit<true, false>(shape, ray, *stats) : anyHit<false, false>(shape, ray, unused);
}

inline constexpr QueryKernels kQueryKernels{
    REVOLVE_ISA_NAME,
    intersectEntry,
    occludedEntry,
    attributesEntry,
};

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
