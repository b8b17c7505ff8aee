// Smooth shading normals from per-vertex normals along the profile (see revolve.h, ShadingNormals).
#include <revolve/core.h>

#include "curve/cubic.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace revolve {
namespace {

struct Direction {  // a unit vector in the (r, z) half-plane
  double r, z;
};

Direction unitDirection(Point2 from, Point2 to) {
  const double dr = to.r - from.r, dz = to.z - from.z;
  const double length = std::hypot(dr, dz);  // > 0: Profile rejects segments below 2^-60 of its extent
  return {dr / length, dz / length};
}

// Right of the direction of travel, as the geometric normal (revolve.h, Conventions).
Direction rightNormal(Direction e) { return {e.z, -e.r}; }

double turningDegrees(Direction before, Direction after) {
  const double cross = before.r * after.z - before.z * after.r;
  const double dot = before.r * after.r + before.z * after.z;
  return std::atan2(std::abs(cross), dot) * (180.0 / std::numbers::pi);
}

}  // namespace

ShadingNormals::ShadingNormals(const Profile& profile, double creaseDegrees) {
  if (!(creaseDegrees >= 0.0 && creaseDegrees <= 180.0)) {
    throw std::invalid_argument("crease angle " + std::to_string(creaseDegrees) + " degrees: must lie in [0, 180]");
  }
  const std::span<const Point2> p = profile.points();
  const std::span<const double> arc = profile.arcLength();
  const std::size_t segments = profile.segmentCount();
  const double total = arc.back();

  std::vector<Direction> direction(segments);
  std::vector<double> length(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    direction[i] = unitDirection(p[i], p[i + 1]);
    length[i] = arc[i + 1] - arc[i];
  }

  // The segment before a vertex and the one after it, as (direction, length): a neighbour, the
  // mirror image across the axis at an end on the axis, the other end's segment in a closed loop,
  // or none at an open end.
  struct Side {
    Direction e;
    double length;
  };
  const bool loop = p.front().r == p.back().r && p.front().z == p.back().z;
  const auto before = [&](std::size_t vertex) -> std::optional<Side> {
    if (vertex > 0) return Side{direction[vertex - 1], length[vertex - 1]};
    if (loop) return Side{direction[segments - 1], length[segments - 1]};
    // Segment 0 mirrored across the axis, from (-r1, z1) to the axis point: direction (e.r, -e.z).
    if (p.front().r == 0.0) return Side{Direction{direction[0].r, -direction[0].z}, length[0]};
    return std::nullopt;
  };
  const auto after = [&](std::size_t vertex) -> std::optional<Side> {
    if (vertex < segments) return Side{direction[vertex], length[vertex]};
    if (loop) return Side{direction[0], length[0]};
    // The last segment mirrored, from the axis point to (-r, z) of the one before: (e.r, -e.z).
    if (p.back().r == 0.0)
      return Side{Direction{direction[segments - 1].r, -direction[segments - 1].z}, length[segments - 1]};
    return std::nullopt;
  };

  startNormal_.resize(segments);
  endNormal_.resize(segments);
  segmentStart_.resize(segments);
  segmentLength_.resize(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    const Direction n = rightNormal(direction[i]);
    startNormal_[i] = {n.r, n.z};
    endNormal_[i] = {n.r, n.z};
    segmentStart_[i] = arc[i] / total;
    segmentLength_[i] = length[i] / total;
  }
  for (std::size_t vertex = 0; vertex <= segments; ++vertex) {
    const std::optional<Side> in = before(vertex), out = after(vertex);
    if (!in || !out || turningDegrees(in->e, out->e) > creaseDegrees) continue;
    // The normal at the vertex of the circle through it and its two neighbours: each unit normal
    // weighted by the other segment's length (the chord-tangent angles of a circle are half the
    // arcs, and chord lengths are 2R sin of them, which makes this sum perpendicular to the
    // circle's tangent at the vertex).
    const Direction nIn = rightNormal(in->e), nOut = rightNormal(out->e);
    const double r = out->length * nIn.r + in->length * nOut.r;
    const double z = out->length * nIn.z + in->length * nOut.z;
    const double norm = std::hypot(r, z);
    if (!(norm > 0.0)) continue;  // a fold back on itself: keep the faces' own normals
    const Meridian vertexNormal{r / norm, z / norm};
    if (vertex > 0)
      endNormal_[vertex - 1] = vertexNormal;
    else if (loop)
      endNormal_[segments - 1] = vertexNormal;
    if (vertex < segments)
      startNormal_[vertex] = vertexNormal;
    else if (loop)
      startNormal_[0] = vertexNormal;
  }
}

ShadingNormals::ShadingNormals(const Profile& polyline, const Spline& curve) : ShadingNormals(polyline, 180.0) {
  const std::span<const double> T = polyline.curveParameters();
  const std::span<const Point2> p = polyline.points();
  if (T.size() != p.size()) {
    throw std::invalid_argument(
        "curve shading normals: the polyline was not made by Profile::fromCurve (it records no curve parameters)");
  }
  const double pieces = double(curve.pieceCount());
  for (std::size_t i = 0; i < p.size(); ++i) {
    // fromCurve places point i at exactly this evaluation of the curve.
    const std::size_t k = T[i] >= pieces ? curve.pieceCount() - 1 : std::size_t(T[i]);
    const Point2 on = curve.at(k, T[i] >= pieces ? 1.0 : T[i] - double(k));
    if (!(T[i] >= 0.0 && T[i] <= pieces) || on.r != p[i].r || on.z != p[i].z) {
      throw std::invalid_argument("curve shading normals: point " + std::to_string(i) +
                                  " of the polyline does not lie on the " + splineKindName(curve.kind()) +
                                  " spline at its recorded parameter (made from another curve?)");
    }
  }
  curveParameter_.assign(T.begin(), T.end());
  vertex_.assign(p.begin(), p.end());
  bezier_.assign(curve.bezier().begin(), curve.bezier().end());
}

