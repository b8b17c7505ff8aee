#include "curve/monotone_parts.h"

#include "curve/cubic.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace revolve::detail {
namespace {

struct Split {
  double u;
  bool r, z;  // which derivative vanishes there
};

}  // namespace

std::vector<MonotonePart> monotoneParts(std::span<const Point2> bezier, double extent) {
  std::vector<MonotonePart> parts;
  const double apart = 0x1p-50 * extent;
  const std::size_t pieces = (bezier.size() - 1) / 3;
  parts.reserve(pieces);  // at least a part a piece
  // At most two turns of r and two of z a piece (the derivatives are quadratics): fixed arrays, no
  // allocation a piece.
  std::array<Split, 4> splits, merged;
  struct Kept {
    double u;
    Point2 point;
    bool r, z;
  };
  std::array<Kept, 6> kept;  // the piece's start, up to four splits, its end
  for (std::size_t i = 0; i < pieces; ++i) {
    const Point2* p = &bezier[3 * i];
    const double r[4] = {p[0].r, p[1].r, p[2].r, p[3].r}, z[4] = {p[0].z, p[1].z, p[2].z, p[3].z};
    double roots[2];
    int splitCount = 0;
    for (int k = 0, count = derivativeSignChanges(r, roots); k < count; ++k)
      splits[splitCount++] = {roots[k], true, false};
    for (int k = 0, count = derivativeSignChanges(z, roots); k < count; ++k)
      splits[splitCount++] = {roots[k], false, true};
    std::sort(splits.begin(), splits.begin() + splitCount, [](const Split& a, const Split& b) { return a.u < b.u; });
    // Where r and z turn at the same parameter (a cusp), one split pins both.
    int mergedCount = 0;
    for (int k = 0; k < splitCount; ++k) {
      const Split& s = splits[k];
      if (mergedCount > 0 && merged[mergedCount - 1].u == s.u) {
        merged[mergedCount - 1].r |= s.r, merged[mergedCount - 1].z |= s.z;
      } else {
        merged[mergedCount++] = s;
      }
    }
    // Keep the splits whose points stand apart from the previous kept point and from the end.
    std::size_t keptCount = 0;
    kept[keptCount++] = {0.0, p[0], false, false};
    const auto farFrom = [&](Point2 a, Point2 b) { return std::max(std::abs(a.r - b.r), std::abs(a.z - b.z)) > apart; };
    for (int k = 0; k < mergedCount; ++k) {
      const Split& s = merged[k];
      const Point2 point{cubicAt(r, s.u), cubicAt(z, s.u)};
      if (farFrom(point, kept[keptCount - 1].point) && farFrom(point, p[3])) kept[keptCount++] = {s.u, point, s.r, s.z};
    }
    kept[keptCount++] = {1.0, p[3], false, false};
    for (std::size_t k = 0; k + 1 < keptCount; ++k) {
      const Kept& a = kept[k];
      const Kept& b = kept[k + 1];
      double rs[4], zs[4];
      cubicRestricted(r, a.u, b.u, rs);
      cubicRestricted(z, a.u, b.u, zs);
      MonotonePart part{{{rs[0], zs[0]}, {rs[1], zs[1]}, {rs[2], zs[2]}, {rs[3], zs[3]}}, std::uint32_t(i), a.u, b.u};
      part.c[0] = a.point;
      part.c[3] = b.point;
      // The derivative that vanishes at a split vanishes in the part's end control pair too.
      if (a.r) part.c[1].r = a.point.r;
      if (a.z) part.c[1].z = a.point.z;
      if (b.r) part.c[2].r = b.point.r;
      if (b.z) part.c[2].z = b.point.z;
      parts.push_back(part);
    }
  }
  return parts;
}

}  // namespace revolve::detail
