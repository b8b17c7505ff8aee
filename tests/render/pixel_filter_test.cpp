// The pixel filters against their definitions. A black wall covers the left of the view of a white
// sky, its vertical edge at image x = 16.3 (by construction of the camera). A pixel's value is the
// share of its filter that lies right of the edge: for the tent of radius 1 about the centre c,
// 1 - T(16.3 - c) with T the tent's distribution function; for the box, the share of the pixel's
// own square; with one sample, whether the centre lies right of it.
#include "render_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace revolve {
namespace {

constexpr int kWidth = 32, kHeight = 8;
constexpr double kEdge = 16.3;

double tentDistribution(double d) {
  if (d <= -1) return 0;
  if (d <= 0) return 0.5 * (d + 1) * (d + 1);
  if (d < 1) return 1 - 0.5 * (1 - d) * (1 - d);
  return 1;
}

// Column means of the rendered image (every row sees the same edge).
std::vector<double> columns(const render::RenderSettings& settings) {
  // Camera at (0, -10, 0) looking along +y: image x maps to world x = 10 tan(fov / 2) (w / h) (2 x / w - 1).
  const double fov = 10, halfWidth = 10 * std::tan(fov / 2 * std::numbers::pi / 180) * kWidth / kHeight;
  const double wallEdge = halfWidth * (2 * kEdge / kWidth - 1);
  char corners[256];
  std::snprintf(corners, sizeof corners, "[[-1000, 0, -1000], [%.17g, 0, -1000], [%.17g, 0, 1000], [-1000, 0, 1000]]",
                wallEdge, wallEdge);
  const std::string scene = R"({"camera": {"from": [0, -10, 0], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 10},
      "profiles": {}, "materials": {"black": {"type": "diffuse", "color": [0, 0, 0]}}, "objects": [],
      "quads": [{"corners": )" +
                            std::string(corners) + R"(, "material": "black"}],
      "environment": {"color": [1, 1, 1]}})";
  const testing::RenderRun run = testing::renderText(scene, settings);
  std::vector<double> means(kWidth, 0.0);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) means[x] += run.result.image.at(x, y).g / kHeight;
  }
  return means;
}

render::RenderSettings settings(int spp, render::PixelFilter filter) {
  render::RenderSettings s;
  s.width = kWidth;
  s.height = kHeight;
  s.spp = spp;
  s.filter = filter;
  return s;
}

TEST(PixelFilterTest, TentSpreadsTheEdgeByItsDistributionFunction) {
  const std::vector<double> value = columns(settings(1024, render::PixelFilter::tent));
  for (int x = 0; x < kWidth; ++x) {
    // 8 rows x 1024 stratified samples: the share is measured to far better than 0.005.
    EXPECT_NEAR(value[x], 1 - tentDistribution(kEdge - (x + 0.5)), 0.005) << "column " << x;
  }
  EXPECT_GT(value[15], 0.01) << "the tent reaches a pixel beyond the edge's own";
}

TEST(PixelFilterTest, BoxTakesThePixelsOwnSquare) {
  const std::vector<double> value = columns(settings(1024, render::PixelFilter::box));
  for (int x = 0; x < kWidth; ++x) EXPECT_NEAR(value[x], std::clamp(x + 1 - kEdge, 0.0, 1.0), 0.005) << "column " << x;
}

TEST(PixelFilterTest, OneSampleIsThePixelsCentre) {
  for (const render::PixelFilter filter : {render::PixelFilter::tent, render::PixelFilter::box}) {
    const std::vector<double> value = columns(settings(1, filter));
    for (int x = 0; x < kWidth; ++x) EXPECT_EQ(value[x], x + 0.5 > kEdge ? 1.0 : 0.0) << "column " << x;
  }
}

}  // namespace
}  // namespace revolve
