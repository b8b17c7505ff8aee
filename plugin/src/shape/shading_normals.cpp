// Smooth shading normals from per-vertex normals along the profile (see revolve.h, ShadingNormals).
#include <revolve/core.h>

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
    throw std::invalid_argument("crease angle " + std::to_string(creaseDegrees) +
                                " degrees: must lie in [0, 180]");
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
    if (p.back().r == 0.0) return Side{Direction{direction[segments - 1].r, -direction[segments - 1].z}, length[segments - 1]};
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
    if (vertex > 0) endNormal_[vertex - 1] = vertexNormal;
    else if (loop) endNormal_[segments - 1] = vertexNormal;
    if (vertex < segments) startNormal_[vertex] = vertexNormal;
    else if (loop) startNormal_[0] = vertexNormal;
  }
}

Vec3 ShadingNormals::normal(std::uint32_t segment, float u, float v) const noexcept {
  const double s = std::clamp((double(v) - segmentStart_[segment]) / segmentLength_[segment], 0.0, 1.0);
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
         (segmentStart_.capacity() + segmentLength_.capacity()) * sizeof(double);
}

}  // namespace revolve
