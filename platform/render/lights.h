// Point lights, the sun (a cone of directions when its apparent diameter is above zero) and the
// environment (a uniform colour or a zenith-to-horizon sky). Point lights and a sun of angle 0 are
// delta lights, reached by light sampling only. A sun with a cone is also reached by rays sampled
// from a diffuse or glossy lobe, and the path tracer weighs the two strategies against each other
// (multiple importance sampling). Neither kind is visible to camera rays or to rays leaving a
// mirror or glass: a mirror does not show them and glass casts no caustics.
#pragma once

#include "geometry/vector_math.h"
#include "io/scene_file.h"
#include "render/color.h"
#include "render/random_stream.h"

#include <vector>

namespace revolve::render {

struct LightSample {
  Vec3 wi{};         // unit, from the shaded point towards the light
  Color irradiance;  // arriving along wi on a surface facing it (I / d^2, or the sun's E)
  bool atInfinity = false;
  Vec3 position{};  // point lights: where the shadow ray ends
  float pdf = 0;    // solid-angle density of wi; 0 for a delta light (a point, a sun of angle 0)
};

// A light seen along a direction that a BSDF sample chose: its radiance and the density with which
// light sampling would have chosen that direction.
struct LightSeen {
  Color radiance;
  float pdf = 0;
};

class Lights {
 public:
  Lights(const std::vector<io::SceneLight>& lights, const io::SceneEnvironment& environment);

  std::size_t count() const { return lights_.size(); }
  LightSample sample(std::size_t light, Vec3 point, RandomStream& random) const;
  // Light `light` along unit direction `d` of a ray that escaped the scene: the sun's radiance
  // E / Omega inside its cone, else black (and always black for delta lights).
  LightSeen seen(std::size_t light, Vec3 d) const;
  // Radiance of the environment seen in direction `d` (unit).
  Color environment(Vec3 d) const;

 private:
  struct Light {
    io::LightType type;
    Vec3 position{}, towardsSun{};
    Color power;             // intensity or irradiance
    float cosHalfAngle = 1;  // the sun's cone: directions with cos >= this
    float oneMinusCos = 0;   // 1 - cos(half angle), computed without cancellation
    float solidAngle = 0;    // Omega = 2 pi (1 - cos(half angle)); 0 for delta lights
  };
  std::vector<Light> lights_;
  io::SceneEnvironment environment_;
  Color color_, zenith_, horizon_;
};

}  // namespace revolve::render
