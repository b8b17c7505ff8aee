// Inside or outside the solid a closed shape bounds (revolve/core.h, insideSolid), decided in the
// meridian plane from the profile itself: its polyline, or the Bezier pieces of a spline traced
// exactly. The crossing number of the half-line {(r, z) : r > rho} with the curve closed along the
// axis (whose own points, r = 0, never cross it).
#include "curve/cubic.h"
#include "shape/shape_impl.h"

#include <cmath>
#include <span>

namespace revolve {
namespace {

using detail::cubicAt;

// Whether the part of the cubic piece (r[], z[]) over [u0, u1], monotone in z, crosses the
// half-line at `height` beyond `rho`: its ends lie on opposite sides of the line by the half-open
// rule (z > height or not, so that neighbours sharing an end agree), and its crossing, found by
// bisection in double, lies beyond rho.
bool partCrosses(const double r[4], const double z[4], double u0, double u1, double rho, double height) {
  // cubicAt is exact at u = 0 and 1: the ends are the piece's own, as its neighbours see them.
  const bool above0 = cubicAt(z, u0) > height, above1 = cubicAt(z, u1) > height;
  if (above0 == above1) return false;
  double low = u0, high = u1;
  // Until no double lies between the ends: within 1,100 halvings for any interval of [0, 1] (a
  // double there has at most 1,075 bits below 1).
  for (int i = 0; i < 1100; ++i) {
    const double middle = 0.5 * (low + high);
    if (middle <= low || middle >= high) break;
    ((cubicAt(z, middle) > height) == above0 ? low : high) = middle;
  }
  return cubicAt(r, 0.5 * (low + high)) > rho;
}

}  // namespace

bool insideSolid(const Shape& shape, Point2 query) noexcept {
  const double rho = query.r, height = query.z;
  bool inside = false;
  if (const Spline* spline = shape.spline()) {
    const std::span<const Point2> b = spline->bezier();
    for (std::size_t piece = 0; piece + 3 < b.size(); piece += 3) {
      const double r[4] = {b[piece].r, b[piece + 1].r, b[piece + 2].r, b[piece + 3].r};
      const double z[4] = {b[piece].z, b[piece + 1].z, b[piece + 2].z, b[piece + 3].z};
      // Split where z turns: each part is monotone in z, crossed once or not at all.
      double turns[2];
      const int count = detail::derivativeSignChanges(z, turns);
      double start = 0;
      for (int i = 0; i <= count; ++i) {
        const double end = i < count ? turns[i] : 1;
        inside ^= partCrosses(r, z, start, end, rho, height);
        start = end;
      }
    }
    return inside;
  }
  const std::span<const Point2> p = shape.profile().points();
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const Point2 a = p[i], b = p[i + 1];
    if ((a.z > height) == (b.z > height)) continue;
    const double r = a.r + (b.r - a.r) * ((height - a.z) / (b.z - a.z));
    inside ^= r > rho;
  }
  return inside;
}

}  // namespace revolve
