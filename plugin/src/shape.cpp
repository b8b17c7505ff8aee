// Building a Shape: the local frame, the bounding sphere and box, and the search structures.
#include "shape_impl.h"
#include "util/rounding.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

}  // namespace

Stats& Stats::operator+=(const Stats& other) noexcept {
  rays += other.rays;
  nodesVisited += other.nodesVisited;
  shellTests += other.shellTests;
  quadratics += other.quadratics;
  return *this;
}

Shape::Shape(Profile profile, const BuildOptions& options)
    : impl_(std::make_unique<Impl>(std::move(profile), options)) {
  Impl& impl = *impl_;
  const std::span<const Point2> points = impl.profile.points();

  double zMin = points[0].z, zMax = points[0].z, rMax = 0.0;
  for (const Point2& p : points) {
    zMin = std::min(zMin, p.z);
    zMax = std::max(zMax, p.z);
    rMax = std::max(rMax, p.r);
  }
  const double zCentre = 0.5 * zMin + 0.5 * zMax;  // halves first: no overflow near the double range
  impl.local.reserve(points.size());
  double radius = 0.0;
  for (const Point2& p : points) {
    impl.local.push_back({p.r, p.z - zCentre});
    radius = std::max(radius, std::hypot(p.r, impl.local.back().z));
  }
  // The farthest surface point from the centre is a vertex (distance is convex along a segment).
  impl.frame = detail::makeShapeFrame(zCentre, radius * (1.0 + 0x1p-20));

  const std::span<const double> arc = impl.profile.arcLength();
  impl.segments.reserve(points.size() - 1);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double er = points[k + 1].r - points[k].r, ez = points[k + 1].z - points[k].z;
    const double length2 = er * er + ez * ez;  // magnitudes within 2^+-60: no overflow, no underflow
    const double length = std::sqrt(length2);
    impl.segments.push_back({ez / length, -er / length, 1.0 / length2, arc[k] / arc.back(),
                             (arc[k + 1] - arc[k]) / arc.back()});
  }

  impl.mibit = detail::buildMibitTree(impl.local, options);
  // The wide layout serves the default MIBIT only: cylinder shells, monotone split, range search and
  // the finest refinement; the paper's other variants keep their binary tree for its comparisons.
  // Its float filter needs R^2 well inside float's range (mibit/wide_search.h).
  const double R = impl.frame.sphereRadius;
  if (options.method == Method::mibit && options.wideNodes && options.shell == ShellKind::cylinder &&
      options.monotoneSplit && options.rangeSearch && options.subdivisions == 0 && R >= 0x1p-50 && R <= 0x1p50) {
    impl.wide = detail::buildWideTree(impl.local, impl.mibit.intervals, impl.frame);
  }
  if (options.method == Method::kajiya) impl.strips = detail::buildStripTree(impl.local);
  impl.bounds = paddedBounds(rMax, zMin, zMax);
}

Shape::~Shape() = default;
Shape::Shape(Shape&&) noexcept = default;
Shape& Shape::operator=(Shape&&) noexcept = default;

const Profile& Shape::profile() const noexcept { return impl_->profile; }
const BuildOptions& Shape::options() const noexcept { return impl_->options; }
Bounds Shape::bounds() const noexcept { return impl_->bounds; }

std::size_t Shape::treeNodeCount() const noexcept {
  switch (impl_->options.method) {
    case Method::mibit: {
      if (!impl_->wide.empty()) return impl_->wide.nodes.size() + impl_->wide.leaves.size();
      // Explicit nodes, plus the implicit MR nodes below each interval leaf (2 leaves - 1 each,
      // the interval's own root being its explicit leaf).
      std::size_t nodes = impl_->mibit.nodes.size();
      for (const detail::MonotoneInterval& interval : impl_->mibit.intervals) nodes += 2 * std::size_t{interval.leaves} - 2;
      return nodes;
    }
    case Method::kajiya: return impl_->strips.nodes.size();
    case Method::linear: return 0;
  }
  return 0;
}

std::size_t Shape::memoryBytes() const noexcept {
  const Impl& impl = *impl_;
  return sizeof(Impl) + impl.local.capacity() * sizeof(Point2) + impl.segments.capacity() * sizeof(detail::SegmentFrame) +
         impl.mibit.nodes.capacity() * sizeof(detail::MibitNode) +
         impl.mibit.intervals.capacity() * sizeof(detail::MonotoneInterval) +
         impl.mibit.implicitShells.capacity() * sizeof(detail::ImplicitShell) +
         impl.strips.nodes.capacity() * sizeof(detail::StripNode) + impl.wide.memoryBytes() +
         impl.profile.points().size() * (sizeof(Point2) + sizeof(double) + sizeof(std::size_t));
}

}  // namespace revolve
