// A pinhole camera from the scene's from / to / up / vertical field of view: the renderer's camera rays
// and picking's ray through a pixel are the same rays.
#pragma once

#include "geometry/unit_vector.h"
#include "geometry/vector_math.h"
#include "io/scene_file.h"

#include <cfloat>
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
    // The frame in float, as the reference images were made, wherever float's squared lengths are
    // normal numbers; otherwise (a view direction of 1e-30, or a step that float cannot see at
    // 1e12) in double from the scene's values, each vector scaled by its largest component first.
    const auto normal = [](Vec3 v) {
      const float squared = dot(v, v);
      return squared >= FLT_MIN && squared <= FLT_MAX;
    };
    forward_ = to - origin_;
    if (normal(forward_) && normal(cross(normalize(forward_), up))) {
      forward_ = normalize(forward_);
      right_ = normalize(cross(forward_, up));
      up_ = cross(right_, forward_);
    } else {
      using V = app::Vec3d;
      const auto crossed = [](V a, V b) {
        return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      };
      const auto toFloat = [](V v) { return Vec3{float(v[0]), float(v[1]), float(v[2])}; };
      const V forward =
          unitVector({camera.to[0] - camera.from[0], camera.to[1] - camera.from[1], camera.to[2] - camera.from[2]});
      const V right = unitVector(crossed(forward, camera.up));
      forward_ = toFloat(forward);
      right_ = toFloat(right);
      up_ = toFloat(crossed(right, forward));
    }
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
