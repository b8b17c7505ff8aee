#include "reference_ranges.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace revolve::bench {
namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3d times(const std::array<Vec3d, 3>& m, const Vec3d& v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }

// Keeps t if it is a nearer hit than `best`.
void offer(double t, double& best) {
  if (t > 0 && t < best) best = t;
}

// The ray p + t d (object space) against the surface swept by segment a-b.
void segmentHits(const Vec3d& p, const Vec3d& d, Point2 a, Point2 b, double& best) {
  if (a.z == b.z) {  // a disc or an annulus in the plane z = a.z
    if (d[2] == 0) return;
    const double t = (a.z - p[2]) / d[2];
    const double rho = std::hypot(p[0] + t * d[0], p[1] + t * d[1]);
    if (rho >= std::min(a.r, b.r) && rho <= std::max(a.r, b.r)) offer(t, best);
    return;
  }
  // rho = A + B t along the ray with rho(z) = a.r + (z - a.z) s on the segment's line: the cone
  // x^2 + y^2 = rho^2, with rho >= 0 (not the mirror nappe) and z within the segment.
  const double s = (b.r - a.r) / (b.z - a.z);
  const double A = a.r + (p[2] - a.z) * s, B = d[2] * s;
  const double qa = d[0] * d[0] + d[1] * d[1] - B * B, qb = p[0] * d[0] + p[1] * d[1] - A * B,
               qc = p[0] * p[0] + p[1] * p[1] - A * A;
  double roots[2];
  int count = 0;
  if (qa == 0) {
    if (qb != 0) roots[count++] = -qc / (2 * qb);
  } else {
    const double disc = qb * qb - qa * qc;
    if (disc < 0) return;
    const double q = -(qb + std::copysign(std::sqrt(disc), qb));  // no cancellation (Numerical Recipes)
    if (q != 0) roots[count++] = qc / q;
    roots[count++] = q / qa;
  }
  const double zLow = std::min(a.z, b.z), zHigh = std::max(a.z, b.z);
  for (int i = 0; i < count; ++i) {
    const double t = roots[i], z = p[2] + t * d[2];
    if (z >= zLow && z <= zHigh && A + B * t >= 0) offer(t, best);
  }
}

}  // namespace

ReferenceRanges::ReferenceRanges(const io::SceneDescription& scene) {
  profiles_.reserve(scene.profiles.size());
  for (const io::SceneProfile& profile : scene.profiles) {
    const std::span<const Point2> points = profile.polyline().points();
    profiles_.emplace_back(points.begin(), points.end());
  }
  for (const io::SceneObject& object : scene.objects) {
    const app::Transform& t = object.transform;
    // World to object: scale^-1 rotation^T (x - translate).
    const double theta = t.rotateDegrees * std::numbers::pi / 180, c = std::cos(theta), s = std::sin(theta);
    const auto& k = t.rotateAxis;
    const double r[3][3] = {
        {c + k[0] * k[0] * (1 - c), k[0] * k[1] * (1 - c) - k[2] * s, k[0] * k[2] * (1 - c) + k[1] * s},
        {k[1] * k[0] * (1 - c) + k[2] * s, c + k[1] * k[1] * (1 - c), k[1] * k[2] * (1 - c) - k[0] * s},
        {k[2] * k[0] * (1 - c) - k[1] * s, k[2] * k[1] * (1 - c) + k[0] * s, c + k[2] * k[2] * (1 - c)}};
    Object o{&profiles_[object.profile], {}, t.translate, {}, 0};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) o.inverse[i][j] = r[j][i] / t.scale[i];
    }
    double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
    for (const Point2 p : *o.profile)
      rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
    o.centre = {0, 0, 0.5 * (zLow + zHigh)};
    o.radius = std::hypot(rMax, 0.5 * (zHigh - zLow));
    objects_.push_back(o);
  }
  for (std::size_t q = 0; q < scene.quads.size(); ++q) {
    const auto& c = scene.quads[q].corners;
    const std::int64_t id = std::int64_t(scene.objects.size() + q);
    triangles_.push_back({c[0], c[1], c[2], id});
    triangles_.push_back({c[0], c[2], c[3], id});
  }
}

std::optional<ReferenceHit> ReferenceRanges::trace(const Vec3d& origin, const Vec3d& direction) const {
  double best = INFINITY;
  std::int64_t bestObject = -1;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    const Object& o = objects_[i];
    // The ray in object space keeps its parameter t (the map is affine).
    const Vec3d p = times(o.inverse, minus(origin, o.translate)), d = times(o.inverse, direction);
    // Skip objects whose bounding sphere the ray misses (padded by 2^-30 of its radius for rounding).
    const Vec3d pc = minus(p, o.centre);
    const double a = dot(d, d), b = dot(pc, d), c = dot(pc, pc) - o.radius * o.radius * (1 + 0x1p-30);
    if (b * b - a * c < 0 || (c > 0 && b > 0)) continue;
    double t = best;
    for (std::size_t k = 0; k + 1 < o.profile->size(); ++k) segmentHits(p, d, (*o.profile)[k], (*o.profile)[k + 1], t);
    if (t < best) best = t, bestObject = std::int64_t(i);
  }
  for (const Triangle& tri : triangles_) {
    const Vec3d e1 = minus(tri.b, tri.a), e2 = minus(tri.c, tri.a), h = cross(direction, e2);
    const double det = dot(e1, h);
    if (det == 0) continue;
    const Vec3d s = minus(origin, tri.a);
    const double u = dot(s, h) / det;
    if (u < 0 || u > 1) continue;
    const Vec3d q = cross(s, e1);
    const double v = dot(direction, q) / det;
    if (v < 0 || u + v > 1) continue;
    const double t = dot(e2, q) / det;
    if (t > 0 && t < best) best = t, bestObject = tri.object;
  }
  if (bestObject < 0) return std::nullopt;
  return ReferenceHit{best, bestObject};
}

}  // namespace revolve::bench
