#include "render/lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::render {

using namespace app;
// Declared here, beside Color's own operators, which would otherwise hide the directive's.
using app::operator+;
using app::operator-;
using app::operator*;

namespace {
Color toColor(const io::Rgb& c) { return {float(c[0]), float(c[1]), float(c[2])}; }
Vec3 toVec3(const app::Vec3d& v) { return {float(v[0]), float(v[1]), float(v[2])}; }
}  // namespace

Lights::Lights(const std::vector<io::SceneLight>& lights, const io::SceneEnvironment& environment)
    : environment_(environment),
      color_(toColor(environment.color)),
      zenith_(toColor(environment.zenith)),
      horizon_(toColor(environment.horizon)) {
  for (const io::SceneLight& light : lights) {
    Light l{light.type, {}, {}, {}, 1, 0, 0};
    if (light.type == io::LightType::point) {
      l.position = toVec3(light.position);
      l.power = toColor(light.intensity);
    } else {
      l.towardsSun = -toVec3(light.direction);
      l.power = toColor(light.irradiance);
      // 1 - cos(h) = 2 sin^2(h / 2): in float, 1 - cos of a 0.5 degree half angle would keep 3 digits.
      const double half = light.angleDegrees * std::numbers::pi / 360.0, s = std::sin(half / 2);
      l.oneMinusCos = float(2 * s * s);
      l.cosHalfAngle = 1 - l.oneMinusCos;
      l.solidAngle = float(2 * std::numbers::pi * 2 * s * s);
    }
    lights_.push_back(l);
  }
}

LightSample Lights::sample(std::size_t index, Vec3 point, RandomStream& random) const {
  const Light& light = lights_[index];
  LightSample s;
  if (light.type == io::LightType::point) {
    const Vec3 toLight = light.position - point;
    const float distance2 = dot(toLight, toLight);
    s.wi = (1 / std::sqrt(distance2)) * toLight;
    s.irradiance = (1 / distance2) * light.power;
    s.position = light.position;
    return s;
  }
  s.atInfinity = true;
  s.irradiance = light.power;
  const auto [u1, u2] = random.next2D();
  if (light.solidAngle <= 0) {
    s.wi = light.towardsSun;
    return s;
  }
  // Uniform over the cone's solid angle Omega, radiance L = E / Omega in it: each sample carries
  // L / pdf = E. (E is the sun's irradiance on a surface facing it, for the small cones a sun has.)
  s.pdf = 1 / light.solidAngle;
  const float cosTheta = 1 - u1 * light.oneMinusCos;
  const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
  const float phi = 2 * std::numbers::pi_v<float> * u2;
  s.wi = Frame(light.towardsSun).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
  return s;
}

LightSeen Lights::seen(std::size_t index, Vec3 d) const {
  const Light& light = lights_[index];
  if (light.type != io::LightType::sun || light.solidAngle <= 0 || dot(d, light.towardsSun) < light.cosHalfAngle)
    return {};
  return {(1 / light.solidAngle) * light.power, 1 / light.solidAngle};
}

Color Lights::environment(Vec3 d) const {
  if (!environment_.sky) return color_;
  const float up = std::clamp(d.z, 0.0f, 1.0f);
  return (1 - up) * horizon_ + up * zenith_;
}

}  // namespace revolve::render
