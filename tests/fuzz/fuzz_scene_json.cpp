// Fuzz target: a scene file as revolve-render reads it. Expected: a SceneError with a one-line
// message, or a description that keeps the reader's promises (every name resolved to a valid index,
// unit directions, values in their documented ranges, positions and every placed object within the
// coordinate limit, scales within theirs). Then Embree's ray contract, by Embree itself: the scene
// is built (objects and quads, up to 32 of each) and camera rays, shadow rays to every light and a
// bounce off every hit are traced, as the renderer makes them; Embree aborts the process on a ray
// beyond its range (also inside an instance), and the scene must have refused none. Anything else,
// or a sanitizer report, is a finding. Profile CSVs resolve against a folder that does not exist,
// so a "csv" entry must end in a clean SceneError too.
#include "fuzz_checks.h"
#include "geometry/placement.h"
#include "geometry/ray_limits.h"
#include "geometry/vector_math.h"
#include "io/scene_file.h"
#include "scene/camera.h"
#include "scene/embree_scene.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

using namespace revolve;
using app::operator+;  // common/vector_math.h
using app::operator-;
using app::operator*;

namespace {

void checkUnit(const app::Vec3d& v) {
  FUZZ_CHECK(std::abs(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1) < 1e-9);
}

void checkRange(const io::Rgb& c, double hi) {
  for (const double x : c) FUZZ_CHECK(x >= 0 && x <= hi);
}

void checkPosition(const app::Vec3d& p) {
  for (const double x : p) FUZZ_CHECK(std::abs(x) <= app::kMaxWorldCoordinate);
}

// Traces what the renderer would: a 3 x 3 grid of camera rays, and from each hit a shadow ray to
// every light and a ray back along the normal.
void traceLikeTheRenderer(const io::SceneDescription& scene) {
  const scene::EmbreeScene built(scene, {});
  const scene::Camera camera(scene.camera, 4, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) {
      const Ray ray = camera.ray(0.5f + 1.5f * float(x), 0.5f + float(y));
      FUZZ_CHECK(app::embreeAccepts(ray));
      const std::optional<scene::WorldHit> hit = built.intersect(ray);
      if (!hit) continue;
      for (const io::SceneLight& light : scene.lights) {
        Ray shadow;
        if (light.type == io::LightType::sun) {
          const Vec3 towards{-float(light.direction[0]), -float(light.direction[1]), -float(light.direction[2])};
          shadow = {built.spawn(*hit, towards), towards};
        } else {
          const Vec3 position{float(light.position[0]), float(light.position[1]), float(light.position[2])};
          shadow.origin = built.spawn(*hit, position - hit->point);
          shadow.direction = position - shadow.origin;
          shadow.tfar = 1;
        }
        built.occluded(shadow);
      }
      built.intersect(Ray{built.spawn(*hit, hit->geometricNormal), hit->geometricNormal});
    }
  }
  FUZZ_CHECK(built.refusedRays() == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::SceneDescription scene;
  try {
    scene = io::parseScene(text, "fuzz.json", "/nonexistent-fuzz-folder");
  } catch (const io::SceneError& error) {
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  FUZZ_CHECK(scene.camera.fovDegrees > 0 && scene.camera.fovDegrees < 180);
  checkPosition(scene.camera.from);
  checkPosition(scene.camera.to);
  checkUnit(scene.camera.up);
  for (const io::SceneProfile& profile : scene.profiles) {
    FUZZ_CHECK(profile.polyline().points().size() >= 2);
    // A curve traced exactly is a curved kind without a tolerance; one with a tolerance is its polyline.
    if (profile.spline) {
      FUZZ_CHECK(profile.spline->kind() != SplineKind::linear && profile.tolerance == 0);
      FUZZ_CHECK(profile.polyline().points().front().r == profile.spline->bezier().front().r);
    }
    FUZZ_CHECK(profile.tolerance >= 0);
    FUZZ_CHECK(profile.creaseDegrees >= 0 && profile.creaseDegrees <= 180);
    // The shading normals of every accepted profile are built and unit at each segment's ends.
    const ShadingNormals normals(profile.polyline(), profile.creaseDegrees);
    const std::span<const double> arc = profile.polyline().arcLength();
    for (std::uint32_t s = 0; s < profile.polyline().segmentCount() && s < 64; ++s) {
      for (const double at : {arc[s], arc[s + 1]}) {
        const Vec3 n = normals.normal(s, 0.3f, float(at / arc.back()));
        FUZZ_CHECK(std::abs(std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z) - 1) < 1e-5);
      }
    }
  }
  for (const io::SceneMaterial& material : scene.materials) {
    checkRange(material.color, 1);
    checkRange(material.tint, 1);
    FUZZ_CHECK(material.roughness >= 0 && material.roughness <= 1);
    FUZZ_CHECK(material.ior >= 1 && material.ior <= 4);
  }
  for (const io::SceneObject& object : scene.objects) {
    FUZZ_CHECK(object.profile < scene.profiles.size());
    FUZZ_CHECK(object.material < scene.materials.size());
    checkUnit(object.transform.rotateAxis);
    for (const double s : object.transform.scale) FUZZ_CHECK(s >= app::kMinScale && s <= app::kMaxScale);
    checkPosition(object.transform.translate);
    FUZZ_CHECK(app::worldReach(scene.profiles[object.profile].polyline(), app::Placement(object.transform)) <=
               app::kMaxWorldCoordinate);
  }
  for (const io::SceneQuad& quad : scene.quads) {
    FUZZ_CHECK(quad.material < scene.materials.size());
    for (const app::Vec3d& corner : quad.corners) checkPosition(corner);
  }
  for (const io::SceneLight& light : scene.lights) {
    if (light.type == io::LightType::sun) {
      checkUnit(light.direction);
      FUZZ_CHECK(light.angleDegrees >= 0 && light.angleDegrees <= 45);
    } else {
      checkPosition(light.position);
    }
  }
  if (scene.objects.size() <= 32 && scene.quads.size() <= 32) traceLikeTheRenderer(scene);
  return 0;
}
