// Embree's own primitives, built from a profile for comparison with revolve's exact surface: a
// tessellated triangle mesh and Embree's linear cone curve (what an Embree user would try first).
// revolve-bench and revolve-render's --geometry mesh / embree-cone use them; an application tracing
// surfaces of revolution needs neither.
#pragma once

#include <revolve/baselines.h>
#include <revolve/embree.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace revolve {

// A triangle mesh of the profile swept in `slices` steps (2 * segments * slices triangles, vertices
// on the exact circles), committed and ready to attach: the tessellated baseline. Throws
// std::invalid_argument when slices < 3 or the triangle count exceeds 32-bit indices.
[[nodiscard]] RTCGeometry newTessellatedGeometry(RTCDevice device, const Profile& profile, std::uint32_t slices);
// A bound on the Hausdorff distance between that mesh and the exact surface: r_max (1 - cos(pi /
// slices)), the gap between a circle and its inscribed polygon at the largest radius; exact when
// that radius lies on a vertical segment (elsewhere the gap normal to the surface is smaller).
[[nodiscard]] double tessellationError(const Profile& profile, std::uint32_t slices);

// Embree's own linear cone curve (RTC_GEOMETRY_TYPE_CONE_LINEAR_CURVE) with its centre line on the z
// axis: the baseline an Embree user tries first. Each profile segment that rises or falls is one
// truncated cone, traced by Embree's single-precision kernel; a first or last segment running
// horizontally from the axis is the curve's flat end disc (RTC_CURVE_FLAG_NEIGHBOR_LEFT / _RIGHT
// are set everywhere else). It cannot trace a horizontal segment anywhere else (a rim, a step, a
// flat shoulder), nor an open end off the axis (Embree would close it with a disc); a loop and a
// point on the axis between segments are fine. Embree's Ng points away from the axis on the cones
// and away from its cone on a disc, whichever side the solid lies on.
//
// Why `profile` cannot be traced as one linear cone curve, naming the points concerned ("profile
// point 3 (r = .., z = ..)"); nothing when it can. `pointName` is what the reason calls a point:
// "polyline point" suits a profile made by Profile::fromCurve, whose points are not the curve's.
[[nodiscard]] std::optional<std::string> coneCurveLimitation(const Profile& profile,
                                                             std::string_view pointName = "profile point");

class ConeCurveGeometry {
 public:
  // Builds and commits the curve (buffers of 16 bytes a point); attach handle() to a scene. Throws
  // std::invalid_argument with coneCurveLimitation's reason when the profile cannot be one curve.
  ConeCurveGeometry(RTCDevice device, const Profile& profile);
  ~ConeCurveGeometry();
  ConeCurveGeometry(const ConeCurveGeometry&) = delete;
  ConeCurveGeometry& operator=(const ConeCurveGeometry&) = delete;

  [[nodiscard]] RTCGeometry handle() const noexcept { return geometry_; }
  std::uint32_t coneCount() const noexcept { return std::uint32_t(rising_.size()); }
  // The profile segment (as Conventions number them) of a hit with Embree's primID, u and Ng: a hit
  // on an end disc (u exactly 0 or 1, Ng along the axis) is the horizontal segment it stands for.
  [[nodiscard]] std::uint32_t profileSegment(unsigned primID, float u, Vec3 ng) const noexcept;
  // +1 or -1: Embree's Ng times this points to revolve's side (Conventions) for hits on cone primID.
  float normalSign(unsigned primID) const noexcept { return float(rising_[primID]); }

 private:
  RTCGeometry geometry_ = nullptr;
  std::vector<std::int8_t> rising_;
  std::uint32_t firstSegment_ = 0;
  bool startDisc_ = false, endDisc_ = false;
};

}  // namespace revolve
