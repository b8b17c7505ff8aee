// The tessellated baseline: the profile swept in `slices` steps as a triangle mesh.
#pragma once

#include <revolve/core.h>

#include <cstdint>
#include <vector>

namespace revolve::detail {

struct TriangleMesh {
  std::vector<float> vertices;         // x, y, z per vertex
  std::vector<std::uint32_t> indices;  // three per triangle
};

// Ring i holds point i of the profile at `slices` azimuths 2 pi j / slices, on the exact circle;
// the quad between rings k, k + 1 and azimuths j, j + 1 (a planar trapezoid) becomes two triangles
// numbered 2 (k slices + j) and 2 (k slices + j) + 1, so triangle / (2 slices) is the segment.
// Wound so that Embree's Ng = (v1 - v0) x (v2 - v0) agrees with the exact surface's normal.
// Throws std::invalid_argument for slices < 3 or more triangles than 32-bit indices hold.
TriangleMesh tessellate(const Profile& profile, std::uint32_t slices);

}  // namespace revolve::detail
