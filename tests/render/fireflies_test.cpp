// Fireflies on scenes/many.json at its 16 samples a pixel, default options, counted on the linear
// EXR revolve-render writes (fireflies.h has the rule).
//
// The rule also flags what is really there: the sun's glints on the steel kegs cover a third of a
// pixel and are 50 times as bright as the concrete, so the converged image has about a hundred
// such pixels of its own. A firefly is noise when the converged image does not have it: each
// flagged pixel and its 8 neighbours are estimated again with 1024 samples and another seed, and
// the pixel counts as noise if it is no firefly there. At most 30 may be noise.
#include "fireflies.h"
#include "render_support.h"

#include "io/scene_file.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <unistd.h>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>

namespace revolve {
namespace {

struct Count {
  int flagged = 0;  // fireflies of the 16-spp image
  int noise = 0;    // ... that the converged image does not have
};

Count countOnMany(bool regularize) {
  const io::SceneDescription description = io::readScene(std::string(REVOLVE_SOURCE_DIR) + "/scenes/many.json");
  const scene::EmbreeScene built(description, {});
  render::RenderSettings settings;  // what revolve-render does with the scene's camera block
  settings.width = description.camera.width.value();
  settings.height = description.camera.height.value();
  settings.spp = description.camera.spp.value();
  settings.integrator.regularize = regularize;
  const render::RenderResult result = render::render(description, built, settings);

  // Through the EXR, as a user counts them.
  const std::string exr =
      (std::filesystem::temp_directory_path() / ("revolve-fireflies-" + std::to_string(getpid()) + ".exr")).string();
  io::writeFileAtomically(exr, [&](std::FILE* file) {
    io::OutputStream out(file, exr);
    render::writeImage(out, exr, result.image);
  });
  OIIO::ImageBuf image(exr);
  std::vector<float> pixels(result.image.pixels.size());
  const bool read = image.read(0, 0, true, OIIO::TypeDesc::FLOAT) &&
                    image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  std::filesystem::remove(exr);
  EXPECT_TRUE(read) << image.geterror();

  render::RenderSettings converged = settings;
  converged.spp = 1024;
  converged.seed = 7;
  const render::PixelEstimator estimator(description, built, converged);
  const std::vector<testing::Pixel> flagged = testing::fireflies(pixels, settings.width, settings.height);
  std::atomic<int> noise{0};
  tbb::parallel_for(std::size_t(0), flagged.size(), [&](std::size_t i) {
    render::RayCounts counts;
    const auto luminance = [&](int x, int y) {
      const render::Color c = estimator.pixel(x, y, counts);
      return (c.r + c.g + c.b) / 3;
    };
    if (!testing::isFirefly(luminance, settings.width, settings.height, flagged[i].x, flagged[i].y)) ++noise;
  });
  return {int(flagged.size()), noise.load()};
}

TEST(FirefliesTest, ManyAtSixteenSamplesHasAtMostThirtyThatAreNoise) {
  const Count count = countOnMany(true);
  std::printf("many.json, 16 spp: %d fireflies, %d of them not in the converged image\n", count.flagged, count.noise);
  EXPECT_LE(count.noise, 30);
  EXPECT_GT(count.flagged, 0) << "the glints should be flagged: is the counting rule applied?";
}

}  // namespace
}  // namespace revolve
