// Clearance in the meridian plane (revolve.h, "Clearance"): the least signed distance from an
// axis-aligned rectangle (a vertical cylinder beside an upright shape, seen in the meridian plane;
// a point when degenerate) to the profile polyline. Each segment is solved in closed form; the
// MIBIT tree's meridian boxes give lower bounds that skip far runs of the profile, best first.
#include "curve/part_distance.h"
#include "mibit/best_first.h"
#include "shape/shape_impl.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace revolve {
namespace {

// [rLow, rHigh] x [zLow, zHigh] in the scaled local frame (r * radial, (z - zCentre) * axial).
struct Rect {
  double rLow, rHigh, zLow, zHigh;
};

struct Candidate {
  double value;  // signed distance
  double r, z;   // the segment point realising it
};

// Signed distance from (r, z) to the rectangle: Euclidean outside; inside, minus the distance to
// the nearest side (the cylinder's signed distance function, restricted to a meridian).
double signedDistance(const Rect& q, double r, double z) {
  const double dr = std::max(q.rLow - r, r - q.rHigh);
  const double dz = std::max(q.zLow - z, z - q.zHigh);
  if (dr <= 0 && dz <= 0) return std::max(dr, dz);
  return std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
}

// A lower bound of the signed distance over a box [r0, r1] x [z0, z1]: the distance between the
// two rectangles when apart; otherwise minus the greatest depth in their overlap, which separates
// (the depth is min(tent in r, tent in z), and max over a product of a min of separate terms is the
// min of their maxima): each tent peaks at its side's midpoint, clamped into the overlap.
double boxBound(const Rect& q, double r0, double r1, double z0, double z1) {
  const double gapR = std::max({q.rLow - r1, r0 - q.rHigh, 0.0});
  const double gapZ = std::max({q.zLow - z1, z0 - q.zHigh, 0.0});
  if (gapR > 0 || gapZ > 0) return std::hypot(gapR, gapZ);
  const double r = std::clamp(0.5 * (q.rLow + q.rHigh), std::max(r0, q.rLow), std::min(r1, q.rHigh));
  const double z = std::clamp(0.5 * (q.zLow + q.zHigh), std::max(z0, q.zLow), std::min(z1, q.zHigh));
  return -std::min(std::min(r - q.rLow, q.rHigh - r), std::min(z - q.zLow, q.zHigh - z));
}

// Liang-Barsky: narrows [t0, t1] to where p + t e lies in [lo, hi]; false when that is empty.
bool clip(double p, double e, double lo, double hi, double& t0, double& t1) {
  if (e == 0) return p >= lo && p <= hi;
  double enter = (lo - p) / e, leave = (hi - p) / e;
  if (e < 0) std::swap(enter, leave);
  t0 = std::max(t0, enter);
  t1 = std::min(t1, leave);
  return t0 <= t1;
}

// The least signed distance from the rectangle to the segment a-b.
Candidate segmentMinimum(const Rect& q, Point2 a, Point2 b) {
  const double er = b.r - a.r, ez = b.z - a.z;
  double t0 = 0, t1 = 1;
  if (clip(a.r, er, q.rLow, q.rHigh, t0, t1) && clip(a.z, ez, q.zLow, q.zHigh, t0, t1)) {
    // Inside over [t0, t1]: the depth is the least of four linear functions of t (the distances
    // to the four sides), concave, so its maximum lies at an end or where two of them cross.
    const double value0[4] = {a.r - q.rLow, q.rHigh - a.r, a.z - q.zLow, q.zHigh - a.z};
    const double slope[4] = {er, -er, ez, -ez};
    const auto depth = [&](double t) {
      return std::min(std::min(value0[0] + slope[0] * t, value0[1] + slope[1] * t),
                      std::min(value0[2] + slope[2] * t, value0[3] + slope[3] * t));
    };
    double bestT = t0, bestDepth = depth(t0);
    const auto consider = [&](double t) {
      const double d = depth(t);
      if (d > bestDepth) bestDepth = d, bestT = t;
    };
    consider(t1);
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        if (slope[i] == slope[j]) continue;
        const double t = (value0[j] - value0[i]) / (slope[i] - slope[j]);
        if (t > t0 && t < t1) consider(t);
      }
    }
    return {-bestDepth, a.r + bestT * er, a.z + bestT * ez};
  }
  // Apart: two disjoint convex sets of the plane are closest at a vertex of one of them, so the
  // candidates are the segment's ends and the rectangle's corners projected onto the segment.
  Candidate best{signedDistance(q, a.r, a.z), a.r, a.z};
  const double atB = signedDistance(q, b.r, b.z);
  if (atB < best.value) best = {atB, b.r, b.z};
  const double length2 = er * er + ez * ez;
  for (const double cr : {q.rLow, q.rHigh}) {
    for (const double cz : {q.zLow, q.zHigh}) {
      const double t = std::clamp(((cr - a.r) * er + (cz - a.z) * ez) / length2, 0.0, 1.0);
      const double pr = a.r + t * er, pz = a.z + t * ez;
      const double d = std::hypot(pr - cr, pz - cz);
      if (d < best.value) best = {d, pr, pz};
    }
  }
  return best;
}

