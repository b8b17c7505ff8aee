// Packets of rays equal single rays, bit for bit: EmbreeScene's 8-wide queries (rtcIntersect8 under
// a valid mask) against its one-ray queries (rtcIntersect1) on the bundled scenes' camera rays, in
// the renderer's 4 x 2 pixel blocks and in partial packets of every size, exact and tessellated;
// lanes whose rays break Embree's contract refused while the rest are traced; and the renderer's
// packets of pixels against its pixel-by-pixel estimate, at image edges where blocks and tiles are
// partial. The expected values are the single-ray peers' (the contract: the tools trace in packets
// and their images and scans stay what single rays gave).
#include "render_support.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace revolve {
namespace {

const std::string kPatio = std::string(REVOLVE_SOURCE_DIR) + "/scenes/patio.json";
const std::string kSplines = std::string(REVOLVE_SOURCE_DIR) + "/scenes/spline_still_life.json";
constexpr std::size_t kLanes = scene::EmbreeScene::kPacketRays;

bool sameBits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool sameBits(Vec3 a, Vec3 b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }

// Every field of the hit, bit for bit.
void expectSameHit(const std::optional<scene::WorldHit>& packet, const std::optional<scene::WorldHit>& single,
                   const std::string& where) {
  ASSERT_EQ(packet.has_value(), single.has_value()) << where;
  if (!single) return;
  EXPECT_TRUE(sameBits(packet->t, single->t)) << where;
  EXPECT_TRUE(sameBits(packet->point, single->point)) << where;
  EXPECT_TRUE(sameBits(packet->geometricNormal, single->geometricNormal)) << where;
  EXPECT_TRUE(sameBits(packet->shadingNormal, single->shadingNormal)) << where;
  EXPECT_EQ(packet->material, single->material) << where;
  EXPECT_EQ(packet->object, single->object) << where;
  EXPECT_EQ(packet->exactSurface, single->exactSurface) << where;
  EXPECT_TRUE(sameBits(packet->ray.origin, single->ray.origin) &&
              sameBits(packet->ray.direction, single->ray.direction))
      << where;
  EXPECT_TRUE(sameBits(packet->transformError, single->transformError)) << where;
  EXPECT_TRUE(sameBits(packet->pointError, single->pointError)) << where;
}

// Traces `rays` as one packet both ways (intersect and nearest) and checks each lane against the
// single ray; returns how many lanes hit.
int checkPacket(const scene::EmbreeScene& built, const std::vector<Ray>& rays, const std::string& where) {
  std::optional<scene::WorldHit> hits[kLanes];
  std::optional<scene::RangeHit> ranges[kLanes];
  built.intersect(rays, std::span(hits, rays.size()));
  built.nearest(rays, std::span(ranges, rays.size()));
  int hit = 0;
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const std::string lane = where + ", lane " + std::to_string(k) + " of " + std::to_string(rays.size());
    const std::optional<scene::WorldHit> single = built.intersect(rays[k]);
    expectSameHit(hits[k], single, lane);
    const std::optional<scene::RangeHit> range = built.nearest(rays[k]);
    EXPECT_EQ(ranges[k].has_value(), range.has_value()) << lane;
    if (range && ranges[k]) {
      EXPECT_TRUE(sameBits(ranges[k]->t, range->t)) << lane;
      EXPECT_EQ(ranges[k]->object, range->object) << lane;
    }
    hit += single ? 1 : 0;
  }
  return hit;
}

struct Case {
  std::string scene;
  bool mesh;
};

class CameraPacketTest : public ::testing::TestWithParam<Case> {};

