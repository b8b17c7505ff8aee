#include "scene/picking.h"

#include "scene/camera.h"

namespace revolve::scene {

std::string objectName(const io::SceneDescription& description, std::size_t object) {
  if (object < description.objects.size()) return description.objects[object].name;
  return "quads[" + std::to_string(object - description.objects.size()) + "]";
}

std::optional<Pick> pick(const io::SceneDescription& description, const EmbreeScene& scene, int width, int height,
                         int x, int y) {
  const Camera camera(description.camera, width, height);
  const Ray ray = camera.ray(float(x) + 0.5f, float(y) + 0.5f);  // the pixel's centre
  const std::optional<WorldHit> hit = scene.intersect(ray);
  if (!hit) return std::nullopt;
  // The camera's directions are unit length, so t is the distance (up to the float normalisation).
  const double length =
      std::sqrt(double(ray.direction.x) * ray.direction.x + double(ray.direction.y) * ray.direction.y +
                double(ray.direction.z) * ray.direction.z);
  return Pick{hit->object, objectName(description, hit->object), hit->point, float(hit->t * length)};
}

}  // namespace revolve::scene
