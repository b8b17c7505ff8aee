// Picking (as the GLBot simulator's scene editor picks): the object under a pixel of the scene camera's view, found by
// one ray through the pixel's centre, the first object it hits.
#pragma once

#include "io/scene_file.h"
#include "scene/embree_scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace revolve::scene {

struct Pick {
  std::uint32_t object = 0;  // the scene's object index (quads: objects + quad index)
  std::string name;          // the object's name, "" when it has none; "quads[k]" for a quad
  Vec3 point{};              // the hit, world frame
  float distance = 0;        // from the camera, along the ray
};

// The pixel (x, y), counted from the top left of a width x height view through the scene's camera
// (0 <= x < width, 0 <= y < height). Nothing hit: nullopt.
std::optional<Pick> pick(const io::SceneDescription& description, const EmbreeScene& scene, int width, int height,
                         int x, int y);

// The name an object index goes by in messages: the object's name, or "quads[k]".
std::string objectName(const io::SceneDescription& description, std::size_t object);

}  // namespace revolve::scene
