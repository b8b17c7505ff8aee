// Embree's linear cone curve as a profile polyline along the z axis: which profiles it can trace,
// and the buffers that make it (the Embree calls are in embree/glue.cpp).
//
// What Embree 3.13's cone kernel renders (kernels/geometry/coneline_intersector.h): for the
// segment from (p0, r0) to (p1, r1), the truncated cone of radius r0 + s (r1 - r0) between the planes
// through p0 and p1 perpendicular to p1 - p0 (0 < s < 1, open at both planes), in single precision;
// and, when the flags say the segment has no left (right) neighbour, a flat disc of radius r0 (r1)
// in that plane. With p0, p1 on the z axis a segment is the profile segment's truncated cone exactly;
// a horizontal profile segment (p1 = p0, in the floats Embree stores) is no cone at all, and a disc
// is always whole (centred on the axis). So a profile is one cone curve when every segment rises or falls, except that
// a first or last segment running horizontally from the axis is that end's disc; and each end is on the axis (a disc of
// radius 0 closes it), such a disc, or the profile is a loop (no ends). A point on the axis between segments is two
// cones meeting at their apex: no restriction. The kernel assumes a unit ray direction (its quadratic's leading
// coefficient leaves out |d|^2): longer or shorter directions give hits off the surface.
#pragma once

#include <revolve/embree.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace revolve::detail {

struct ConeCurveLayout {
  std::vector<float> vertices;              // x, y, z, radius per vertex; x = y = 0
  std::vector<std::uint32_t> firstVertex;   // per cone: the index of its first vertex
  std::vector<std::uint8_t> flags;          // per cone: RTC_CURVE_FLAG_NEIGHBOR_LEFT | _RIGHT
  std::vector<std::int8_t> rising;          // per cone: +1 when z grows along the profile, else -1
  std::uint32_t firstSegment = 0;           // the profile segment of cone 0 (1 when segment 0 is a disc)
  bool startDisc = false, endDisc = false;  // the profile's first / last segment is the curve's end disc
};

// The layout, or why the profile cannot be one linear cone curve (naming the points concerned).
std::variant<ConeCurveLayout, std::string> layOutConeCurve(const Profile& profile,
                                                           std::string_view pointName = "profile point");

}  // namespace revolve::detail
