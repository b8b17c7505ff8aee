// What a built Shape holds. Internal: the Embree glue and the queries read it directly.
#pragma once

#include <revolve/baselines.h>
#include <revolve/core.h>

#include "kajiya/strip_tree.h"
#include "kernel/curve_hits.h"
#include "kernel/meridian_ray.h"
#include "mibit/mibit_tree.h"
#include "mibit/wide_tree.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace revolve {
namespace detail {

// What a hit's attributes need of its segment, computed once: no square root or division is left
// for the hit itself but the azimuth's.
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
  std::vector<Point2> local;           // profile points in the local frame (z - frame.zCentre)
  std::vector<SegmentFrame> segments;  // one per segment
  MibitTree mibit;                     // always built: it also serves closest-point queries and in-plane rays
  WideTree wide;                       // the SIMD layout, for the default options (BuildOptions::wideNodes)
  StripTree strips;                    // built for Method::kajiya only
  Bounds bounds;
};

}  // namespace detail
}  // namespace revolve
