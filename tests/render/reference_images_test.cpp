// Tiny renders against committed reference images: one per material kind (path tracing) and one
// for the Whitted integrator. These are regression guards, not proofs of correctness (the closed-
// form and agreement tests are those): the references are this renderer's own output, looked at
// before they were committed, and regenerated with the commands in tests/render/README.md.
//
// Tolerance: the references are stored as half floats (relative rounding 2^-11), so each value
// must lie within 2^-10 of the reference relative, or 1e-3 absolute for dark values; 1% of the
// values may differ more, for paths that a last-bit difference between compilers sends elsewhere.
#include "render_support.h"

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace revolve {
namespace {

struct Reference {
  std::string name;
  render::IntegratorKind integrator;
  int depth;
};

class ReferenceImagesTest : public ::testing::TestWithParam<Reference> {};

TEST_P(ReferenceImagesTest, MatchesTheCommittedImage) {
  const Reference& reference = GetParam();
  const std::string directory = std::string(REVOLVE_SOURCE_DIR) + "/tests/render/";
  const io::SceneDescription description = io::readScene(directory + "scenes/" + reference.name + ".json");
  render::RenderSettings settings;  // what revolve-render does with the scene's camera block
  settings.width = description.camera.width.value();
  settings.height = description.camera.height.value();
  settings.spp = description.camera.spp.value();
  settings.integrator.kind = reference.integrator;
  settings.integrator.depth = reference.depth;
  const scene::EmbreeScene built(description, {});
  const render::RenderResult result = render::render(description, built, settings);

  OIIO::ImageBuf image(directory + "reference/" + reference.name + ".exr");
  ASSERT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << image.geterror();
  ASSERT_EQ(image.spec().width, settings.width);
  ASSERT_EQ(image.spec().height, settings.height);
  std::vector<float> expected(result.image.pixels.size());
  ASSERT_TRUE(image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, expected.data()));
  int outside = 0;
  double sum = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const double difference = std::abs(double(result.image.pixels[i]) - expected[i]);
    sum += difference;
    if (difference > std::max(1e-3, 0x1p-10 * std::abs(expected[i]))) ++outside;
  }
  EXPECT_LE(outside, int(expected.size() / 100)) << "mean difference " << sum / expected.size();
}

INSTANTIATE_TEST_SUITE_P(Materials, ReferenceImagesTest,
                         ::testing::Values(Reference{"material_diffuse", render::IntegratorKind::path, 8},
                                           Reference{"material_metal", render::IntegratorKind::path, 8},
                                           Reference{"material_mirror", render::IntegratorKind::path, 8},
                                           Reference{"material_glass", render::IntegratorKind::path, 8},
                                           Reference{"whitted_all", render::IntegratorKind::whitted, 4}),
                         [](const ::testing::TestParamInfo<Reference>& info) { return info.param.name; });

}  // namespace
}  // namespace revolve
