#include "curve/curve_self_intersection.h"

#include "curve/cubic.h"

#include "profile/exact_predicates.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

namespace revolve::detail {
namespace {

Point2 operator-(Point2 a, Point2 b) { return {a.r - b.r, a.z - b.z}; }
double dot(Point2 a, Point2 b) { return a.r * b.r + a.z * b.z; }
double cross(Point2 a, Point2 b) { return a.r * b.z - a.z * b.r; }
double norm(Point2 a) { return std::hypot(a.r, a.z); }
// a / |a| for a != 0, computed after scaling a by a power of two so that nothing underflows.
Point2 direction(Point2 a) {
  int exponent;
  std::frexp(std::max(std::abs(a.r), std::abs(a.z)), &exponent);
  const Point2 scaled{std::ldexp(a.r, -exponent), std::ldexp(a.z, -exponent)};
  const double length = norm(scaled);
  return {scaled.r / length, scaled.z / length};
}
bool same(Point2 a, Point2 b) { return a.r == b.r && a.z == b.z; }

// A piece of a monotone part: its control points, and whether its ends are the part's own.
struct Sub {
  Point2 c[4];
  bool startIsPartStart, endIsPartEnd;
};

struct Box {
  double rLow, rHigh, zLow, zHigh;
};

Box boxOf(const Sub& s) {  // monotone: the box of the ends
  return {std::min(s.c[0].r, s.c[3].r), std::max(s.c[0].r, s.c[3].r), std::min(s.c[0].z, s.c[3].z),
          std::max(s.c[0].z, s.c[3].z)};
}

// Whether the boxes come within `gap` of each other.
bool boxesMeet(const Box& a, const Box& b, double gap) {
  return a.rLow - gap <= b.rHigh && b.rLow - gap <= a.rHigh && a.zLow - gap <= b.zHigh && b.zLow - gap <= a.zHigh;
}

double diagonal(const Sub& s) { return norm(s.c[3] - s.c[0]); }

void halve(const Sub& s, Sub& left, Sub& right) {
  const auto mid = [](Point2 a, Point2 b) { return Point2{0.5 * (a.r + b.r), 0.5 * (a.z + b.z)}; };
  const Point2 a = mid(s.c[0], s.c[1]), b = mid(s.c[1], s.c[2]), c = mid(s.c[2], s.c[3]);
  const Point2 d = mid(a, b), e = mid(b, c), m = mid(d, e);
  left = {{s.c[0], a, d, m}, s.startIsPartStart, false};
  right = {{m, e, c, s.c[3]}, false, s.endIsPartEnd};
}

double pointSegmentDistance(Point2 p, Point2 a, Point2 b) {
  const Point2 e = b - a;
  const double length2 = dot(e, e);
  const double along = length2 > 0.0 ? std::clamp(dot(p - a, e) / length2, 0.0, 1.0) : 0.0;
  return norm(p - Point2{a.r + along * e.r, a.z + along * e.z});
}

bool segmentsCross(Point2 a, Point2 b, Point2 c, Point2 d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  return o1 * o2 <= 0 && o3 * o4 <= 0;  // touching counts (the distance is then 0 anyway)
}

double segmentDistance(Point2 a, Point2 b, Point2 c, Point2 d) {
  if (segmentsCross(a, b, c, d)) return 0.0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                   pointSegmentDistance(d, a, b)});
}

// How far the control hull reaches from the chord.
double hullWidth(const Sub& s) {
  return std::max(pointSegmentDistance(s.c[1], s.c[0], s.c[3]), pointSegmentDistance(s.c[2], s.c[0], s.c[3]));
}

class Checker {
 public:
  Checker(double extent, std::size_t parts)
      : tiny_(0x1p-40 * extent), margin_(2.0 * kCubicAtError * extent), total_(kPairBudget + 256 * long(parts)) {}

  // Parts closer than this may cross once evaluated: each point is computed within kCubicAtError of
  // the extent, so two parts of the curve count as apart only when more than twice that apart.
  double margin() const { return margin_; }

  // Starts a pair of parts: its budget of subdivisions, within what is left of the curve's.
  void startPair() {
    total_ -= pairStart_ - std::max(budget_, 0L);
    budget_ = pairStart_ = std::min(kPairBudget, total_);
  }

  // Whether two parts are apart; joinAB: a's last point is b's first and is a join of the curve;
  // joinBA likewise the other way round.
  bool apart(const Sub& a, const Sub& b, bool joinAB, bool joinBA) {
    if (--budget_ < 0) return false;
    const bool sharedAB = joinAB && a.endIsPartEnd && b.startIsPartStart;
    const bool sharedBA = joinBA && b.endIsPartEnd && a.startIsPartStart;
    if (sharedAB && sharedBA) {  // two parts closing a loop: halve one so each half meets the other once
      Sub a1, a2;
      halve(a, a1, a2);
      return apart(a1, b, joinAB, joinBA) && apart(a2, b, joinAB, joinBA);
    }
    if (sharedAB) return apartAtJoin(a, b);
    if (sharedBA) return apartAtJoin(b, a);
    if (!boxesMeet(boxOf(a), boxOf(b), margin_)) return true;
    if (segmentDistance(a.c[0], a.c[3], b.c[0], b.c[3]) > hullWidth(a) + hullWidth(b) + margin_) return true;
    const double da = diagonal(a), db = diagonal(b);
    if (da <= tiny_ && db <= tiny_) return false;
    Sub x1, x2;
    if (da >= db) {
      halve(a, x1, x2);
      return apart(x1, b, joinAB, joinBA) && apart(x2, b, joinAB, joinBA);
    }
    halve(b, x1, x2);
    return apart(a, x1, joinAB, joinBA) && apart(a, x2, joinAB, joinBA);
  }

