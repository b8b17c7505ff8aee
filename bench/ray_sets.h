// The rays every method traces: the same seeded incoherent rays and the same camera rays. Their
// directions are unit vectors (rounded to float): Embree 3.13's linear cone curve kernel assumes
// them (kernels/geometry/coneline_intersector.h: its quadratic's leading coefficient leaves out
// |d|^2), and every other method takes any length.
#pragma once

#include <revolve/revolve.h>

#include <cstdint>
#include <vector>

namespace revolve::bench {

struct Box {
  double lower[3], upper[3];
};

// Origins uniform on a sphere of three bounding radii about the box's centre, each aimed at a
// uniform point of the box: rays from every direction, about three quarters of them hitting.
std::vector<Ray> incoherentRays(const Box& box, std::size_t count, std::uint64_t seed);

// A pinhole camera's primary rays, framing the box's bounding sphere from a three-quarter view
// above (30 degrees of elevation), width x height pixels through pixel centres. Laid out in tiles
// of 4 x 2 pixels, row-major within a tile, so that rays 8i .. 8i + 7 form packet i for
// rtcIntersect8; width must be a multiple of 4 and height of 2.
std::vector<Ray> cameraRays(const Box& box, int width, int height);

}  // namespace revolve::bench
