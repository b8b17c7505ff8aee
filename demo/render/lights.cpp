#include "lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::render {

using namespace app;

namespace {
Color toColor(const io::Rgb& c) { return {float(c[0]), float(c[1]), float(c[2])}; }
Vec3 toVec3(const io::Vec3d& v) { return {float(v[0]), float(v[1]), float(v[2])}; }
}  // namespace

Lights::Lights(const std::vector<io::SceneLight>& lights, const io::SceneEnvironment& environment)
    : environment_(environment),
      color_(toColor(environment.color)),
      zenith_(toColor(environment.zenith)),
      horizon_(toColor(environment.horizon)) {
  for (const io::SceneLight& light : lights) {
    Light l{light.type, {}, {}, {}, 1};
    if (light.type == io::LightType::point) {
      l.position = toVec3(light.position);
      l.power = toColor(light.intensity);
    } else {
      l.towardsSun = -toVec3(light.direction);
      l.power = toColor(light.irradiance);
      l.cosHalfAngle = float(std::cos(light.angleDegrees * std::numbers::pi / 360.0));
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
  const float u1 = random.next(), u2 = random.next();
  if (light.cosHalfAngle >= 1) {
    s.wi = light.towardsSun;
    return s;
  }
  // Uniform over the cone's solid angle; the irradiance E is spread evenly over it (E = L Omega for
  // the small cones a sun has), so each direction carries E.
  const float cosTheta = 1 - u1 * (1 - light.cosHalfAngle);
  const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
  const float phi = 2 * std::numbers::pi_v<float> * u2;
  s.wi = Frame(light.towardsSun).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
  return s;
}

Color Lights::environment(Vec3 d) const {
  if (!environment_.sky) return color_;
  const float up = std::clamp(d.z, 0.0f, 1.0f);
  return (1 - up) * horizon_ + up * zenith_;
}

}  // namespace revolve::render
