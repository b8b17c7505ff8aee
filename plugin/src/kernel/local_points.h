// A shape's profile points in its local frame (z_local = z - zCentre), read through rather than
// stored: a shape shifts its profile's own points on each read, which gives the very double a stored
// copy held (one rounded subtraction either way), and saves a second copy of every point. A spline
// shape's profile holds its parts' ends as the curve has them, so their shift is each part's local end.
#pragma once

#include "util/isa.h"

#include <revolve/core.h>

#include <cstddef>

namespace revolve::detail {
inline namespace REVOLVE_ISA {  // read on the ray path: one copy an instruction set (util/isa.h)

class LocalPoints {
 public:
  LocalPoints(const Point2* points, std::size_t count, double zShift) noexcept
      : points_(points), count_(count), zShift_(zShift) {}

  Point2 operator[](std::size_t k) const noexcept { return {points_[k].r, points_[k].z - zShift_}; }
  std::size_t size() const noexcept { return count_; }

 private:
  const Point2* points_;
  std::size_t count_;
  double zShift_;
};

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
