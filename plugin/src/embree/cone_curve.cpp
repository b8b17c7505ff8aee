#include "embree/cone_curve.h"
#include <revolve/embree_baselines.h>

#include "profile/points.h"
#include "util/format.h"

#include <revolve/embree_api.h>

namespace revolve::detail {
namespace {

class Describer {
 public:
  Describer(const Profile& profile, std::string_view pointName) : profile_(profile), pointName_(pointName) {}
  std::string point(std::size_t k) const {
    const Point2 p = profile_.points()[k];
    return pointName_ + " " + std::to_string(profile_.sourceIndex()[k]) + " (r = " + formatNumber(p.r) +
           ", z = " + formatNumber(p.z) + ")";
  }
  std::string segment(std::size_t k) const { return "the segment from " + point(k) + " to " + point(k + 1); }

 private:
  const Profile& profile_;
  std::string pointName_;
};

void appendVertex(std::vector<float>& vertices, Point2 p) {
  vertices.insert(vertices.end(), {0.0f, 0.0f, float(p.z), float(p.r)});
}

}  // namespace

std::variant<ConeCurveLayout, std::string> layOutConeCurve(const Profile& profile, std::string_view pointName) {
  const std::span<const Point2> p = profile.points();
  const std::size_t n = p.size();
  const Describer describe(profile, pointName);
  // Embree's vertices are floats: a segment whose two heights round to the same float is a disc
  // to Embree, whatever it is in double.
  const auto horizontal = [&](std::size_t k) { return float(p[k].z) == float(p[k + 1].z); };
  const auto isHorizontal = [&](std::size_t k) {
    return describe.segment(k) +
           (p[k].z == p[k + 1].z ? " is horizontal"
                                 : " is horizontal in single precision (Embree's vertices are floats)") +
           ": a linear cone curve has flat discs only at its two ends, each a whole disc centred on the axis, so a "
           "horizontal segment can only be the first one starting on the axis or the last one ending there";
  };
  ConeCurveLayout layout;
  // A loop (its last point its first, off the axis) has no ends; one closing on the axis has two.
  const bool loop = samePoint(p.front(), p.back()) && p.front().r != 0.0;
  std::size_t first = 0, last = n - 1;  // the cones are the segments between points first and last
  bool anyCone = false;
  for (std::size_t k = 0; k + 1 < n; ++k) anyCone = anyCone || !horizontal(k);
  if (!anyCone)
    return "the profile is only flat discs and rings: a linear cone curve needs a segment that rises or falls";
  if (!loop) {
    if (horizontal(0)) {
      if (p[0].r != 0.0) return isHorizontal(0);
      layout.startDisc = true;
      first = 1;
    } else if (p[0].r != 0.0) {
      return "the profile ends at " + describe.point(0) +
             ", off the axis: a linear cone curve closes each end with a flat disc, which the profile does not have "
             "there";
    }
    if (horizontal(n - 2)) {
      if (p[n - 1].r != 0.0) return isHorizontal(n - 2);
      layout.endDisc = true;
      last = n - 2;
    } else if (p[n - 1].r != 0.0) {
      return "the profile ends at " + describe.point(n - 1) +
             ", off the axis: a linear cone curve closes each end with a flat disc, which the profile does not have "
             "there";
    }
  }
  for (std::size_t k = first; k < last; ++k) {
    if (horizontal(k)) return isHorizontal(k);
  }

  const std::size_t cones = last - first;
  layout.firstSegment = std::uint32_t(first);
  if (loop) {
    // Each cone's neighbours exist, and lie where Embree assumes them (the vertices before its first
    // and after its second): the loop's last cone before the first, its first cone after the last.
    appendVertex(layout.vertices, p[n - 2]);
    for (std::size_t k = 0; k < n; ++k) appendVertex(layout.vertices, p[k]);
    appendVertex(layout.vertices, p[1]);
  } else {
    for (std::size_t k = first; k <= last; ++k) appendVertex(layout.vertices, p[k]);
  }
  for (std::size_t j = 0; j < cones; ++j) {
    layout.firstVertex.push_back(std::uint32_t(loop ? j + 1 : j));
    std::uint8_t flags = 0;
    if (loop || j > 0) flags |= RTC_CURVE_FLAG_NEIGHBOR_LEFT;
    if (loop || j + 1 < cones) flags |= RTC_CURVE_FLAG_NEIGHBOR_RIGHT;
    layout.flags.push_back(flags);
    layout.rising.push_back(float(p[first + j + 1].z) > float(p[first + j].z) ? 1 : -1);
  }
  return layout;
}

}  // namespace revolve::detail
