#include "renderer.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace revolve::render {

namespace {
constexpr int kTile = 16;  // pixels a side: enough work per task, enough tasks to balance
}

namespace {

// The tent filter importance-sampled: the inverse of its distribution function, so that every
// sample keeps weight 1. A box filter lets a glint a third of a pixel wide fall into a pixel's
// samples by chance; on many.json at 16 spp that made a third of the fireflies that are not in
// the converged image (README, "Fireflies"). The tent shares each sample with the neighbours.
float tentOffset(float u) { return u < 0.5f ? std::sqrt(2 * u) - 1 : 1 - std::sqrt(2 - 2 * u); }

std::vector<Material> materialsOf(const io::SceneDescription& description) {
  std::vector<Material> materials;
  for (const io::SceneMaterial& m : description.materials) materials.emplace_back(m);
  return materials;
}
}  // namespace

PixelEstimator::PixelEstimator(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                               const RenderSettings& settings)
    : settings_(settings),
      materials_(materialsOf(description)),
      lights_(description.lights, description.environment),
      integrator_(scene, materials_, lights_, settings.integrator),
      camera_(description.camera, settings.width, settings.height) {}

Color PixelEstimator::pixel(int x, int y, RayCounts& counts) const {
  const std::uint64_t pixel = std::uint64_t(y) * settings_.width + x;
  Color sum;
  for (int s = 0; s < settings_.spp; ++s) {
    RandomStream random(settings_.seed, pixel, std::uint64_t(s));
    // One sample: the pixel's centre (Baciu, Jia & Lam's ray casting); more: drawn from the pixel filter.
    float jx = 0.5f, jy = 0.5f;
    if (settings_.spp > 1) {
      const auto [u, v] = random.next2D();
      if (settings_.filter == PixelFilter::tent)
        jx += tentOffset(u), jy += tentOffset(v);
      else
        jx = u, jy = v;
    }
    sum += integrator_.radiance(camera_.ray(float(x) + jx, float(y) + jy), random, counts);
  }
  return (1.0f / float(settings_.spp)) * sum;
}

RenderResult render(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                    const RenderSettings& settings, const std::function<void(double)>& progress) {
  const PixelEstimator estimator(description, scene, settings);

  RenderResult result;
  result.image.width = settings.width;
  result.image.height = settings.height;
  result.image.pixels.assign(3 * std::size_t(settings.width) * settings.height, 0.0f);

  const int tilesX = (settings.width + kTile - 1) / kTile, tilesY = (settings.height + kTile - 1) / kTile;
  const int tiles = tilesX * tilesY;
  std::atomic<int> tilesDone{0};
  std::atomic<std::uint64_t> cameraRays{0}, bounceRays{0}, shadowRays{0};

  // The progress reporter wakes a few times a second; the tiles only bump an atomic counter.
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread reporter;
  if (progress) {
    reporter = std::thread([&] {
      std::unique_lock lock(mutex);
      while (!finished.wait_for(lock, std::chrono::milliseconds(250), [&] { return done; })) {
        progress(double(tilesDone.load()) / tiles);
      }
    });
  }

  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(0, tiles, [&](int tile) {
      RayCounts counts;
      const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
      for (int y = y0; y < std::min(y0 + kTile, settings.height); ++y) {
        for (int x = x0; x < std::min(x0 + kTile, settings.width); ++x) {
          const Color value = estimator.pixel(x, y, counts);
          float* out = result.image.pixels.data() + 3 * (std::size_t(y) * settings.width + x);
          out[0] = value.r, out[1] = value.g, out[2] = value.b;
        }
      }
      cameraRays += counts.camera, bounceRays += counts.bounce, shadowRays += counts.shadow;
      ++tilesDone;
    });
  });
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (reporter.joinable()) {
    {
      std::lock_guard lock(mutex);
      done = true;
    }
    finished.notify_one();
    reporter.join();
  }
  result.rays = {cameraRays.load(), bounceRays.load(), shadowRays.load()};
  return result;
}

}  // namespace revolve::render
