// Building a Shape: the local frame, the bounding sphere and box, and the search structures.
#include "curve/arc_length.h"
#include "curve/arc_table.h"
#include "curve/monotone_parts.h"
#include "shape/shape_impl.h"
#include "util/rounding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace revolve {
namespace {

// Embree tests user geometry against its box in single precision and never with its robust
// variant; the error grows with the ray's coordinates (about a float ulp of the origin's distance),
// so a surface that touches its box (a cap on the top face, the widest circle on the side faces)
// loses hits there to a tight box, 10-23% of rays aimed at such edges when measured. Padding by
// 2^-12 of the box's largest coordinate kept every such hit for cameras up to 10^5 object sizes away
// (EmbreeBoundsTest checks 10^4), at the cost of a box 0.02% larger.
Bounds paddedBounds(double rMax, double zMin, double zMax) {
  const double magnitude = std::max({rMax, std::abs(zMin), std::abs(zMax)});
  const double pad = std::ldexp(magnitude, -12);
  const float r = detail::floatAbove(rMax + pad);
  return {{-r, -r, detail::floatBelow(zMin - pad)}, {r, r, detail::floatAbove(zMax + pad)}};
}

// The search structures over the local points (a polyline's, or a spline's monotone parts' ends).
void buildSearch(detail::ShapeImpl& impl, std::span<const Point2> local, const BuildOptions& options,
                 std::span<const Point2> innerControls) {
  impl.mibit = detail::buildMibitTree(local, options, innerControls);
  // The wide layout serves the default MIBIT only: cylinder shells, monotone split, range search and
  // the finest refinement; the paper's other variants keep their binary tree for its comparisons.
  // Its float filter needs R^2 well inside float's range (mibit/wide_search.h).
  const double R = impl.frame.sphereRadius;
  if (options.method == Method::mibit && options.wideNodes && options.shell == ShellKind::cylinder &&
      options.monotoneSplit && options.rangeSearch && options.subdivisions == 0 && R >= 0x1p-50 && R <= 0x1p50) {
    impl.wide = detail::buildWideTree(local, impl.mibit.intervals, impl.frame);
  }
  if (options.method == Method::kajiya) impl.strips = detail::buildStripTree(local);
  // Each array at its size: the trees grow theirs level by level, and a scene of a million shapes
  // pays for every element of slack.
  impl.mibit.nodes.shrink_to_fit();
  impl.mibit.cones.shrink_to_fit();
  impl.mibit.intervals.shrink_to_fit();
  impl.mibit.implicitShells.shrink_to_fit();
  impl.strips.nodes.shrink_to_fit();
}

// A part whose inner control points lie within a few roundings of its chord (2^-50 of the
// curve's extent) is that chord, to the coordinates' precision; a horizontal one is an annulus.
bool isStraight(const detail::MonotonePart& part, double extent) {
  const Point2 a = part.c[0], b = part.c[3];
  if (a.z == b.z) return true;  // monotone in z with equal ends: horizontal throughout
  const double er = b.r - a.r, ez = b.z - a.z, length = std::hypot(er, ez);
  for (int i = 1; i < 3; ++i) {
    const double across = std::abs((part.c[i].r - a.r) * ez - (part.c[i].z - a.z) * er) / length;
    if (!(across <= 0x1p-50 * extent)) return false;
  }
  return true;
}

}  // namespace

Stats& Stats::operator+=(const Stats& other) noexcept {
  rays += other.rays;
  nodesVisited += other.nodesVisited;
  shellTests += other.shellTests;
  quadratics += other.quadratics;
  return *this;
}

Shape::Shape(Profile profile) : Shape(std::move(profile), BuildOptions{}) {}

