#include "renderer.h"

#include "scene/camera.h"

#include <tbb/task_arena.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace revolve::render {

namespace {
constexpr int kTile = 16;  // pixels a side: enough work per task, enough tasks to balance
}

RenderResult render(const io::SceneDescription& description, const scene::EmbreeScene& scene,
                    const RenderSettings& settings, const std::function<void(double)>& progress) {
  std::vector<Material> materials;
  for (const io::SceneMaterial& m : description.materials) materials.emplace_back(m);
  const Lights lights(description.lights, description.environment);
  const Integrator integrator(scene, materials, lights, settings.integrator);
  const scene::Camera camera(description.camera, settings.width, settings.height);

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
  arena.execute([&] { tbb::parallel_for(0, tiles, [&](int tile) {
    RayCounts counts;
    const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
    for (int y = y0; y < std::min(y0 + kTile, settings.height); ++y) {
      for (int x = x0; x < std::min(x0 + kTile, settings.width); ++x) {
        const std::uint64_t pixel = std::uint64_t(y) * settings.width + x;
        Color sum;
        for (int s = 0; s < settings.spp; ++s) {
          RandomStream random(settings.seed, pixel, std::uint64_t(s));
          // One sample: the pixel's centre (the paper's ray casting); more: jittered over the pixel.
          const float jx = settings.spp == 1 ? 0.5f : random.next(), jy = settings.spp == 1 ? 0.5f : random.next();
          sum += integrator.radiance(camera.ray(float(x) + jx, float(y) + jy), random, counts);
        }
        float* out = result.image.pixels.data() + 3 * pixel;
        const float scale = 1.0f / float(settings.spp);
        out[0] = sum.r * scale, out[1] = sum.g * scale, out[2] = sum.b * scale;
      }
    }
    cameraRays += counts.camera, bounceRays += counts.bounce, shadowRays += counts.shadow;
    ++tilesDone;
  }); });
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
