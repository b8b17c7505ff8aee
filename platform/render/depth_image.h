// A depth image as ROS's depth cameras give one (sensor_msgs/Image, 32FC1): per pixel the distance
// along the camera's optical axis (z in its optical frame, REP 118) to the nearest surface seen
// through the pixel's centre, in the scene's units; +inf where the ray meets nothing. The rays
// are the renderer's own camera rays (scene/camera.h), one a pixel, traced exactly.
#pragma once

#include "io/scene_file.h"
#include "scene/embree_scene.h"

#include <vector>

namespace revolve::render {

// Row 0 at the top, width x height floats; on `threads` threads (0: all), the result the same on any.
std::vector<float> depthImage(const scene::EmbreeScene& scene, const io::SceneCamera& camera, int width, int height,
                              int threads = 0);

}  // namespace revolve::render
