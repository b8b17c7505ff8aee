// Renders a built scene into a linear RGB float image: tiles in parallel (TBB), each pixel's samples
// drawn from its own random stream, so the image depends on the seed only, not on the threads.
#pragma once

#include "io/scene_file.h"
#include "render/integrators.h"
#include "render/phase_clock.h"
#include "scene/camera.h"
#include "scene/embree_scene.h"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
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
  bool measurePhases = false;  // RenderResult::phaseShares (--stats); costs a clock read per phase switch
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
  // With measurePhases: the share of the tiles' time (summed over threads) in each Phase, by its
  // number; they sum to 1. Otherwise zeros.
  std::array<double, kPhaseCount> phaseShares{};
};

// Neighbouring pixels whose camera rays are traced together: a block of kPacketWidth x
// kPacketHeight pixels, fewer where the image ends.
inline constexpr int kPacketWidth = 4, kPacketHeight = 2;
struct PixelPacket {
  int count = 0;  // up to scene::EmbreeScene::kPacketRays
  std::array<int, scene::EmbreeScene::kPacketRays> x{}, y{};
};

// One pixel's estimate: the mean of settings.spp samples, each from the random stream of (seed,
// pixel, sample). render() is this over every pixel; tests also call it for single pixels.
class PixelEstimator {
 public:
  PixelEstimator(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                 const RenderSettings& settings);
  // Thread-safe; never allocates, throws or locks.
  Color pixel(int x, int y, RayCounts& counts) const;
  // The estimates of a packet's pixels, each sample's camera rays traced as one packet: out[i] is
  // pixel(packet.x[i], packet.y[i]) bit for bit (the same random numbers drawn in the same order).
  // Thread-safe; never allocates, throws or locks.
  void pixels(const PixelPacket& packet, std::span<Color> out, RayCounts& counts) const;

 private:
  // The pixel position of sample `s` of pixel (x, y), drawn from `random` (its first numbers).
  std::pair<float, float> samplePosition(int x, int y, RandomStream& random) const;

  RenderSettings settings_;
  std::vector<Material> materials_;
  Lights lights_;
  Integrator integrator_;
  const scene::EmbreeScene& scene_;
  scene::Camera camera_;
};

// `progress(done, total)` is called from a thread of its own now and then, never from a tile.
RenderResult render(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                    const RenderSettings& settings, const std::function<void(double fraction)>& progress = {});

}  // namespace revolve::render
