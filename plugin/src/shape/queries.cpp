// The queries that need no Embree: nearest hit and any hit (per instruction set, see
// isa/query_kernels.h), closest point.
#include "shape/queries.h"
#include "curve/part_distance.h"
#include "mibit/best_first.h"
#include "shape/query_kernels.h"
#include "util/azimuth.h"

#include <algorithm>

#include <cmath>

namespace revolve {
namespace {

// Squared distance from (rho, z) to a meridian box: a lower bound for the segments inside it.
double boxDistance2(double rMin, double rMax, double zLow, double zHigh, double rho, double z) {
  const double dr = std::max({rMin - rho, 0.0, rho - rMax});
  const double dz = std::max({zLow - z, 0.0, z - zHigh});
  return dr * dr + dz * dz;
}

// The closest point of the profile's segments to (rho, z), best first, pruned by meridian boxes.
class ClosestSegment {
 public:
  ClosestSegment(const detail::ShapeImpl& shape, double rho, double z) : shape_(shape), rho_(rho), z_(z) {}

  void search() {
    detail::searchBestFirst(
        shape_.mibit, detail::localPointsOf(shape_),
        [&](double rMin, double rMax, double zLow, double zHigh) {
          return boxDistance2(rMin, rMax, zLow, zHigh, rho_, z_);
        },
        [&](double distance2) { return distance2 > best2_; }, [&](std::uint32_t k) { visit(k); });
  }

  double distance2() const { return best2_; }
  std::uint32_t segment() const { return segment_; }
  Point2 point() const { return point_; }

 private:
  void visit(std::uint32_t k) {
    if (shape_.curved()) {
      const detail::CurvePart& part = shape_.parts[k];
      const detail::PartMinimum m = detail::partMinimum({rho_, rho_, z_, z_}, part.r, part.z);
      if (m.value * m.value < best2_) best2_ = m.value * m.value, segment_ = k, point_ = {m.r, m.z};
      return;
    }
    const detail::LocalPoints local = detail::localPointsOf(shape_);
    const Point2 a = local[k], b = local[k + 1];
    const double er = b.r - a.r, ez = b.z - a.z;
    const double along = std::clamp(((rho_ - a.r) * er + (z_ - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
    const Point2 q{a.r + along * er, a.z + along * ez};
    const double d2 = (rho_ - q.r) * (rho_ - q.r) + (z_ - q.z) * (z_ - q.z);
    if (d2 < best2_) best2_ = d2, segment_ = k, point_ = q;
  }

  const detail::ShapeImpl& shape_;
  double rho_, z_;
  double best2_ = std::numeric_limits<double>::infinity();
  std::uint32_t segment_ = 0;
  Point2 point_{};
};

}  // namespace

std::optional<Hit> intersect(const Shape& shape, const Ray& ray, Stats* stats) noexcept {
  return detail::queryKernels().intersect(detail::implOf(shape), ray, stats);
}

bool occluded(const Shape& shape, const Ray& ray, Stats* stats) noexcept {
  return detail::queryKernels().occluded(detail::implOf(shape), ray, stats);
}

std::optional<Hit> surfaceAttributes(const Shape& shape, const Ray& ray, std::uint32_t segment, float t) noexcept {
  return detail::queryKernels().attributes(detail::implOf(shape), ray, segment, t);
}

namespace detail {

SurfacePoint closestSurfacePoint(const detail::ShapeImpl& impl, Vec3 p) noexcept {
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
          float(std::sqrt(closest.distance2())),
          closest.segment()};
}

}  // namespace detail

SurfacePoint closestPoint(const Shape& shape, Vec3 p) noexcept {
  return detail::closestSurfacePoint(detail::implOf(shape), p);
}

}  // namespace revolve
