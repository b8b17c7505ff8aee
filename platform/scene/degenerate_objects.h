// Scenes that are valid but show nothing of an object, said once per object (a warning on stderr,
// not an error), so that a user knows why an image or a scan is empty there:
//  - every point of its profile lies on the axis (r = 0): a surface of no area, which no ray hits;
//  - placed, it spans less than one float step at its position: Embree's float instance transform
//    cannot place it, so its hits are lost to rounding;
//  - the camera lies inside it (a closed profile): the view shows its inside, or nothing.
#pragma once

#include "io/scene_file.h"

#include <string>
#include <vector>

namespace revolve::scene {

// One line per object concerned ("scene.json: objects[3] \"vase\": ..."), in object order; the
// camera's position is tested only when `camera` is set (tools that look through it).
std::vector<std::string> degenerateObjectWarnings(const io::SceneDescription& scene, bool camera);

}  // namespace revolve::scene