Shape::Shape(Profile profile, const BuildOptions& options)
    : impl_(std::make_unique<detail::ShapeImpl>(std::move(profile), options)) {
  detail::ShapeImpl& impl = *impl_;
  const std::span<const Point2> points = impl.profile.points();

  double zMin = points[0].z, zMax = points[0].z, rMax = 0.0;
  for (const Point2& p : points) {
    zMin = std::min(zMin, p.z);
    zMax = std::max(zMax, p.z);
    rMax = std::max(rMax, p.r);
  }
  const double zCentre = 0.5 * zMin + 0.5 * zMax;  // halves first: no overflow near the double range
  // The builders' copy of the points in the local frame; the shape reads its profile's through
  // localPointsOf, which gives the same doubles.
  std::vector<Point2> local;
  local.reserve(points.size());
  double radius = 0.0;
  for (const Point2& p : points) {
    local.push_back({p.r, p.z - zCentre});
    radius = std::max(radius, std::hypot(p.r, local.back().z));
  }
  // The farthest surface point from the centre is a vertex (distance is convex along a segment).
  impl.frame = detail::makeShapeFrame(zCentre, radius * (1.0 + 0x1p-20));

  buildSearch(impl, local, options, {});
  impl.bounds = paddedBounds(rMax, zMin, zMax);
}

Shape::Shape(Spline curve) : Shape(std::move(curve), BuildOptions{}) {}

Shape::Shape(Spline curve, const BuildOptions& options) {
  if (curve.kind() == SplineKind::linear) {
    *this = Shape(Profile(curve.points()), options);
    return;
  }
  if (options.method == Method::kajiya) {
    throw std::invalid_argument(
        "Kajiya's strip tree bounds polylines only: a curve traced exactly needs the MIBIT search or the linear scan");
  }
  double extent = 0.0;
  for (const Point2& p : curve.bezier()) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  const std::vector<detail::MonotonePart> parts = detail::monotoneParts(curve.bezier(), extent);

  // Each monotone part lies in the box of its ends: the knots bound the curve.
  double zMin = parts[0].c[0].z, zMax = zMin, rMax = 0.0;
  for (const detail::MonotonePart& part : parts) {
    for (const Point2& p : {part.c[0], part.c[3]}) {
      zMin = std::min(zMin, p.z);
      zMax = std::max(zMax, p.z);
      rMax = std::max(rMax, p.r);
    }
  }
  const double zCentre = 0.5 * zMin + 0.5 * zMax;
  // The bounding sphere holds every control point (the curve lies in their hull), so the kernel's
  // rounding bounds, scaled by its radius, hold for the control values the leaves compute with.
  double radius = 0.0;
  std::vector<detail::CurvePart> local;
  // The knots as the parts have them (global): the profile's points, whose shift as read
  // (localPointsOf: z - zCentre) is the very double each part's local end holds.
  std::vector<Point2> knots{parts[0].c[0]}, inner;
  std::vector<double> arc{0.0};
  auto data = std::make_unique<detail::SplineData>(detail::SplineData{std::move(curve), {}, {}});
  std::vector<double>& records = data->arcRecords;
  local.reserve(parts.size());
  knots.reserve(parts.size() + 1);
  inner.reserve(2 * parts.size());
  arc.reserve(parts.size() + 1);
  for (const detail::MonotonePart& part : parts) {
    detail::CurvePart c{};
    for (int i = 0; i < 4; ++i) {
      c.r[i] = part.c[i].r;
      c.z[i] = part.c[i].z - zCentre;
      radius = std::max(radius, std::hypot(c.r[i], c.z[i]));
    }
    c.straight = isStraight(part, extent);
    if (data->firstPartOfPiece.size() == part.piece) data->firstPartOfPiece.push_back(std::uint32_t(local.size()));
    // Its length; a curved part's table of arc length without its ends, its record of v
    // (curve/arc_record.h). A straight part's length is one five-point rule: its speed is its
    // chord's length times a quadratic (to its controls' 2^-50 of the extent off the chord), which
    // the rule integrates exactly up to rounding.
    if (c.straight) {
      arc.push_back(arc.back() + detail::arcLengthBetween(c.r, c.z, 0.0, 1.0));
    } else {
      const detail::ArcTable table = detail::arcTableOf(c.r, c.z);
      c.arcRecord = std::uint32_t(records.size());
      c.arcSteps = std::uint16_t(table.steps);
      records.insert(records.end(), table.cumulative.begin() + 1, table.cumulative.end() - 1);
      arc.push_back(arc.back() + table.length);
    }
    knots.push_back(part.c[3]);
    inner.push_back({c.r[1], c.z[1]});
    inner.push_back({c.r[2], c.z[2]});
    local.push_back(c);
  }
  data->firstPartOfPiece.push_back(std::uint32_t(local.size()));
  data->firstPartOfPiece.shrink_to_fit();  // grown by insertion
  records.shrink_to_fit();

  impl_ = std::make_unique<detail::ShapeImpl>(
      Profile(Profile::Unchecked{}, std::move(knots), std::move(arc), data->spline.closed()), options);
  detail::ShapeImpl& impl = *impl_;
  impl.parts = std::move(local);
  impl.curve = std::move(data);
  impl.frame = detail::makeShapeFrame(zCentre, radius * (1.0 + 0x1p-20));
  // The builders' copy of the knots in the local frame, the doubles localPointsOf gives.
  std::vector<Point2> localKnots;
  localKnots.reserve(impl.parts.size() + 1);
  for (const Point2& p : impl.profile.points()) localKnots.push_back({p.r, p.z - zCentre});
  buildSearch(impl, localKnots, options, inner);
  impl.bounds = paddedBounds(rMax, zMin, zMax);
}

