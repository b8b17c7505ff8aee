// revolve-render's options beyond the scene, as a process: --pick writes nothing (and refuses an
// output), --exposure scales the image by 2^EV, glass that renders wrongly is named once per
// object, Whitted's default depth, the stats' record of the settings.
#include "../io/scratch_directory.h"
#include "bad_scenes.h"
#include "support/process.h"

#include <OpenImageIO/imagebuf.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using testing::kBottleCsv;
using testing::kScene;
using testing::readWholeFile;
using testing::replaced;
using testing::ScratchDirectory;

testing::ProcessResult runRender(const std::string& directory, const std::vector<std::string>& args) {
  return testing::runProcess(REVOLVE_RENDER_PATH, args, directory);
}

std::size_t lineCount(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

std::vector<float> readExr(const std::string& path) {
  OIIO::ImageBuf image(path);
  std::vector<float> pixels;
  if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
    ADD_FAILURE() << image.geterror();
    return pixels;
  }
  pixels.resize(std::size_t(image.spec().width) * image.spec().height * image.spec().nchannels);
  EXPECT_TRUE(image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data()));
  return pixels;
}

TEST(RevolveRenderOptionsTest, PickPrintsAndRefusesAnOutputItWouldNotWrite) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  const testing::ProcessResult pick = runRender(dir.path(), {"scene.json", "--pick", "4,3"});
  ASSERT_EQ(pick.status, 0) << pick.err;
  EXPECT_THAT(pick.out, HasSubstr("object 0"));
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"-o", "image.png"}, {"--stats", "stats.json"}}) {
    std::vector<std::string> args{"scene.json", "--pick", "4,3"};
    args.insert(args.end(), extra.begin(), extra.end());
    const testing::ProcessResult refused = runRender(dir.path(), args);
    EXPECT_EQ(refused.status, 1);
    EXPECT_EQ(lineCount(refused.err), 1u) << refused.err;
    EXPECT_THAT(refused.err, HasSubstr("--pick renders"));
  }
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "bottle.csv"}));
}

TEST(RevolveRenderOptionsTest, ExposureScalesTheImageByTwoToTheEv) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  ASSERT_EQ(runRender(dir.path(), {"scene.json", "-o", "plain.exr"}).status, 0);
  ASSERT_EQ(runRender(dir.path(), {"scene.json", "-o", "bright.exr", "--exposure", "1"}).status, 0);
  ASSERT_EQ(runRender(dir.path(), {"scene.json", "-o", "dark.exr", "--exposure", "-2"}).status, 0);
  const std::vector<float> plain = readExr(dir / "plain.exr"), bright = readExr(dir / "bright.exr"),
                           dark = readExr(dir / "dark.exr");
  ASSERT_EQ(plain.size(), bright.size());
  ASSERT_EQ(plain.size(), dark.size());
  int lit = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    // Powers of two scale half floats exactly (far from their range's ends).
    EXPECT_EQ(bright[i], 2 * plain[i]) << i;
    EXPECT_EQ(dark[i], plain[i] / 4) << i;
    lit += plain[i] > 0 ? 1 : 0;
  }
  EXPECT_GT(lit, 0);
}

TEST(RevolveRenderOptionsTest, GlassTheRendererCannotShowRightIsNamedOncePerObject) {
  const ScratchDirectory dir;
  // The ball listed from the top down (clockwise in (r, z)): glass on it would be a bubble.
  const std::string scene = replaced(replaced(kScene, R"("ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]})",
                                              R"("ball": {"points": [[0, 1], [0.5, 0.8], [0.5, 0.2], [0, 0]]})"),
                                     R"("materials": {"white": {"type": "diffuse", "color": [0.8, 0.8, 0.8]}})",
                                     R"("materials": {"white": {"type": "glass", "ior": 1.5}})");
  dir.write("scene.json", scene);
  dir.write("bottle.csv", kBottleCsv);
  const testing::ProcessResult run = runRender(dir.path(), {"scene.json", "-o", "image.png"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(lineCount(run.err), 1u) << run.err;  // the bottle is closed and outwards, the quad no solid
  EXPECT_THAT(run.err,
              HasSubstr("revolve-render: warning: scene.json: objects[0]: glass on profile \"ball\" runs clockwise"));
}

TEST(RevolveRenderOptionsTest, StatsRecordTheSettingsAndWhittedDefaultsToDepthEight) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  ASSERT_EQ(runRender(dir.path(), {"scene.json", "-o", "w.png", "--integrator", "whitted", "--filtered-shadows",
                                   "--stats", "w.json"})
                .status,
            0);
  const nlohmann::json whitted = nlohmann::json::parse(readWholeFile(dir / "w.json"));
  EXPECT_EQ(whitted["depth"], 8);
  EXPECT_EQ(whitted["filtered_shadows"], true);
  ASSERT_EQ(runRender(dir.path(), {"scene.json", "-o", "p.png", "--no-regularize", "--filter", "box", "--exposure",
                                   "0.5", "--stats", "p.json"})
                .status,
            0);
  const nlohmann::json path = nlohmann::json::parse(readWholeFile(dir / "p.json"));
  EXPECT_EQ(path["depth"], 8);
  EXPECT_EQ(path["regularize"], false);
  EXPECT_EQ(path["filter"], "box");
  EXPECT_EQ(path["exposure"], 0.5);
}

}  // namespace
}  // namespace revolve