// Best-first search of the profile for the least signed distance, pruned by meridian boxes.
class ClearanceSearch {
 public:
  ClearanceSearch(const detail::ShapeImpl& shape, const Rect& rect, double radial, double axial)
      : shape_(shape), rect_(rect), radial_(radial), axial_(axial) {}

  void run() {
    detail::searchBestFirst(
        shape_.mibit, detail::localPointsOf(shape_),
        [&](double rMin, double rMax, double zLow, double zHigh) { return scaledBoxBound(rMin, rMax, zLow, zHigh); },
        [&](double bound) { return bound >= best_.value; }, [&](std::uint32_t k) { visit(k); });
  }

  const Candidate& best() const { return best_; }
  std::uint32_t segment() const { return segment_; }

 private:
  Point2 scaled(std::uint32_t k) const {
    const Point2 p = detail::localPointsOf(shape_)[k];
    return {p.r * radial_, p.z * axial_};
  }

  double scaledBoxBound(double rMin, double rMax, double zLow, double zHigh) const {
    const double za = zLow * axial_, zb = zHigh * axial_;
    return boxBound(rect_, rMin * radial_, rMax * radial_, std::min(za, zb), std::max(za, zb));
  }

  void visit(std::uint32_t k) {
    Candidate c;
    if (shape_.curved()) {
      // A spline's part, scaled as the profile is (monotone still; z's direction may flip).
      const detail::CurvePart& part = shape_.parts[k];
      double r[4], z[4];
      for (int i = 0; i < 4; ++i) r[i] = part.r[i] * radial_, z[i] = part.z[i] * axial_;
      const detail::PartMinimum m = detail::partMinimum({rect_.rLow, rect_.rHigh, rect_.zLow, rect_.zHigh}, r, z);
      c = {m.value, m.r, m.z};
    } else {
      c = segmentMinimum(rect_, scaled(k), scaled(k + 1));
    }
    if (c.value < best_.value) best_ = c, segment_ = k;
  }

  const detail::ShapeImpl& shape_;
  Rect rect_;
  double radial_, axial_;
  Candidate best_{std::numeric_limits<double>::infinity(), 0, 0};
  std::uint32_t segment_ = 0;
};

bool finite(double x) { return std::abs(x) < HUGE_VAL; }

}  // namespace

CylinderClearance cylinderClearance(const Shape& shape, const UprightCylinder& cylinder, MeridianScale scale) noexcept {
  const detail::ShapeImpl& impl = detail::implOf(shape);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Written so that NaN fails every test.
  const bool valid = finite(cylinder.axisDistance) && cylinder.axisDistance >= 0 && finite(cylinder.radius) &&
                     cylinder.radius >= 0 && finite(cylinder.zMin) && finite(cylinder.zMax) &&
                     cylinder.zMin <= cylinder.zMax && finite(scale.radial) && scale.radial > 0 &&
                     finite(scale.axial) && scale.axial != 0;
  if (!valid) return {nan, {nan, nan}, 0};
  // Heights in the scaled local frame: z_scaled = axial * (z_local + zCentre).
  const double shift = scale.axial * impl.frame.zCentre;
  const Rect rect{cylinder.axisDistance - cylinder.radius, cylinder.axisDistance + cylinder.radius,
                  cylinder.zMin - shift, cylinder.zMax - shift};
  ClearanceSearch search(impl, rect, scale.radial, scale.axial);
  search.run();
  const Candidate& best = search.best();
  return {best.value, {best.r, best.z + shift}, search.segment()};
}

MeridianPoint closestMeridianPoint(const Shape& shape, Point2 query) noexcept {
  // A degenerate cylinder: the rectangle is the point itself, whose signed distance is the distance.
  const CylinderClearance closest = cylinderClearance(shape, {query.r, 0.0, query.z, query.z});
  return {closest.point, closest.clearance, closest.segment};
}

}  // namespace revolve
