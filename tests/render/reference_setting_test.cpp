// The reference setting (no path regularisation, the box pixel filter) converges to the images
// the renderer made before it weighed the sun's two strategies (multiple importance sampling),
// stratified its samples and filtered pixels with the tent: those changes remove noise, not light.
//
// converged/*.exr are the five reference scenes rendered by that earlier renderer at 16,384 samples
// a pixel (whitted_all: 4,096), written as half floats (tests/render/README.md). Each is compared
// with two independent renders of this one (seeds 11 and 12): per channel, the mean difference
// over the image and over each 8 x 8 block must lie within 5 of its standard errors, estimated from
// the two renders' differences (a t statistic of 64 or more degrees of freedom), plus the half
// floats' rounding (2^-11 relative).
#include "render_support.h"

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace revolve {
namespace {

struct Scene {
  std::string name;
  render::IntegratorKind integrator;
  int depth;
  int referenceSpp;
};
void PrintTo(const Scene& scene, std::ostream* out) { *out << scene.name; }

class ReferenceSettingTest : public ::testing::TestWithParam<Scene> {};

TEST_P(ReferenceSettingTest, ConvergesToTheImageOfTheEarlierRenderer) {
  const Scene& scene = GetParam();
  const std::string directory = std::string(REVOLVE_SOURCE_DIR) + "/tests/render/";
  const io::SceneDescription description = io::readScene(directory + "scenes/" + scene.name + ".json");
  const scene::EmbreeScene built(description, {});
  render::RenderSettings settings;
  settings.width = description.camera.width.value();
  settings.height = description.camera.height.value();
  settings.spp = 512;
  settings.filter = render::PixelFilter::box;
  settings.integrator.kind = scene.integrator;
  settings.integrator.depth = scene.depth;
  settings.integrator.regularize = false;
  settings.seed = 11;
  const render::Image a = render::render(description, built, settings).image;
  settings.seed = 12;
  const render::Image b = render::render(description, built, settings).image;

  OIIO::ImageBuf image(directory + "converged/" + scene.name + ".exr");
  ASSERT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << image.geterror();
  ASSERT_EQ(image.spec().width, settings.width);
  ASSERT_EQ(image.spec().height, settings.height);
  std::vector<float> reference(a.pixels.size());
  ASSERT_TRUE(image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, reference.data()));

  // The mean of (a + b) / 2 - reference over a rectangle of pixels, in units of its standard error.
  // Var((a + b) / 2) = sigma^2 / 2 is estimated by (a - b)^2 / 4; the reference's own variance is
  // that times 2 * 512 / its samples.
  const double referenceShare = 2.0 * settings.spp / scene.referenceSpp;
  const auto deviation = [&](int x0, int y0, int x1, int y1, int channel) {
    double difference = 0, variance = 0, rounding = 0;
    int n = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x, ++n) {
        const std::size_t i = 3 * (std::size_t(y) * settings.width + x) + channel;
        difference += 0.5 * (a.pixels[i] + b.pixels[i]) - reference[i];
        variance += (1 + referenceShare) * 0.25 * (a.pixels[i] - b.pixels[i]) * (a.pixels[i] - b.pixels[i]);
        rounding += 0x1p-11 * std::abs(reference[i]);
      }
    }
    const double excess = std::max(0.0, std::abs(difference) - rounding);
    return variance > 0 ? excess / std::sqrt(variance) : (excess > 0 ? INFINITY : 0.0);
  };
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_LT(deviation(0, 0, settings.width, settings.height, channel), 5) << "whole image, channel " << channel;
    for (int y0 = 0; y0 < settings.height; y0 += 8) {
      for (int x0 = 0; x0 < settings.width; x0 += 8) {
        EXPECT_LT(deviation(x0, y0, std::min(x0 + 8, settings.width), std::min(y0 + 8, settings.height), channel), 5)
            << "block at " << x0 << ", " << y0 << ", channel " << channel;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReferenceSettingTest,
                         ::testing::Values(Scene{"material_diffuse", render::IntegratorKind::path, 8, 16384},
                                           Scene{"material_metal", render::IntegratorKind::path, 8, 16384},
                                           Scene{"material_mirror", render::IntegratorKind::path, 8, 16384},
                                           Scene{"material_glass", render::IntegratorKind::path, 8, 16384},
                                           Scene{"whitted_all", render::IntegratorKind::whitted, 4, 4096}),
                         [](const ::testing::TestParamInfo<Scene>& info) { return info.param.name; });

}  // namespace
}  // namespace revolve
