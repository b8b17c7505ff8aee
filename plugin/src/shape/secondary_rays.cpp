// Spawning secondary rays from a hit without re-hitting the surface (after pbrt-v4's OffsetRayOrigin).
#include <revolve/core.h>

#include <cmath>
#include <limits>

namespace revolve {
namespace {

constexpr double kFloatRoundoff = 0x1p-24;  // u for float

float awayFrom(float value, double offset) {
  if (offset > 0.0) return std::nextafter(value, std::numeric_limits<float>::infinity());
  if (offset < 0.0) return std::nextafter(value, -std::numeric_limits<float>::infinity());
  return value;
}

}  // namespace

Vec3 offsetRayOrigin(const Ray& ray, float t, Vec3 normal, Vec3 newDirection) noexcept {
  const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const float d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const double n[3] = {normal.x, normal.y, normal.z};
  const double w[3] = {newDirection.x, newDirection.y, newDirection.z};
  const double nLength = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);

  // p = o + t d in float. Per axis its error against the true hit is at most
  //   u (|o| + 2 |t d|)  from the float multiply and add, plus
  //   u |t d|            from t itself, the float rounding of the kernel's double solution.
  // That solution is accurate to far below a float ulp, except near tangency, where its error (up
  // to ~2^-26 of the object's size) lies along the ray, that is along the tangent plane: it moves
  // p along the surface, not off it, and does not count towards the offset along the normal.
  // 2 u (|o| + 4 |t d|) bounds the sum with room.
  float p[3];
  double error[3];
  for (int i = 0; i < 3; ++i) {
    p[i] = o[i] + t * d[i];
    error[i] = 2.0 * kFloatRoundoff * (std::abs(double(o[i])) + 4.0 * std::abs(double(t) * d[i]));
  }
  if (!(nLength > 0.0)) return {p[0], p[1], p[2]};

  // Move off the surface along the unit normal by the error's extent in that direction, to the side
  // the new ray leaves on; then round away from p so the rounding cannot undo the offset.
  double distance = 0.0;
  for (int i = 0; i < 3; ++i) distance += std::abs(n[i] / nLength) * error[i];
  if (n[0] * w[0] + n[1] * w[1] + n[2] * w[2] < 0.0) distance = -distance;
  float result[3];
  for (int i = 0; i < 3; ++i) {
    const double offset = distance * n[i] / nLength;
    result[i] = awayFrom(static_cast<float>(p[i] + offset), offset);
  }
  return {result[0], result[1], result[2]};
}

}  // namespace revolve
