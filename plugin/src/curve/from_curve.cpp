// Profile::fromCurve: the fewest polyline points within a tolerance of a spline, chosen greedily,
// each chord reaching as far along the curve as its exact chord error allows.
#include <revolve/core.h>

#include "curve/cubic.h"
#include "profile/self_intersection.h"
#include "util/format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace revolve {
namespace {

// A position on the curve: piece index plus parameter, as one number T in [0, pieces].
class CurveWalk {
 public:
  explicit CurveWalk(const Spline& curve) : bezier_(curve.bezier()), pieces_(curve.pieceCount()) {}

  std::size_t pieces() const { return pieces_; }

  // Whether the curve turns a corner where piece k - 1 ends and piece k begins: the tangents
  // (towards the first control point apart from the join) differ by more than the rounding of the
  // control points (8 u in the sine of their angle), or point against each other.
  bool cornerAt(std::size_t k) const {
    const Point2* before = &bezier_[3 * k - 3];
    const Point2* after = &bezier_[3 * k];
    const auto direction = [](Point2 from, Point2 a, Point2 b, Point2 c) {
      for (const Point2 p : {a, b, c}) {
        if (p.r != from.r || p.z != from.z) return Point2{p.r - from.r, p.z - from.z};
      }
      return Point2{0.0, 0.0};
    };
    const Point2 in = direction(before[3], before[2], before[1], before[0]);  // backwards along piece k - 1
    const Point2 out = direction(after[0], after[1], after[2], after[3]);
    const double cross = in.r * out.z - in.z * out.r, dot = in.r * out.r + in.z * out.z;
    // Smooth when `in` and `out` point opposite ways (the curve goes straight on).
    return !(dot < 0.0 && std::abs(cross) <= 8.0 * 0x1p-53 * std::hypot(in.r, in.z) * std::hypot(out.r, out.z));
  }

  Point2 at(double T) const {
    const auto [k, u] = split(T);
    return pieceAt(k, u);
  }

  // How far the arc between at(Ta) and at(Tb) strays from the chord between them. Where the arc
  // is a graph over the chord (its tangent points along the chord throughout), this is exactly the
  // arc's largest distance from the chord's line. Elsewhere (the arc turns back somewhere, as a
  // curve folding back on itself does) it is the largest distance of the arc's control points from
  // the chord segment, a bound by the convex hull property. Either bounds the Hausdorff distance
  // between arc and chord: a continuous arc from a to b projects onto the whole chord, so every
  // chord point has an arc point no farther away than the arc's distance from the segment.
  // Infinity for a chord of no length (the arc returns to its start).
  double chordError(double Ta, double Tb) const {
    const Point2 a = at(Ta), b = at(Tb);
    const double er = b.r - a.r, ez = b.z - a.z, length = std::hypot(er, ez);
    if (!(length > 0.0)) return std::numeric_limits<double>::infinity();
    const double ur = er / length, uz = ez / length;
    const double graph = graphChordError(Ta, Tb, a, ur, uz);
    return graph < std::numeric_limits<double>::infinity() ? graph : hullChordError(Ta, Tb, a, b);
  }

 private:
  // The largest distance of the arc's restricted control points from the segment a-b.
  double hullChordError(double Ta, double Tb, Point2 a, Point2 b) const {
    const double er = b.r - a.r, ez = b.z - a.z, length2 = er * er + ez * ez;
    const auto [k0, u0] = split(Ta);
    const auto [k1, u1] = split(Tb);
    double worst = 0.0;
    for (std::size_t k = k0; k <= k1 && k < pieces_; ++k) {
      const double from = k == k0 ? u0 : 0.0, to = k == k1 ? u1 : 1.0;
      if (!(to > from)) continue;
      const Point2* c = &bezier_[3 * k];
      const double r[4] = {c[0].r, c[1].r, c[2].r, c[3].r}, z[4] = {c[0].z, c[1].z, c[2].z, c[3].z};
      double rs[4], zs[4];
      detail::cubicRestricted(r, from, to, rs);
      detail::cubicRestricted(z, from, to, zs);
      for (int i = 0; i < 4; ++i) {
        const double s = std::clamp(((rs[i] - a.r) * er + (zs[i] - a.z) * ez) / length2, 0.0, 1.0);
        worst = std::max(worst, std::hypot(rs[i] - (a.r + s * er), zs[i] - (a.z + s * ez)));
      }
    }
    return worst;
  }

