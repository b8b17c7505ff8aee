// Profile validation: every rule is checked once, here, with a message naming the point, its value
// and the rule, so that nothing downstream (tree builders, kernels) has to guard against bad input.
#include <revolve/core.h>

#include "profile/points.h"
#include "profile/self_intersection.h"
#include "util/format.h"

#include <algorithm>
#include <cmath>

namespace revolve {
namespace {

using detail::formatNumber;
using detail::samePoint;

std::string describePoint(std::size_t index, Point2 p) { return detail::describePoint("profile", index, p); }

void checkPoint(std::size_t index, Point2 p) {
  detail::checkFinite("profile", index, p);
  if (p.r < 0.0) {
    throw ProfileError(ProfileError::Rule::negativeRadius, index,
                       describePoint(index, p) + ": r must be >= 0 (r is the distance from the z axis)");
  }
  detail::checkWithinRange("profile", index, p);
}

}  // namespace

// The profile's extent (largest coordinate magnitude) and every segment's length must stay within
// the range the kernel resolves (see Profile::kMinExtent, kMinSegmentFraction).
void Profile::checkScale() const {
  double extent = 0.0;
  for (const Point2& p : points_) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  const SourceIndices sourceIndex = this->sourceIndex();
  detail::checkExtent("profile", sourceIndex[0], extent);
  const double shortest = extent * kMinSegmentFraction;
  for (std::size_t k = 0; k + 1 < points_.size(); ++k) {
    const double length = std::hypot(points_[k + 1].r - points_[k].r, points_[k + 1].z - points_[k].z);
    if (length < shortest) {
      throw ProfileError(ProfileError::Rule::segmentTooShort, sourceIndex[k],
                         "the segment from " + describePoint(sourceIndex[k], points_[k]) + " to " +
                             describePoint(sourceIndex[k + 1], points_[k + 1]) + " has length " + formatNumber(length) +
                             ", below 2^-60 of the profile's extent " + formatNumber(extent) + " (" +
                             formatNumber(shortest) + "), which the kernel cannot resolve; merge the points");
    }
  }
}

Profile::Profile(std::span<const Point2> input) {
  if (input.size() > kMaxPoints) {
    throw ProfileError(ProfileError::Rule::tooManyPoints, kMaxPoints,
                       "profile has " + std::to_string(input.size()) + " points; at most " +
                           std::to_string(kMaxPoints) + " are supported (32-bit tree node indices)");
  }
  points_.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    checkPoint(i, input[i]);
    if (!points_.empty() && samePoint(points_.back(), input[i])) {
      const std::size_t repeated = sourceIndex_.empty() ? points_.size() - 1 : sourceIndex_.back();
      warnings_.push_back(
          {i, describePoint(i, input[i]) + " repeats point " + std::to_string(repeated) + " exactly; dropped"});
      // From the first dropped point on, the indices differ from the positions: stored from here.
      if (sourceIndex_.empty()) {
        sourceIndex_.resize(points_.size());
        for (std::size_t k = 0; k < points_.size(); ++k) sourceIndex_[k] = k;
      }
      continue;
    }
    points_.push_back(input[i]);
    if (!sourceIndex_.empty()) sourceIndex_.push_back(i);
  }
  if (points_.size() < 2) {
    throw ProfileError(ProfileError::Rule::tooFewPoints, input.empty() ? 0 : input.size() - 1,
                       "profile has " + std::to_string(points_.size()) +
                           " distinct point(s); at least 2 are needed to form a segment");
  }

  checkScale();

  if (auto pair = detail::findSelfIntersection(points_)) {
    const SourceIndices sourceIndex = this->sourceIndex();
    const auto describeSegment = [&](std::size_t k) {
      return "the segment from " + describePoint(sourceIndex[k], points_[k]) + " to " +
             describePoint(sourceIndex[k + 1], points_[k + 1]);
    };
    throw ProfileError(ProfileError::Rule::selfIntersecting, sourceIndex[pair->first],
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

namespace revolve {

Profile::Profile(Unchecked, std::vector<Point2> points, std::vector<double> arcLength, bool closed)
    : points_(std::move(points)), arcLength_(std::move(arcLength)), closed_(closed) {}

}  // namespace revolve
