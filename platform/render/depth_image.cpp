#include "render/depth_image.h"

#include "geometry/unit_vector.h"
#include "scene/camera.h"
#include "threads/thread_arenas.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <span>

namespace revolve::render {

std::vector<float> depthImage(const scene::EmbreeScene& scene, const io::SceneCamera& camera, int width, int height,
                              int threads) {
  const scene::Camera pinhole(camera, width, height);
  // The optical axis in double: z = (t d) . axis for the hit t d along the ray's direction d.
  const app::Vec3d axis =
      app::unitVector({camera.to[0] - camera.from[0], camera.to[1] - camera.from[1], camera.to[2] - camera.from[2]});
  std::vector<float> depth(std::size_t(width) * std::size_t(height));
  constexpr std::size_t kPacket = scene::EmbreeScene::kPacketRays;
  app::threadArena(threads).execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
      std::array<Ray, kPacket> rays;
      std::array<std::optional<scene::RangeHit>, kPacket> hits;
      for (int y = rows.begin(); y != rows.end(); ++y) {
        for (int x0 = 0; x0 < width; x0 += int(kPacket)) {
          const std::size_t n = std::min<std::size_t>(kPacket, std::size_t(width - x0));
          for (std::size_t k = 0; k < n; ++k) rays[k] = pinhole.ray(float(x0 + int(k)) + 0.5f, float(y) + 0.5f);
          scene.nearest(std::span<const Ray>(rays.data(), n), std::span(hits.data(), n));
          for (std::size_t k = 0; k < n; ++k) {
            float& out = depth[std::size_t(y) * std::size_t(width) + std::size_t(x0) + k];
            if (!hits[k]) {
              out = std::numeric_limits<float>::infinity();
              continue;
            }
            const Vec3& d = rays[k].direction;
            out = float(double(hits[k]->t) * (double(d.x) * axis[0] + double(d.y) * axis[1] + double(d.z) * axis[2]));
          }
        }
      }
    });
  });
  return depth;
}

}  // namespace revolve::render
