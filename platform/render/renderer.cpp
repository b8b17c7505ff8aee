#include "render/renderer.h"
#include "threads/thread_arenas.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <optional>
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
      scene_(scene),
      camera_(description.camera, settings.width, settings.height) {}

std::pair<float, float> PixelEstimator::samplePosition(int x, int y, RandomStream& random) const {
  // One sample: the pixel's centre (Baciu, Jia & Lam's ray casting); more: drawn from the pixel filter.
  float jx = 0.5f, jy = 0.5f;
  if (settings_.spp > 1) {
    const auto [u, v] = random.next2D();
    if (settings_.filter == PixelFilter::tent)
      jx += tentOffset(u), jy += tentOffset(v);
    else
      jx = u, jy = v;
  }
  return {float(x) + jx, float(y) + jy};
}

Color PixelEstimator::pixel(int x, int y, RayCounts& counts) const {
  const std::uint64_t pixel = std::uint64_t(y) * settings_.width + x;
  Color sum;
  for (int s = 0; s < settings_.spp; ++s) {
    RandomStream random(settings_.seed, pixel, std::uint64_t(s));
    const auto [px, py] = samplePosition(x, y, random);
    sum += integrator_.radiance(camera_.ray(px, py), random, counts);
  }
  return (1.0f / float(settings_.spp)) * sum;
}

void PixelEstimator::pixels(const PixelPacket& packet, std::span<Color> out, RayCounts& counts) const {
  constexpr std::size_t kLanes = scene::EmbreeScene::kPacketRays;
  const std::size_t lanes = std::size_t(packet.count);
  std::array<Color, kLanes> sums{};
  std::array<std::optional<RandomStream>, kLanes> randoms;
  std::array<Ray, kLanes> rays;
  std::array<std::optional<scene::WorldHit>, kLanes> hits;
  for (int s = 0; s < settings_.spp; ++s) {
    // Each lane's sample drawn from its own stream, as pixel() draws it; then the camera rays
    // traced together; then each lane's path on from its hit, drawing from its stream again.
    {
      const PhaseScope phase(counts.clock, Phase::sampling);
      for (std::size_t i = 0; i < lanes; ++i) {
        const std::uint64_t pixel = std::uint64_t(packet.y[i]) * settings_.width + packet.x[i];
        RandomStream& random = randoms[i].emplace(settings_.seed, pixel, std::uint64_t(s));
        const auto [px, py] = samplePosition(packet.x[i], packet.y[i], random);
        rays[i] = camera_.ray(px, py);
      }
    }
    {
      const PhaseScope phase(counts.clock, Phase::intersection);
      scene_.intersect(std::span<const Ray>(rays.data(), lanes), std::span(hits.data(), lanes));
    }
    for (std::size_t i = 0; i < lanes; ++i) sums[i] += integrator_.radiance(rays[i], hits[i], *randoms[i], counts);
  }
  for (std::size_t i = 0; i < lanes; ++i) out[i] = (1.0f / float(settings_.spp)) * sums[i];
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
  // Each tile's phase ticks, summed per tile (a tile runs on one thread) and added here once per tile.
  std::array<std::atomic<std::uint64_t>, kPhaseCount> phaseTicks{};

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
  tbb::task_arena& arena = app::threadArena(settings.threads > 0 ? settings.threads : 0);
  arena.execute([&] {
    tbb::parallel_for(0, tiles, [&](int tile) {
      std::optional<PhaseClock> clock;
      if (settings.measurePhases) clock.emplace();
      RayCounts counts;
      counts.clock = clock ? &*clock : nullptr;
      const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
      const int x1 = std::min(x0 + kTile, settings.width), y1 = std::min(y0 + kTile, settings.height);
      // The tile in blocks of kPacketWidth x kPacketHeight pixels, partial where the image ends.
      for (int by = y0; by < y1; by += kPacketHeight) {
        for (int bx = x0; bx < x1; bx += kPacketWidth) {
          PixelPacket packet;
          for (int y = by; y < std::min(by + kPacketHeight, y1); ++y) {
            for (int x = bx; x < std::min(bx + kPacketWidth, x1); ++x) {
              packet.x[packet.count] = x, packet.y[packet.count] = y;
              ++packet.count;
            }
          }
          std::array<Color, scene::EmbreeScene::kPacketRays> values;
          estimator.pixels(packet, values, counts);
          for (int i = 0; i < packet.count; ++i) {
            float* out = result.image.pixels.data() + 3 * (std::size_t(packet.y[i]) * settings.width + packet.x[i]);
            out[0] = values[i].r, out[1] = values[i].g, out[2] = values[i].b;
          }
        }
      }
      cameraRays += counts.camera, bounceRays += counts.bounce, shadowRays += counts.shadow;
      if (clock) {
        const std::array<std::uint64_t, kPhaseCount> ticks = clock->ticks();
        for (std::size_t p = 0; p < kPhaseCount; ++p) phaseTicks[p] += ticks[p];
      }
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
  double allTicks = 0;
  for (const auto& ticks : phaseTicks) allTicks += double(ticks.load());
  for (std::size_t p = 0; p < kPhaseCount && allTicks > 0; ++p)
    result.phaseShares[p] = double(phaseTicks[p]) / allTicks;
  return result;
}

}  // namespace revolve::render
