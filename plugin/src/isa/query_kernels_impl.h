// The per-ray entry points of one instruction set: include once, from that set's translation unit
// (query_kernels_sse2.cpp, query_kernels_avx2.cpp), which defines its QueryKernels table from them.
#pragma once

#include "isa/query_kernels.h"
#include "shape/shape_search.h"
#include "shape/surface_hit.h"
#include "util/isa.h"

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
};

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
