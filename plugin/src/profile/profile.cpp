// Profile validation: every rule is checked once, here, with a message naming the point, its value
// and the rule, so that nothing downstream (tree builders, kernels) has to guard against bad input.
#include <revolve/revolve.h>

#include "profile/self_intersection.h"
#include "util/format.h"

#include <cmath>

namespace revolve {
namespace {

using detail::formatNumber;

std::string describePoint(std::size_t index, Point2 p) {
  return "profile point " + std::to_string(index) + " (r = " + formatNumber(p.r) + ", z = " + formatNumber(p.z) + ")";
}

void checkPoint(std::size_t index, Point2 p) {
  if (!std::isfinite(p.r) || !std::isfinite(p.z)) {
    throw ProfileError(ProfileError::Rule::nonFinite, index,
                       describePoint(index, p) + ": coordinates must be finite numbers");
  }
  if (p.r < 0.0) {
    throw ProfileError(ProfileError::Rule::negativeRadius, index,
                       describePoint(index, p) + ": r must be >= 0 (r is the distance from the z axis)");
  }
}

bool samePoint(Point2 a, Point2 b) { return a.r == b.r && a.z == b.z; }

}  // namespace

Profile::Profile(std::span<const Point2> input) {
  if (input.size() > kMaxPoints) {
    throw ProfileError(ProfileError::Rule::tooManyPoints, kMaxPoints,
                       "profile has " + std::to_string(input.size()) + " points; at most " +
                           std::to_string(kMaxPoints) + " are supported (32-bit tree node indices)");
  }
  points_.reserve(input.size());
  sourceIndex_.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    checkPoint(i, input[i]);
    if (!points_.empty() && samePoint(points_.back(), input[i])) {
      warnings_.push_back({i, describePoint(i, input[i]) + " repeats point " + std::to_string(sourceIndex_.back()) +
                                  " exactly; dropped"});
      continue;
    }
    points_.push_back(input[i]);
    sourceIndex_.push_back(i);
  }
  if (points_.size() < 2) {
    throw ProfileError(ProfileError::Rule::tooFewPoints, input.empty() ? 0 : input.size() - 1,
                       "profile has " + std::to_string(points_.size()) +
                           " distinct point(s); at least 2 are needed to form a segment");
  }

  if (auto pair = detail::findSelfIntersection(points_)) {
    const auto describeSegment = [&](std::size_t k) {
      return "the segment from " + describePoint(sourceIndex_[k], points_[k]) + " to " +
             describePoint(sourceIndex_[k + 1], points_[k + 1]);
    };
    throw ProfileError(ProfileError::Rule::selfIntersecting, sourceIndex_[pair->first],
                       describeSegment(pair->first) + " and " + describeSegment(pair->second) +
                           " intersect; a profile must not cross or touch itself");
  }

  closed_ = samePoint(points_.front(), points_.back()) || (points_.front().r == 0.0 && points_.back().r == 0.0);

  arcLength_.resize(points_.size());
  arcLength_[0] = 0.0;
  for (std::size_t i = 1; i < points_.size(); ++i) {
    arcLength_[i] = arcLength_[i - 1] + std::hypot(points_[i].r - points_[i - 1].r, points_[i].z - points_[i - 1].z);
  }
}

}  // namespace revolve
