// Point lights, the sun (a cone of directions when its apparent diameter is above zero) and the
// environment (a uniform colour or a zenith-to-horizon sky). Point lights and the sun are reached
// by light sampling only: neither is visible to camera or reflected rays, so a mirror does not show
// them and glass casts no caustics (the scenes' "model only what a scene needs").
#pragma once

#include "color.h"
#include "common/vector_math.h"
#include "io/scene_file.h"
#include "random_stream.h"

#include <vector>

namespace revolve::render {

struct LightSample {
  Vec3 wi{};            // unit, from the shaded point towards the light
  Color irradiance;     // arriving along wi on a surface facing it (I / d^2, or the sun's E)
  bool atInfinity = false;
  Vec3 position{};      // point lights: where the shadow ray ends
};

class Lights {
 public:
  Lights(const std::vector<io::SceneLight>& lights, const io::SceneEnvironment& environment);

  std::size_t count() const { return lights_.size(); }
  LightSample sample(std::size_t light, Vec3 point, RandomStream& random) const;
  // Radiance of the environment seen in direction `d` (unit).
  Color environment(Vec3 d) const;

 private:
  struct Light {
    io::LightType type;
    Vec3 position{}, towardsSun{};
    Color power;            // intensity or irradiance
    float cosHalfAngle = 1;  // the sun's cone
  };
  std::vector<Light> lights_;
  io::SceneEnvironment environment_;
  Color color_, zenith_, horizon_;
};

}  // namespace revolve::render
