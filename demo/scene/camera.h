// A pinhole camera from the scene's from / to / up / vertical field of view: the renderer's camera rays
// and picking's ray through a pixel are the same rays.
#pragma once

#include "common/vector_math.h"
#include "io/scene_file.h"

#include <cmath>
#include <numbers>

namespace revolve::scene {

class Camera {
 public:
  Camera(const io::SceneCamera& camera, int width, int height) : width_(width), height_(height) {
    using namespace app;
    origin_ = {float(camera.from[0]), float(camera.from[1]), float(camera.from[2])};
    const Vec3 to{float(camera.to[0]), float(camera.to[1]), float(camera.to[2])};
    const Vec3 up{float(camera.up[0]), float(camera.up[1]), float(camera.up[2])};
    forward_ = normalize(to - origin_);
    right_ = normalize(cross(forward_, up));
    up_ = cross(right_, forward_);
    const float halfHeight = float(std::tan(camera.fovDegrees * std::numbers::pi / 360.0));
    right_ = (halfHeight * float(width) / float(height)) * right_;
    up_ = halfHeight * up_;
  }
  // The ray through image position (x, y) in pixels, (0, 0) at the top left corner.
  Ray ray(float x, float y) const {
    using namespace app;
    const float sx = 2.0f * x / float(width_) - 1.0f, sy = 1.0f - 2.0f * y / float(height_);
    return {origin_, normalize(forward_ + sx * right_ + sy * up_)};
  }

 private:
  int width_, height_;
  Vec3 origin_{}, forward_{}, right_{}, up_{};
};

}  // namespace revolve::scene
