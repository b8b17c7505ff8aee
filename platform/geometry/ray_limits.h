// The ranges the tools and Python trace within, and why: Embree 3's ray contract, and the world
// coordinates and object scales that keep every ray inside it, in the world and inside every
// instance. The readers refuse what lies outside (naming the key path or line and the limit), the
// placement rule (geometry/placement.h) holds objects' scales to it, and rays are checked against
// the contract before they reach rtcIntersect1 / rtcOccluded1: the tools' by embreeAccepts, a
// Python user's, which may come from anywhere, by queryRayAccepted (the tighter ranges within which
// a ray stays inside the contract through any accepted placement).
#pragma once

#include <revolve/revolve.h>

#include <cmath>
#include <string>

namespace revolve::app {

// Embree's RayK::valid(), asserted in Debian's build (a failure aborts the process): every
// component of org and dir at most FLT_LARGE = 1.844e18 in magnitude (so finite), tnear and tfar
// not NaN. It is asserted again inside an instance, on the ray after the inverse transform.
inline constexpr float kEmbreeLargest = 1.844e18f;

inline bool embreeAccepts(const Ray& ray) noexcept {
  const auto within = [](float x) { return std::abs(x) <= kEmbreeLargest; };  // false for NaN
  return within(ray.origin.x) && within(ray.origin.y) && within(ray.origin.z) && within(ray.direction.x) &&
         within(ray.direction.y) && within(ray.direction.z) && !std::isnan(ray.tnear) && !std::isnan(ray.tfar);
}

// Positions given in scene, sensor and poses files (the camera, lights, quad corners, translations,
// the reach of every placed object, robot poses, sensor mountings) lie within +-2^40 (about 1.1e12)
// scene units. Every ray the tools trace then starts within kMaxRayOrigin = 4 * 2^40: at a given
// position, off a hit on the scene's geometry (within 1.25 * 2^40, see kMaxScaleRatio), or at a
// sensor mounted on a robot pose (|p + Rz m| <= (1 + sqrt 2) 2^40); its direction is unit or, to a
// point light, within 2.25 * 2^40.
inline constexpr double kMaxWorldCoordinate = 0x1p40;
inline constexpr double kMaxRayOrigin = 4 * kMaxWorldCoordinate;
// The coordinate limit as messages state it: "<value> is beyond the coordinate limit: " + this.
inline constexpr const char* kCoordinateLimitRule = "positions lie within +-2^40 (1.1e12)";

// The scale factors of a placed object lie in [2^-16, 2^40]. Embree maps a world ray into the
// object by L^-1 = S^-1 R^T, whose rows have 1-norm at most sqrt 3 / s: from an origin within
// kMaxRayOrigin of an object translated by at most 2^40 (|o - T| <= 5 * 2^40), the object-space
// origin stays within sqrt 3 * 2^16 * 5 * 2^40 = 2^59.1 and a direction within sqrt 3 * 2^16 *
// 2.25 * 2^40 = 2^58, both under half of FLT_LARGE (2^60.7), the other half left for Embree's float
// rounding of the transform. Above, 2^40 keeps the float matrix and its determinant (Embree inverts
// it in float) finite.
inline constexpr double kMinScale = 0x1p-16;
inline constexpr double kMaxScale = 0x1p40;

// An object's scale factors lie within a factor 2^16 of each other. A secondary ray leaving a hit
// on an instance starts off the surface by the error of Embree's float transform, gamma(4) |L|
// |L^-1| (|o| + |T| + |t d|) (scene/embree_scene.h); with |L| |L^-1| <= 3 * 2^16 and that sum at
// most 4.5 * 2^40 (an origin within 1.25 * 2^40, a translation, the way to a hit on geometry within
// 2^40), the offset stays under 0.21 * 2^40, so rays leaving hits start within 1.25 * 2^40 again.
inline constexpr double kMaxScaleRatio = 0x1p16;
static_assert(1.7320508075688772 / kMinScale * (kMaxRayOrigin + kMaxWorldCoordinate) <= 0.5 * double(kEmbreeLargest));
static_assert(kMaxScale * kMaxScale * kMaxScale * 6 <
              3.4e38);  // a float determinant of 3 x 3 entries below 2^40 stays finite
static_assert(4 * 0x1p-24 / (1 - 4 * 0x1p-24) * 3 * kMaxScaleRatio * 4.5 <= 0.25);

// Rays and points given to a query from outside (Python's RaycastingScene), checked one by one
// before any reaches Embree: origins and points within kMaxRayOrigin per coordinate; directions
// within kMaxWorldCoordinate per component, finite and not zero. Above, such rays are shown to stay
// within Embree's range through any placement the rule accepts.
inline bool queryPointAccepted(const float* p) noexcept {
  const auto within = [](float x) { return std::abs(x) <= float(kMaxRayOrigin); };  // false for NaN
  return within(p[0]) && within(p[1]) && within(p[2]);
}
// r: ox, oy, oz, dx, dy, dz.
inline bool queryRayAccepted(const float* r) noexcept {
  const auto within = [](float x) { return std::abs(x) <= float(kMaxWorldCoordinate); };
  return queryPointAccepted(r) && within(r[3]) && within(r[4]) && within(r[5]) && (r[3] != 0 || r[4] != 0 || r[5] != 0);
}
// Why a point or ray is refused (the component, its value and the rule), for the message; empty
// when accepted.
std::string queryPointFault(const float* p);
std::string queryRayFault(const float* r);

}  // namespace revolve::app
