// The queries that need no Embree: nearest hit and any hit (per instruction set, see
// isa/query_kernels.h), closest point.
#include "isa/query_kernels.h"
#include "queries.h"
#include "util/azimuth.h"

#include <algorithm>

#include <cmath>

namespace revolve {
namespace {

double boxDistance2(double rMin, double rMax, double zLow, double zHigh, double rho, double z) {
  const double dr = std::max({rMin - rho, 0.0, rho - rMax});
  const double dz = std::max({zLow - z, 0.0, z - zHigh});
  return dr * dr + dz * dz;
}

// Squared distance from (rho, z) to a node's meridian box: a lower bound for its segments.
double boxDistance2(const detail::MibitNode& node, double rho, double z) {
  return boxDistance2(node.rMin, node.rMax, node.zLow, node.zHigh, rho, z);
}

// The closest point of the profile's segments to (rho, z), best first, pruned by meridian boxes.
class ClosestSegment {
 public:
  ClosestSegment(const Shape::Impl& shape, double rho, double z) : shape_(shape), rho_(rho), z_(z) {}

  void search() {
    const auto& nodes = shape_.mibit.nodes;
    struct Entry {
      std::uint32_t node;
      double distance2;
    };
    Entry stack[64];  // depth + 1 entries at most, as in the ray search
    int top = 0;
    stack[top++] = {0, boxDistance2(nodes[0], rho_, z_)};
    while (top > 0) {
      const Entry current = stack[--top];
      if (current.distance2 > best2_) continue;
      const detail::MibitNode& node = nodes[current.node];
      if (node.kind == detail::MibitNode::Kind::interval) {
        searchInterval(shape_.mibit.intervals[node.first]);
      } else if (node.kind == detail::MibitNode::Kind::segments) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) visit(k);
      } else {
        const Entry a{node.first, boxDistance2(nodes[node.first], rho_, z_)};
        const Entry b{node.first + 1, boxDistance2(nodes[node.first + 1], rho_, z_)};
        stack[top++] = a.distance2 <= b.distance2 ? b : a;  // farther first: the nearer is popped next
        stack[top++] = a.distance2 <= b.distance2 ? a : b;
      }
    }
  }

  double distance2() const { return best2_; }
  std::uint32_t segment() const { return segment_; }
  Point2 point() const { return point_; }

 private:
  // Inside a monotone interval a run's box is spanned by its end vertices.
  void searchInterval(const detail::MonotoneInterval& interval) {
    struct Entry {
      std::uint32_t leafBegin, leafEnd;
      double distance2;
    };
    Entry stack[64];
    int top = 0;
    stack[top++] = {0, interval.leaves, 0.0};
    while (top > 0) {
      const Entry current = stack[--top];
      if (current.distance2 > best2_) continue;
      const std::uint32_t a = detail::MibitTree::leafVertex(interval, current.leafBegin);
      const std::uint32_t b = detail::MibitTree::leafVertex(interval, current.leafEnd);
      if (current.leafEnd - current.leafBegin == 1) {
        for (std::uint32_t k = a; k < b; ++k) visit(k);
        continue;
      }
      const std::uint32_t middle = (current.leafBegin + current.leafEnd) / 2;
      const std::uint32_t m = detail::MibitTree::leafVertex(interval, middle);
      const Entry left{current.leafBegin, middle, vertexBoxDistance2(a, m)};
      const Entry right{middle, current.leafEnd, vertexBoxDistance2(m, b)};
      stack[top++] = left.distance2 <= right.distance2 ? right : left;
      stack[top++] = left.distance2 <= right.distance2 ? left : right;
    }
  }

  double vertexBoxDistance2(std::uint32_t a, std::uint32_t b) const {
    const Point2 p = shape_.local[a], q = shape_.local[b];
    return boxDistance2(std::min(p.r, q.r), std::max(p.r, q.r), std::min(p.z, q.z), std::max(p.z, q.z), rho_, z_);
  }

  void visit(std::uint32_t k) {
    const Point2 a = shape_.local[k], b = shape_.local[k + 1];
    const double er = b.r - a.r, ez = b.z - a.z;
    const double along = std::clamp(((rho_ - a.r) * er + (z_ - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
    const Point2 q{a.r + along * er, a.z + along * ez};
    const double d2 = (rho_ - q.r) * (rho_ - q.r) + (z_ - q.z) * (z_ - q.z);
    if (d2 < best2_) best2_ = d2, segment_ = k, point_ = q;
  }

  const Shape::Impl& shape_;
  double rho_, z_;
  double best2_ = std::numeric_limits<double>::infinity();
  std::uint32_t segment_ = 0;
  Point2 point_{};
};

}  // namespace

std::optional<Hit> intersect(const Shape& shape, const Ray& ray, Stats* stats) noexcept {
  return detail::queryKernels().intersect(shape.impl(), ray, stats);
}

bool occluded(const Shape& shape, const Ray& ray, Stats* stats) noexcept {
  return detail::queryKernels().occluded(shape.impl(), ray, stats);
}

namespace detail {

SurfacePoint closestSurfacePoint(const Shape::Impl& impl, Vec3 p) noexcept {
  const double px = p.x, py = p.y, z = double(p.z) - impl.frame.zCentre;
  if (!(std::abs(px) < HUGE_VAL && std::abs(py) < HUGE_VAL && std::abs(z) < HUGE_VAL)) {
    return {p, std::numeric_limits<float>::quiet_NaN(), 0};  // no point is closest to a non-finite one
  }
  // Same azimuth as p; on the axis every azimuth is equally close.
  const auto [rho, cosPhi, sinPhi] = azimuthOf(px, py);
  ClosestSegment closest(impl, rho, z);
  closest.search();
  const Point2 q = closest.point();
  return {{float(q.r * cosPhi), float(q.r * sinPhi), float(q.z + impl.frame.zCentre)},
          float(std::sqrt(closest.distance2())), closest.segment()};
}

}  // namespace detail

SurfacePoint closestPoint(const Shape& shape, Vec3 p) noexcept { return detail::closestSurfacePoint(shape.impl(), p); }

}  // namespace revolve
