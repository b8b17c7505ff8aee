#include "profile/points.h"

#include "util/format.h"

#include <cmath>

namespace revolve::detail {

std::string describePoint(const char* what, std::size_t index, Point2 p) {
  return std::string(what) + " point " + std::to_string(index) + " (r = " + formatNumber(p.r) +
         ", z = " + formatNumber(p.z) + ")";
}

void checkFinite(const char* what, std::size_t index, Point2 p) {
  if (!std::isfinite(p.r) || !std::isfinite(p.z)) {
    throw ProfileError(ProfileError::Rule::nonFinite, index,
                       describePoint(what, index, p) + ": coordinates must be finite numbers");
  }
}

void checkWithinRange(const char* what, std::size_t index, Point2 p) {
  if (std::abs(p.r) > Profile::kMaxCoordinate || std::abs(p.z) > Profile::kMaxCoordinate) {
    throw ProfileError(ProfileError::Rule::outOfRange, index,
                       describePoint(what, index, p) + ": coordinates must be within +-2^60 (" +
                           formatNumber(Profile::kMaxCoordinate) +
                           "); Embree's single-precision bounds and the kernel's products support no more");
  }
}

void checkExtent(const char* what, std::size_t index, double extent) {
  if (extent < Profile::kMinExtent) {
    throw ProfileError(ProfileError::Rule::outOfRange, index,
                       std::string(what) + " extent " + formatNumber(extent) +
                           " (its largest coordinate) is below 2^-60 (" + formatNumber(Profile::kMinExtent) +
                           "), too small for the kernel's products");
  }
}

}  // namespace revolve::detail
