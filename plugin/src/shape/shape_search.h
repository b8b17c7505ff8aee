// One search over a shape, whatever its method, and the per-segment visitors the queries use.
//
// Determinism: every segment's hits are computed over the same range [lo, hi at the start], never
// over the shrinking best-so-far, and ties go to the lower segment index. The nearest hit is then
// the same bit for bit whichever method found it, and methods can be checked hit for hit.
#pragma once

#include "util/isa.h"

#include "kajiya/strip_search.h"
#include "kernel/curve_hits.h"
#include "kernel/segment_hits.h"
#include "mibit/mibit_search.h"
#include "mibit/wide_search.h"
#include "shape/shape_impl.h"

#include <cstdint>
#include <limits>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

template <bool kCount, class VisitSegment>
inline void searchShape(const detail::ShapeImpl& shape, const MeridianRay& ray, double& hi, VisitSegment&& visit,
                        Stats& stats) noexcept {
  switch (shape.options.method) {
    case Method::mibit:
      if (!shape.wide.empty() && !ray.inPlane && wideSearchServes(ray)) {
        searchWide<kCount>(shape.wide, ray, shape.frame.sphereRadius, hi, visit, stats);
      } else {
        searchMibit<kCount>(shape.mibit, localPointsOf(shape), shape.options.rangeSearch, ray, hi, visit, stats);
      }
      break;
    case Method::kajiya:
      searchStripTree<kCount>(shape.strips, ray, hi, visit, stats);
      break;
    case Method::linear: {
      const auto segments = static_cast<std::uint32_t>(shape.profile.segmentCount());
      for (std::uint32_t k = 0; k < segments; ++k) {
        if (visit(k)) return;
      }
      break;
    }
  }
}

template <bool kCount, bool kFirstOnly = false>
inline SegmentHits hitsOfSegment(const detail::ShapeImpl& shape, const MeridianRay& ray, std::uint32_t k, double hi,
                                 Stats& stats) noexcept {
  const LocalPoints local = localPointsOf(shape);
  const SegmentHits hits = segmentHits<kFirstOnly>(ray, local[k], local[k + 1], ray.lo, hi);
  if constexpr (kCount) stats.quadratics += hits.solved;
  return hits;
}

// A spline shape's leaf: its monotone part k (the segment between knots k and k + 1).
template <bool kCount, bool kFirstOnly = false>
inline CurveHits hitsOfPart(const detail::ShapeImpl& shape, const MeridianRay& ray, std::uint32_t k, double hi,
                            Stats& stats) noexcept {
  const CurveHits hits = curveHits<kFirstOnly>(ray, shape.parts[k], ray.lo, hi, shape.frame.sphereRadius);
  if constexpr (kCount) stats.quadratics += hits.solved;
  return hits;
}

// The leaf of either kind of shape: a polyline's segment, or a spline's part (kCurve).
template <bool kCurve, bool kCount, bool kFirstOnly = false>
inline auto leafHits(const detail::ShapeImpl& shape, const MeridianRay& ray, std::uint32_t k, double hi,
                     Stats& stats) noexcept {
  if constexpr (kCurve) {
    return hitsOfPart<kCount, kFirstOnly>(shape, ray, k, hi, stats);
  } else {
    return hitsOfSegment<kCount, kFirstOnly>(shape, ray, k, hi, stats);
  }
}

// The curve parameter of hit j of a leaf (spline parts only; 0 for segments, which need none).
template <class Hits>
inline double leafParameter(const Hits& hits, int j) noexcept {
  if constexpr (requires { hits.u[j]; }) {
    return hits.u[j];
  } else {
    return 0.0;
  }
}

// The nearest hit: (s, segment), ties to the lower segment; for spline shapes also the part's
// parameter there.
template <bool kCount, bool kCurve = false>
struct NearestHit {
  const detail::ShapeImpl& shape;
  const MeridianRay& ray;
  double& hi;  // the search's pruning bound, lowered to the best hit
  Stats& stats;
  const double leafHi = hi;
  double s = std::numeric_limits<double>::infinity();
  double u = 0.0;
  std::uint32_t segment = kNoSegment;
  static constexpr std::uint32_t kNoSegment = 0xffffffffu;

  bool operator()(std::uint32_t k) noexcept {
    const auto hits = leafHits<kCurve, kCount, true>(shape, ray, k, leafHi, stats);
    if (hits.count > 0 && (hits.s[0] < s || (hits.s[0] == s && k < segment))) {
      s = hits.s[0];
      if constexpr (kCurve) u = hits.u[0];
      segment = k;
      hi = s;
    }
    return false;
  }
  bool found() const noexcept { return segment != kNoSegment; }
};

// Whether any hit exists: the search ends at the first.
template <bool kCount, bool kCurve = false>
struct AnyHit {
  const detail::ShapeImpl& shape;
  const MeridianRay& ray;
  Stats& stats;
  bool found = false;

  bool operator()(std::uint32_t k) noexcept {
    found = leafHits<kCurve, kCount, true>(shape, ray, k, ray.hi, stats).count > 0;
    return found;
  }
};

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