 private:
  // Subdivisions a pair of parts may take before it counts as touching: curves running within a
  // few 2^-40 of the extent of each other for much of their length (where only sub-parts that small
  // separate) would take up to 2^40; a thin wall 1e-6 of the extent thick, about 10^4. The whole
  // curve gets one pair's budget plus 256 a part (neighbours take a few each).
  static constexpr long kPairBudget = 1 << 16;

  // `a` ends at the join P where `b` starts.
  bool apartAtJoin(const Sub& a, const Sub& b) {
    if (--budget_ < 0) return false;
    const Point2 p = a.c[3];
    // Boxes meeting only at P's r (or z) would prove the parts share only P, but not that they stay
    // apart by more than rounding next to it: a hairpin 1e-300 wide, its halves on either side of
    // P's z, does not. Only cones tell parts that leave P in different directions apart.
    // Cones from P: each hull lies within the cone about its tangent direction at P whose half-angle
    // is the widest angle of a control point, a convex cone while that is below a right angle; two
    // such cones whose axes are apart by more than both half-angles meet only at P. The margins, 2^-40
    // radians, cover the angles' rounding: directions are taken as unit vectors (scaled by powers of
    // two first, so that control points a subnormal distance from P keep their direction instead
    // of their cross and dot products underflowing to 0).
    const auto cone = [&](const Point2* c, int first, int step, double& halfAngle) -> Point2 {
      Point2 tangent{0.0, 0.0};
      for (int i = first, k = 0; k < 3 && tangent.r == 0.0 && tangent.z == 0.0; i += step, ++k) tangent = c[i] - p;
      tangent = direction(tangent);
      halfAngle = 0.0;
      for (int i = 0; i < 4; ++i) {
        const Point2 d = c[i] - p;
        if (d.r == 0.0 && d.z == 0.0) continue;
        const Point2 e = direction(d);
        halfAngle = std::max(halfAngle, std::atan2(std::abs(cross(tangent, e)), dot(tangent, e)));
      }
      return tangent;
    };
    double halfA, halfB;
    const Point2 ta = cone(a.c, 2, -1, halfA), tb = cone(b.c, 1, 1, halfB);
    const double between = std::atan2(std::abs(cross(ta, tb)), dot(ta, tb));
    constexpr double kMargin = 0x1p-40, kConvex = 0.5 * std::numbers::pi - kMargin;
    if (halfA < kConvex && halfB < kConvex && between > halfA + halfB + kMargin) return true;
    const double da = diagonal(a), db = diagonal(b);
    if (da <= tiny_ && db <= tiny_) return false;  // a cusp: the curve turns back on itself at P
    Sub a1, a2, b1, b2;
    halve(a, a1, a2);
    halve(b, b1, b2);
    return apartAtJoin(a2, b1) && apart(a1, b1, false, false) && apart(a1, b2, false, false) &&
           apart(a2, b2, false, false);
  }

  double tiny_, margin_;
  long total_;
  long pairStart_ = 0, budget_ = 0;
};

}  // namespace

std::optional<PartPair> findCurveSelfIntersection(std::span<const MonotonePart> parts, double extent) {
  const std::size_t n = parts.size();
  if (n < 2) return std::nullopt;
  const bool loop = same(parts.front().c[0], parts.back().c[3]);
  std::vector<Sub> subs(n);
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    subs[i] = {{parts[i].c[0], parts[i].c[1], parts[i].c[2], parts[i].c[3]}, true, true};
    boxes[i] = boxOf(subs[i]);
  }
  // Candidate pairs: boxes that meet, by a sweep in increasing r.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes[a].rLow < boxes[b].rLow; });
  Checker checker(extent, n);
  const double gap = checker.margin();
  std::vector<std::size_t> active;
  for (const std::size_t i : order) {
    std::erase_if(active, [&](std::size_t j) { return boxes[j].rHigh + gap < boxes[i].rLow; });
    for (const std::size_t j : active) {
      if (!boxesMeet(boxes[i], boxes[j], gap)) continue;
      const std::size_t a = std::min(i, j), b = std::max(i, j);
      const bool joinAB = b == a + 1;                    // consecutive: a's end is b's start
      const bool joinBA = loop && a == 0 && b == n - 1;  // the loop's closing join: b's end is a's start
      checker.startPair();
      if (!checker.apart(subs[a], subs[b], joinAB, joinBA)) return PartPair{a, b};
    }
    active.push_back(i);
  }
  return std::nullopt;
}

}  // namespace revolve::detail