Shape::~Shape() = default;
Shape::Shape(Shape&&) noexcept = default;
Shape& Shape::operator=(Shape&&) noexcept = default;

const Profile& Shape::profile() const noexcept { return impl_->profile; }
const Spline* Shape::spline() const noexcept { return impl_->curve ? &impl_->curve->spline : nullptr; }
std::uint32_t Shape::splinePiece(std::uint32_t segment) const noexcept {
  // The last piece whose first part is at or before the segment.
  const std::vector<std::uint32_t>& first = impl_->curve->firstPartOfPiece;
  return std::uint32_t(std::upper_bound(first.begin(), first.end(), segment) - first.begin() - 1);
}
const BuildOptions& Shape::options() const noexcept { return impl_->options; }

bool Shape::closed() const noexcept { return impl_->curve ? impl_->curve->spline.closed() : impl_->profile.closed(); }
Bounds Shape::bounds() const noexcept { return impl_->bounds; }

std::size_t Shape::treeNodeCount() const noexcept {
  switch (impl_->options.method) {
    case Method::mibit: {
      if (!impl_->wide.empty()) {
        // A scanned profile is one node holding every segment (as Stats::nodesVisited counts it).
        if (impl_->wide.flatSegments > 0) return 1;
        return impl_->wide.nodes().size() + impl_->wide.leaves().size();
      }
      // Explicit nodes, plus the implicit MR nodes below each interval leaf (2 leaves - 1 each,
      // the interval's own root being its explicit leaf).
      std::size_t nodes = impl_->mibit.nodes.size();
      for (const detail::MonotoneInterval& interval : impl_->mibit.intervals)
        nodes += 2 * std::size_t{interval.leaves} - 2;
      return nodes;
    }
    case Method::kajiya:
      return impl_->strips.nodes.size();
    case Method::linear:
      return 0;
  }
  return 0;
}

std::size_t Shape::memoryBytes() const noexcept {
  const detail::ShapeImpl& impl = *impl_;
  return sizeof(detail::ShapeImpl) + impl.mibit.nodes.capacity() * sizeof(detail::MibitNode) +
         impl.mibit.cones.capacity() * sizeof(detail::NodeCone) +
         impl.mibit.intervals.capacity() * sizeof(detail::MonotoneInterval) +
         impl.mibit.implicitShells.capacity() * sizeof(detail::ImplicitShell) +
         impl.strips.nodes.capacity() * sizeof(detail::StripNode) + impl.wide.memoryBytes() +
         impl.parts.capacity() * sizeof(detail::CurvePart) + (impl.curve ? impl.curve->memoryBytes() : 0) +
         impl.profile.points().size() * (sizeof(Point2) + sizeof(double)) +
         (impl.profile.sourceIndex().identity() ? 0 : impl.profile.points().size() * sizeof(std::size_t));
}

std::size_t detail::SplineData::memoryBytes() const noexcept {
  return sizeof(SplineData) + spline.memoryBytes() + arcRecords.capacity() * sizeof(double) +
         firstPartOfPiece.capacity() * sizeof(std::uint32_t);
}

const detail::ShapeImpl& detail::implOf(const Shape& shape) noexcept { return *shape.impl_; }

}  // namespace revolve