  // The arc's largest distance from the chord's line (direction ur, uz through a), or infinity
  // when it is not a graph over the chord.
  double graphChordError(double Ta, double Tb, Point2 a, double ur, double uz) const {
    const auto [k0, u0] = split(Ta);
    const auto [k1, u1] = split(Tb);
    double worst = 0.0;
    for (std::size_t k = k0; k <= k1 && k < pieces_; ++k) {
      const double from = k == k0 ? u0 : 0.0, to = k == k1 ? u1 : 1.0;
      if (!(to > from)) continue;
      const Point2* c = &bezier_[3 * k];
      const double r[4] = {c[0].r, c[1].r, c[2].r, c[3].r}, z[4] = {c[0].z, c[1].z, c[2].z, c[3].z};
      double rs[4], zs[4];
      detail::cubicRestricted(r, from, to, rs);
      detail::cubicRestricted(z, from, to, zs);
      // Along the chord: the tangent's component c'(t) . u, a quadratic with Bernstein coefficients
      // 3 (c[i+1] - c[i]) . u, must stay >= 0 (zero at most at an end or a point: a repeated
      // control point), so that the arc's projection on the chord moves forward throughout.
      const double d0 = (rs[1] - rs[0]) * ur + (zs[1] - zs[0]) * uz, d1 = (rs[2] - rs[1]) * ur + (zs[2] - zs[1]) * uz,
                   d2 = (rs[3] - rs[2]) * ur + (zs[3] - zs[2]) * uz;
      const double infinity = std::numeric_limits<double>::infinity();
      if (!(d0 >= 0.0 && d2 >= 0.0) || (d0 == 0.0 && d1 == 0.0 && d2 == 0.0)) return infinity;
      const double curvature = d0 - 2.0 * d1 + d2;  // the quadratic's leading coefficient
      if (curvature > 0.0) {
        const double t = (d0 - d1) / curvature;  // its minimum, when inside (0, 1)
        if (t > 0.0 && t < 1.0 && !(d0 * (1 - t) * (1 - t) + 2 * d1 * t * (1 - t) + d2 * t * t > 0.0)) return infinity;
      }
      // Across the chord: the signed distance cross(u, c(t) - a), a cubic; its largest magnitude is
      // at an end or where its derivative changes sign.
      double g[4];
      for (int i = 0; i < 4; ++i) g[i] = ur * (zs[i] - a.z) - uz * (rs[i] - a.r);
      worst = std::max({worst, std::abs(g[0]), std::abs(g[3])});
      double turns[2];
      for (int i = 0, count = detail::derivativeSignChanges(g, turns); i < count; ++i) {
        worst = std::max(worst, std::abs(detail::cubicAt(g, turns[i])));
      }
    }
    return worst;
  }

  std::pair<std::size_t, double> split(double T) const {
    if (T >= double(pieces_)) return {pieces_ - 1, 1.0};
    const auto k = static_cast<std::size_t>(T);
    return {k, T - double(k)};
  }
  Point2 pieceAt(std::size_t k, double u) const {
    const Point2* c = &bezier_[3 * k];
    const double r[4] = {c[0].r, c[1].r, c[2].r, c[3].r}, z[4] = {c[0].z, c[1].z, c[2].z, c[3].z};
    return {detail::cubicAt(r, u), detail::cubicAt(z, u)};
  }

  std::span<const Point2> bezier_;
  std::size_t pieces_;
};

// Samples a piece taken when looking for three far-apart points of a loop.
constexpr int kLoopSamples = 16;

}  // namespace

