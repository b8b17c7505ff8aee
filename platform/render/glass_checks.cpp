#include "render/glass_checks.h"

namespace revolve::render {

namespace {

// Twice the signed area the closed profile encloses in the (r, z) half-plane, the closing side
// included: positive when it runs counter-clockwise, so that its normals (to the right of the
// direction of travel) point out of the solid.
double twiceSignedArea(const Profile& profile) {
  const auto points = profile.points();
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point2& a = points[i];
    const Point2& b = points[(i + 1) % points.size()];
    sum += a.r * b.z - b.r * a.z;
  }
  return sum;
}

}  // namespace

std::vector<std::string> glassWarnings(const io::SceneDescription& scene) {
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const io::SceneObject& object = scene.objects[i];
    if (scene.materials[object.material].type != io::MaterialType::glass) continue;
    const io::SceneProfile& profile = scene.profiles[object.profile];
    const std::string where = scene.file + ": objects[" + std::to_string(i) + "]" +
                              (object.name.empty() ? "" : " (\"" + object.name + "\")") + ": glass on profile \"" +
                              profile.name + "\"";
    if (!profile.polyline().closed()) {
      warnings.push_back(where +
                         " is open (its ends neither meet nor both lie on the axis): it renders as a sheet with no "
                         "inside; close it to make a solid");
    } else if (twiceSignedArea(profile.polyline()) < 0) {
      warnings.push_back(where +
                         " runs clockwise in (r, z): its normals point into the glass, which renders as a bubble of "
                         "air; list it from the axis at the bottom, up the outside");
    }
  }
  return warnings;
}

}  // namespace revolve::render