// Camera rays through a 37 x 23 image: its 4 x 2 blocks (partial on the right and bottom edges),
// each traced at the pixel centres and at scattered positions (rays of one packet far apart); and
// the first 1 to 8 rays of the image as packets of every size.
TEST_P(CameraPacketTest, EveryLaneEqualsItsSingleRay) {
  const io::SceneDescription description = io::readScene(GetParam().scene);
  scene::BuildSettings build;
  build.mesh = GetParam().mesh;
  const scene::EmbreeScene built(description, build);
  constexpr int kWidth = 37, kHeight = 23;
  const scene::Camera camera(description.camera, kWidth, kHeight);
  int hits = 0, rays = 0;
  std::uint32_t scatter = 12345;
  const auto scattered = [&] {  // a small LCG: positions anywhere in the image
    scatter = scatter * 1664525u + 1013904223u;
    return float(scatter >> 8) * 0x1p-24f;
  };
  for (int by = 0; by < kHeight; by += render::kPacketHeight) {
    for (int bx = 0; bx < kWidth; bx += render::kPacketWidth) {
      std::vector<Ray> centres, far;
      for (int y = by; y < std::min(by + render::kPacketHeight, kHeight); ++y) {
        for (int x = bx; x < std::min(bx + render::kPacketWidth, kWidth); ++x) {
          centres.push_back(camera.ray(float(x) + 0.5f, float(y) + 0.5f));
          far.push_back(camera.ray(kWidth * scattered(), kHeight * scattered()));
        }
      }
      const std::string where = "block at " + std::to_string(bx) + ", " + std::to_string(by);
      hits += checkPacket(built, centres, where + " (centres)");
      hits += checkPacket(built, far, where + " (scattered)");
      rays += int(centres.size() + far.size());
    }
  }
  for (std::size_t count = 1; count <= kLanes; ++count) {
    std::vector<Ray> first;
    for (std::size_t i = 0; i < count; ++i) first.push_back(camera.ray(float(i) + 0.5f, 11.5f));
    checkPacket(built, first, "a packet of " + std::to_string(count));
  }
  // The images see their scenes: most rays hit, not all (the sky).
  EXPECT_GT(hits, rays / 2);
  EXPECT_EQ(built.refusedRays(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, CameraPacketTest,
                         ::testing::Values(Case{kPatio, false}, Case{kPatio, true}, Case{kSplines, false},
                                           Case{kSplines, true}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.scene == kPatio ? "Patio" : "SplineStillLife") +
                                  (info.param.mesh ? "Mesh" : "Exact");
                         });

// A ray Embree would abort on (NaN, or beyond its largest coordinate) is refused in its lane and
// counted, as the single query refuses it; the packet's other lanes are traced as usual.
TEST(CameraPacketTest, RefusedLanesMissAndTheOthersAreTraced) {
  const io::SceneDescription description = io::readScene(kPatio);
  const scene::EmbreeScene built(description, {});
  const scene::Camera camera(description.camera, 8, 1);
  std::vector<Ray> rays;
  for (int x = 0; x < 8; ++x) rays.push_back(camera.ray(float(x) + 0.5f, 0.9f));
  rays[2].origin.x = std::numeric_limits<float>::quiet_NaN();
  rays[5].direction.z = 1e30f;
  std::optional<scene::WorldHit> hits[kLanes];
  built.intersect(rays, std::span(hits, rays.size()));
  EXPECT_EQ(built.refusedRays(), 2u);
  EXPECT_FALSE(hits[2]);
  EXPECT_FALSE(hits[5]);
  for (const std::size_t k : {0, 1, 3, 4, 6, 7}) expectSameHit(hits[k], built.intersect(rays[k]), std::to_string(k));
  const int traced = checkPacket(built, rays, "with refused lanes");
  EXPECT_GT(traced, 0);
  // Then checkPacket's four queries (packet and single rays, intersect and nearest) refused both again.
  EXPECT_EQ(built.refusedRays(), 2u + 4u * 2u);
}

// The renderer's packets of pixels (its camera rays traced together) against pixel by pixel, on a
// 13 x 9 image: tiles, blocks and packets partial on its right and bottom edges; both integrators,
// several samples a pixel (their random numbers drawn per pixel as before).
TEST(PixelPacketTest, RenderedImagesEqualThePixelByPixelEstimate) {
  for (const std::string& path : {kPatio, kSplines}) {
    const io::SceneDescription description = io::readScene(path);
    const scene::EmbreeScene built(description, {});
    for (const render::IntegratorKind kind : {render::IntegratorKind::path, render::IntegratorKind::whitted}) {
      render::RenderSettings settings;
      settings.width = 13;
      settings.height = 9;
      settings.spp = 3;
      settings.threads = 2;
      settings.integrator.kind = kind;
      const render::RenderResult result = render::render(description, built, settings);
      const render::PixelEstimator estimator(description, built, settings);
      render::RayCounts counts;
      int lit = 0;
      for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
          const render::Color single = estimator.pixel(x, y, counts), packed = result.image.at(x, y);
          EXPECT_TRUE(sameBits(single.r, packed.r) && sameBits(single.g, packed.g) && sameBits(single.b, packed.b))
              << path << " pixel " << x << ", " << y;
          lit += single.r > 0 ? 1 : 0;
        }
      }
      EXPECT_GT(lit, 0);
      EXPECT_EQ(counts.camera, result.rays.camera);
      EXPECT_EQ(counts.bounce, result.rays.bounce);
      EXPECT_EQ(counts.shadow, result.rays.shadow);
      // A packet of each size, from a lone pixel to a full block, in the image's last row.
      for (int count = 1; count <= int(kLanes); ++count) {
        render::PixelPacket packet;
        for (int i = 0; i < count; ++i) packet.x[i] = settings.width - 1 - i, packet.y[i] = settings.height - 1;
        packet.count = count;
        render::Color values[kLanes];
        estimator.pixels(packet, std::span(values, kLanes), counts);
        for (int i = 0; i < count; ++i) {
          const render::Color single = estimator.pixel(packet.x[i], packet.y[i], counts);
          EXPECT_TRUE(sameBits(single.r, values[i].r) && sameBits(single.g, values[i].g) &&
                      sameBits(single.b, values[i].b))
              << path << " packet of " << count << ", lane " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace revolve