Profile Profile::fromCurve(const Spline& curve, double tolerance) {
  if (!toleranceAllowed(tolerance)) {
    throw std::invalid_argument("polyline tolerance " + detail::formatNumber(tolerance) +
                                " is out of range: " + kToleranceRule);
  }
  if (curve.kind() == SplineKind::linear) return Profile(curve.points());
  double extent = 0.0;
  for (const Point2& p : curve.bezier()) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  // Chords are computed in double: below 2^-40 of the extent a chord error is mostly rounding, and
  // the walk would crawl.
  if (tolerance < 0x1p-40 * extent) {
    throw std::invalid_argument("polyline tolerance " + detail::formatNumber(tolerance) +
                                " is below 2^-40 of the curve's extent " + detail::formatNumber(extent) +
                                ", finer than double-precision chords resolve");
  }
  // Each point is evaluated within kCubicAtError of the extent, so two closer than twice that are
  // one vertex: their order along the curve is lost in rounding, and keeping both can fold the
  // polyline back on itself where the curve moves slowly (next to a repeated control point). Such
  // a merge moves a chord by at most that distance, so chords are measured against what is left of
  // the tolerance (at least 2^-40 of the extent, hence 255/256 of it or more).
  const double indistinct = 2.0 * detail::kCubicAtError * extent;
  const double chordTolerance = tolerance - indistinct;
  const CurveWalk walk(curve);
  const double last = double(walk.pieces());
  // Chords may span smooth joins but not corners, which stay vertices (a rim stays sharp).
  std::vector<double> corners;
  for (std::size_t k = 1; k < walk.pieces(); ++k) {
    if (walk.cornerAt(k)) corners.push_back(double(k));
  }
  corners.push_back(last);
  // A loop (its ends one point) no larger than the tolerance lies within it of a chord from its
  // start to almost its start: two points, no profile. Three of its points far apart stay vertices
  // instead: of samples along it, the farthest from the start, and the farthest from the line
  // through those two. Any three points not on one line make a valid triangle to refine from; a
  // loop within rounding of a line or a point is refused by Spline.
  const Point2 start = walk.at(0.0), finish = walk.at(last);
  if (start.r == finish.r && start.z == finish.z) {
    const auto sampleBest = [&](auto&& score) {
      double bestT = 0.0, best = 0.0;
      for (std::size_t k = 0; k < walk.pieces(); ++k) {
        for (int i = 1; i < kLoopSamples; ++i) {
          const double T = double(k) + double(i) / kLoopSamples;
          if (const double value = score(walk.at(T)); value > best) best = value, bestT = T;
        }
      }
      return bestT;
    };
    const double far = sampleBest([&](Point2 q) { return std::hypot(q.r - start.r, q.z - start.z); });
    const Point2 f = walk.at(far);
    const double wide = sampleBest(
        [&](Point2 q) { return std::abs((f.r - start.r) * (q.z - start.z) - (f.z - start.z) * (q.r - start.r)); });
    for (const double T : {far, wide}) {
      if (T > 0.0) corners.push_back(T);
    }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  }
  std::vector<double> parameters{0.0};  // each point's place on the curve, T = piece + u
  double T = 0.0;
  std::size_t nextCorner = 0;
  while (T < last) {
    while (corners[nextCorner] <= T) ++nextCorner;
    const double end = corners[nextCorner];
    if (walk.chordError(T, end) <= chordTolerance) {
      T = end;
    } else {
      // Gallop over whole pieces, then bisect for the farthest reach the tolerance allows. A chord
      // is only ever taken where its error was computed within the tolerance.
      double good = T, bad = end;
      for (double step = 1.0;; step *= 2.0) {
        const double next = std::floor(T) + step;
        if (next >= end) break;
        if (walk.chordError(T, next) <= chordTolerance) {
          good = next;
        } else {
          bad = next;
          break;
        }
      }
      while (bad - good > 0x1p-44 * std::max(1.0, bad)) {
        const double middle = 0.5 * (good + bad);
        (walk.chordError(T, middle) <= chordTolerance ? good : bad) = middle;
      }
      if (good == T) {
        // Even the shortest chord tried fails (a tolerance below the curve's rounding): step on.
        good = std::min(end, std::nextafter(bad, end));
      }
      T = good;
    }
    parameters.push_back(T);
    if (parameters.size() > kMaxPoints) {
      throw std::invalid_argument("polyline tolerance " + detail::formatNumber(tolerance) + " needs more than " +
                                  std::to_string(kMaxPoints) + " points");
    }
  }

  // Chords within the tolerance of their arcs may still cross or touch one another where two parts
  // of the curve pass closer than twice the tolerance (a thin rim, a stem inside a foot), though
  // the curve itself does not (Spline refuses that). Both chords of such a pair are split at the
  // middle of their arcs, and each half further until it is within the tolerance again, until no
  // pair is left: halving an arc's parameter range brings its chord towards it, so this ends once
  // the chords there lie closer to the curve than its two parts lie to each other.
  const auto pointsOf = [&] {
    std::vector<Point2> points;
    points.reserve(parameters.size());
    for (const double t : parameters) points.push_back(walk.at(t));
    return points;
  };
  std::vector<Point2> points = pointsOf();
  // Appends the parameters strictly between `from` and `to` that cut the arc into chords within
  // the tolerance, its middle always among them.
  const auto refine = [&](auto&& self, double from, double to, std::vector<double>& out) -> void {
    const double middle = 0.5 * (from + to);
    if (!(middle > from && middle < to)) return;  // a parameter range at its resolution
    if (walk.chordError(from, middle) > chordTolerance) self(self, from, middle, out);
    out.push_back(middle);
    if (walk.chordError(middle, to) > chordTolerance) self(self, middle, to, out);
  };
  // Each round splits one crossing pair and sweeps the whole polyline again; a pair of arcs that
  // do not touch comes apart after as many halvings as their distance is below their length in
  // binary digits. Spline accepts only curves whose parts stay more than twice a point's rounding
  // apart (away from the joins, where their cones part them), so the arcs here come apart within
  // about 48 halvings. The bound below is a guard should that reasoning have a hole (fuzzing found
  // such holes twice, now closed): once the rounds have swept 64 times the first polyline's points,
  // or 2^20 if more (a fraction of a second), the pair is refused with a clear message instead of
  // the sweep running for minutes.
  const std::size_t maxSweptPoints = std::max(std::size_t(1) << 20, 64 * points.size());
  std::size_t swept = 0, rounds = 0;
  for (;;) {
    std::vector<double> kept{parameters.front()};
    std::vector<Point2> keptPoints{points.front()};
    for (std::size_t i = 1; i < points.size(); ++i) {
      // (Profile refuses segments shorter than 2^-60 of its extent, far below `indistinct`.)
      if (!(std::hypot(points[i].r - keptPoints.back().r, points[i].z - keptPoints.back().z) < indistinct)) {
        kept.push_back(parameters[i]);
        keptPoints.push_back(points[i]);
      } else if (i + 1 == points.size() && keptPoints.size() > 1) {
        kept.back() = parameters[i];  // the curve's end stays; the point just before it goes
        keptPoints.back() = points[i];
      }
    }
    parameters = std::move(kept);
    points = std::move(keptPoints);
    const std::optional<detail::SegmentPair> pair =
        points.size() >= 2 ? detail::findSelfIntersection(points) : std::nullopt;
    if (!pair) break;
    swept += points.size(), ++rounds;
    if (swept > maxSweptPoints) {
      throw ProfileError(ProfileError::Rule::selfIntersecting, pair->first,
                         "the polyline within " + detail::formatNumber(tolerance) +
                             " of the curve still has crossing chords near polyline points " +
                             std::to_string(pair->first) + " and " + std::to_string(pair->second) +
                             " after splitting them " + std::to_string(rounds) +
                             " times: the curve comes within "
                             "rounding of itself there");
    }
    std::vector<double> refined;
    refined.reserve(parameters.size() + 8);
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      refined.push_back(parameters[i]);
      if (i == pair->first || i == pair->second) refine(refine, parameters[i], parameters[i + 1], refined);
    }
    if (refined.size() == parameters.size()) break;  // nothing left to split: Profile reports the pair
    if (refined.size() > kMaxPoints) {
      throw std::invalid_argument("polyline tolerance " + detail::formatNumber(tolerance) + " needs more than " +
                                  std::to_string(kMaxPoints) + " points");
    }
    parameters = std::move(refined);
    points = pointsOf();
  }
  Profile polyline(points);
  polyline.curveParameters_.reserve(polyline.points().size());
  for (const std::size_t i : polyline.sourceIndex()) polyline.curveParameters_.push_back(parameters[i]);
  return polyline;
}

}  // namespace revolve