// The curve's normal at the point of segment `segment`'s arc that projects onto the segment at
// fraction s of its length: the root of ((c(T) - a) . e) / |e|^2 = s, between the segment's end
// parameters, by Newton steps kept inside a bisection bracket (Press et al.'s rtsafe). Where the arc
// is a graph over its chord (the usual case: fromCurve's chords follow their arcs) the projection
// is monotone and the root unique. Newton converges in a few steps on the smooth cubic; the loop
// stops when a step moves T by less than 2^-30 of the segment's range (s comes from a float v, a
// few 2^-24 of the whole profile), or after 24 steps.
ShadingNormals::Meridian ShadingNormals::curveNormal(std::uint32_t segment, double s) const noexcept {
  const double T0 = curveParameter_[segment], T1 = curveParameter_[segment + 1];
  const Point2 a = vertex_[segment], b = vertex_[segment + 1];
  const double er = b.r - a.r, ez = b.z - a.z, length2 = er * er + ez * ez;
  // The arc's pieces: a segment never spans a corner, but may end exactly on a join, where the
  // piece it belongs to is the one before the join (its end) or after it (its start).
  const double pieces = double((bezier_.size() - 1) / 3);
  const double firstPiece = std::min(std::floor(T0), pieces - 1.0),
               lastPiece = std::max(std::ceil(T1) - 1.0, firstPiece);
  const auto cubic = [&](double T, double r[4], double z[4], double& u) {
    const double k = std::clamp(std::floor(T), firstPiece, lastPiece);
    u = T - k;
    const Point2* c = &bezier_[3 * std::size_t(k)];
    for (int i = 0; i < 4; ++i) r[i] = c[i].r, z[i] = c[i].z;
  };
  double lo = T0, hi = T1, T = T0 + s * (T1 - T0);
  for (int step = 0; step < 24 && hi > lo; ++step) {
    double r[4], z[4], u, pr, dr, pz, dz;
    cubic(T, r, z, u);
    detail::cubicWithDerivative(r, u, pr, dr);
    detail::cubicWithDerivative(z, u, pz, dz);
    const double f = ((pr - a.r) * er + (pz - a.z) * ez) / length2 - s, df = (dr * er + dz * ez) / length2;
    if (f == 0.0) break;
    (f < 0.0 ? lo : hi) = T;
    const double next = T - f / df;
    const double moved = std::abs((next > lo && next < hi ? next : 0.5 * (lo + hi)) - T);
    T = next > lo && next < hi ? next : 0.5 * (lo + hi);
    if (moved <= 0x1p-30 * (T1 - T0)) break;
  }
  double r[4], z[4], u;
  cubic(T, r, z, u);
  double tr = detail::cubicDerivative(r, u), tz = detail::cubicDerivative(z, u);
  if (tr == 0.0 && tz == 0.0) {
    // At an end of a piece with a repeated control point (Spline refuses cusps): the tangent's
    // limit there is the next distinct control point's direction, or the chord's.
    const int from = u <= 0.5 ? 0 : 1, to = u <= 0.5 ? 2 : 3;
    tr = r[to] - r[from], tz = z[to] - z[from];
    if (tr == 0.0 && tz == 0.0) tr = er, tz = ez;
  }
  const double norm = std::hypot(tr, tz);
  const Meridian n{tz / norm, -tr / norm};  // right of the direction of travel, as Ng
  // On Ng's side, as every shading normal: an arc turning back past a right angle from its chord
  // (which fromCurve bounds by its hull, not its tangent) shades with the chord's own normal there.
  if (!(n.r * ez - n.z * er > 0.0)) {
    const double chord = std::sqrt(length2);
    return {ez / chord, -er / chord};
  }
  return n;
}

Vec3 ShadingNormals::normal(std::uint32_t segment, float u, float v) const noexcept {
  const double s = std::clamp((double(v) - segmentStart_[segment]) / segmentLength_[segment], 0.0, 1.0);
  if (!curveParameter_.empty()) {
    const Meridian n = curveNormal(segment, s);
    const double phi = 2.0 * std::numbers::pi * double(u);
    return {float(n.r * std::cos(phi)), float(n.r * std::sin(phi)), float(n.z)};
  }
  const Meridian a = startNormal_[segment], b = endNormal_[segment];
  // Each end normal lies within 90 degrees of the face's (a positive blend of two face normals
  // that are not opposite), so the blend never vanishes; the guard keeps that true under rounding.
  double r = (1.0 - s) * a.r + s * b.r, z = (1.0 - s) * a.z + s * b.z;
  double norm = std::hypot(r, z);
  if (!(norm > 0.0)) r = a.r, z = a.z, norm = 1.0;
  const double phi = 2.0 * std::numbers::pi * double(u);
  return {float(r / norm * std::cos(phi)), float(r / norm * std::sin(phi)), float(z / norm)};
}

std::size_t ShadingNormals::memoryBytes() const noexcept {
  return (startNormal_.capacity() + endNormal_.capacity()) * sizeof(Meridian) +
         (segmentStart_.capacity() + segmentLength_.capacity() + curveParameter_.capacity()) * sizeof(double) +
         (vertex_.capacity() + bezier_.capacity()) * sizeof(Point2);
}

}  // namespace revolve
