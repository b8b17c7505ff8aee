// Renders a built scene into a linear RGB float image: tiles in parallel (TBB), each pixel's samples
// drawn from its own random stream, so the image depends on the seed only, not on the threads.
#pragma once

#include "integrators.h"
#include "io/scene_file.h"
#include "scene/embree_scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace revolve::render {

struct RenderSettings {
  int width = 0, height = 0, spp = 1;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all the machine's
  IntegratorSettings integrator;
};

struct Image {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGB, row 0 at the top
  Color at(int x, int y) const {
    const float* p = pixels.data() + 3 * (std::size_t(y) * width + x);
    return {p[0], p[1], p[2]};
  }
};

struct RenderResult {
  Image image;
  RayCounts rays;
  double seconds = 0;
};

// `progress(done, total)` is called from a thread of its own now and then, never from a tile.
RenderResult render(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                    const RenderSettings& settings, const std::function<void(double fraction)>& progress = {});

}  // namespace revolve::render
