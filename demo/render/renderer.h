// Renders a built scene into a linear RGB float image: tiles in parallel (TBB), each pixel's samples
// drawn from its own random stream, so the image depends on the seed only, not on the threads.
#pragma once

#include "integrators.h"
#include "io/scene_file.h"
#include "scene/camera.h"
#include "scene/embree_scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace revolve::render {

// How a pixel's samples spread over the image: the tent of radius 1 pixel (w(x) = 1 - |x| about
// the pixel's centre, per axis), or the pixel's own square. With one sample a pixel, its centre.
enum class PixelFilter { tent, box };

struct RenderSettings {
  int width = 0, height = 0, spp = 1;
  PixelFilter filter = PixelFilter::tent;
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

// One pixel's estimate: the mean of settings.spp samples, each from the random stream of (seed,
// pixel, sample). render() is this over every pixel; tests also call it for single pixels.
class PixelEstimator {
 public:
  PixelEstimator(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                 const RenderSettings& settings);
  // Thread-safe; never allocates, throws or locks.
  Color pixel(int x, int y, RayCounts& counts) const;

 private:
  RenderSettings settings_;
  std::vector<Material> materials_;
  Lights lights_;
  Integrator integrator_;
  scene::Camera camera_;
};

// `progress(done, total)` is called from a thread of its own now and then, never from a tile.
RenderResult render(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                    const RenderSettings& settings, const std::function<void(double fraction)>& progress = {});

}  // namespace revolve::render
