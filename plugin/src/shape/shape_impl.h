// What a built Shape holds. Internal: the Embree glue and the queries read it directly.
#pragma once

#include <revolve/baselines.h>
#include <revolve/core.h>

#include "kajiya/strip_tree.h"
#include "kernel/curve_hits.h"
#include "kernel/local_points.h"
#include "kernel/meridian_ray.h"
#include "mibit/mibit_tree.h"
#include "mibit/wide_tree.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace revolve {
namespace detail {

// What a hit's attributes need of its segment, computed per hit from the points and arc lengths
// (surface_hit.h): a square root and five divisions a hit cost less than 40 bytes a segment kept.
struct SegmentFrame {
  double nr, nz;      // the unit normal in the meridian plane, right of the direction of travel
  double invLength2;  // 1 / |p1 - p0|^2
  double v0, dv;      // v at the segment's start, and its growth along the segment
};

// What a spline shape holds beyond its parts: behind a pointer, so that a polyline shape pays 8
// bytes for it rather than a Spline's and two vectors' headers.
struct SplineData {
  Spline spline;                   // the curve traced (Shape::spline)
  std::vector<double> arcRecords;  // the curved parts' records of v (CurvePart::arcRecord, curve/arc_record.h)
  // The index of each Bezier piece's first part, then the part count: the parts are in curve order
  // and a piece has one to five (Shape::splinePiece).
  std::vector<std::uint32_t> firstPartOfPiece;
  std::size_t memoryBytes() const noexcept;  // its heap bytes, itself included
};

struct ShapeImpl {
  ShapeImpl(Profile p, const BuildOptions& o) : profile(std::move(p)), options(o) {}

  Profile profile;                          // for a spline shape: its monotone parts' ends
  std::vector<CurvePart> parts;             // a spline shape's monotone parts, one a segment of `profile`
  std::unique_ptr<const SplineData> curve;  // a spline shape's curve and its parts' v
  bool curved() const noexcept { return !parts.empty(); }
  BuildOptions options;
  ShapeFrame frame;
  MibitTree mibit;   // always built: it also serves closest-point queries and in-plane rays
  WideTree wide;     // the SIMD layout, for the default options (BuildOptions::wideNodes)
  StripTree strips;  // built for Method::kajiya only
  Bounds bounds;
};

inline namespace REVOLVE_ISA {
// The shape's points in its local frame: its profile points (a spline's knots) shifted as they are
// read, the same doubles a stored copy would hold (a spline's parts hold them as their ends).
inline LocalPoints localPointsOf(const ShapeImpl& shape) noexcept {
  const std::span<const Point2> points = shape.profile.points();
  return {points.data(), points.size(), shape.frame.zCentre};
}
}  // namespace REVOLVE_ISA

}  // namespace detail
}  // namespace revolve
