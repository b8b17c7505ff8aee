#include "embree/tessellation.h"
#include <revolve/embree_baselines.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace revolve {
namespace detail {

TriangleMesh tessellate(const Profile& profile, std::uint32_t slices) {
  if (slices < 3) {
    throw std::invalid_argument("slices = " + std::to_string(slices) + ": a tessellation needs at least 3 slices");
  }
  const std::span<const Point2> points = profile.points();
  const std::uint64_t triangles = 2ull * profile.segmentCount() * slices;
  const std::uint64_t vertices = std::uint64_t{points.size()} * slices;
  if (triangles > 0xffffffffull || vertices > 0xffffffffull) {
    throw std::invalid_argument("slices = " + std::to_string(slices) + " with " + std::to_string(points.size()) +
                                " profile points gives " + std::to_string(triangles) +
                                " triangles; at most 2^32 - 1 fit Embree's 32-bit indices");
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(3 * vertices);
  for (const Point2& p : points) {
    for (std::uint32_t j = 0; j < slices; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / slices;
      mesh.vertices.push_back(float(p.r * std::cos(phi)));
      mesh.vertices.push_back(float(p.r * std::sin(phi)));
      mesh.vertices.push_back(float(p.z));
    }
  }
  mesh.indices.reserve(3 * triangles);
  for (std::uint32_t k = 0; k + 1 < points.size(); ++k) {
    for (std::uint32_t j = 0; j < slices; ++j) {
      const std::uint32_t j1 = (j + 1) % slices;
      const std::uint32_t a = k * slices + j, b = k * slices + j1;              // ring k
      const std::uint32_t c = (k + 1) * slices + j, d = (k + 1) * slices + j1;  // ring k + 1
      // For a profile rising at r > 0 the exact normal points outwards, and so does
      // (b - a) x (c - a) = (azimuthal) x (up).
      mesh.indices.insert(mesh.indices.end(), {a, b, c});
      mesh.indices.insert(mesh.indices.end(), {b, d, c});
    }
  }
  return mesh;
}

}  // namespace detail

double tessellationError(const Profile& profile, std::uint32_t slices) {
  double rMax = 0.0;
  for (const Point2& p : profile.points()) rMax = std::max(rMax, p.r);
  // The inscribed polygon's edge midpoints lie at r cos(pi / slices): the largest gap is at r_max.
  return rMax * (1.0 - std::cos(std::numbers::pi / slices));
}

}  // namespace revolve
