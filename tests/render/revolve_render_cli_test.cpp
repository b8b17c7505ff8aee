// revolve-render as its users see it: a process given a scene file and options, judged by its exit
// status, its stderr and the files it leaves. Every bad input must give one line on stderr naming
// where the problem is (JSON key path, or CSV file and line) and the rule, a non-zero exit, no
// image, and leave an existing image untouched.
#include "../io/scratch_directory.h"
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
using ::testing::StartsWith;
using testing::ScratchDirectory;
using testing::readWholeFile;

using Result = testing::ProcessResult;

// Runs revolve-render in `directory`; its stdout and stderr go to a capture directory of their own
// so that `directory` holds only what the tool made.
Result runRender(const std::string& directory, const std::vector<std::string>& args) {
  return testing::runProcess(REVOLVE_RENDER_PATH, args, directory);
}

// A small valid scene: an inline profile and one from a CSV beside it.
const std::string kScene = R"({
  "camera": {"from": [0, -3, 1], "to": [0, 0, 0.5], "up": [0, 0, 1], "fov": 40, "width": 8, "height": 6, "spp": 2},
  "profiles": {
    "ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]},
    "bottle": {"csv": "bottle.csv"}
  },
  "materials": {"white": {"type": "diffuse", "color": [0.8, 0.8, 0.8]}},
  "objects": [
    {"profile": "ball", "material": "white"},
    {"profile": "bottle", "material": "white", "translate": [1, 0, 0], "rotate": [1, 0, 0, 10], "scale": 0.5}
  ],
  "quads": [{"corners": [[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], "material": "white"}],
  "lights": [{"type": "sun", "direction": [0, 0.3, -1], "irradiance": [1, 1, 1]}],
  "environment": {"color": [0.2, 0.2, 0.2]}
})";
const std::string kBottleCsv = "r,z\n0,0\n0.3,0\n0.3,0.6\n0.1,0.8\n0.1,1\n0,1\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::size_t lineCount(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(RevolveRenderCliTest, RendersPngAndExrOfTheRequestedSizeAndWritesStats) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  const Result png = runRender(dir.path(), {"scene.json", "-o", "image.png", "--stats", "stats.json"});
  ASSERT_EQ(png.status, 0) << png.err;
  OIIO::ImageBuf image(dir / "image.png");
  ASSERT_TRUE(image.read()) << image.geterror();
  EXPECT_EQ(image.spec().width, 8);
  EXPECT_EQ(image.spec().height, 6);
  EXPECT_EQ(image.spec().format, OIIO::TypeDesc::UINT8);
  const nlohmann::json stats = nlohmann::json::parse(readWholeFile(dir / "stats.json"));
  EXPECT_EQ(stats["rays"]["camera"], 8 * 6 * 2);  // width x height x spp
  EXPECT_GT(stats["mibit"]["quadratics"].get<long>(), 0);
  EXPECT_GT(stats["memory"]["revolve_bytes"].get<long>(), 0);
  EXPECT_GT(stats["memory"]["embree_bytes"].get<long>(), 0);

  const Result exr = runRender(dir.path(), {"scene.json", "-o", "image.exr", "--width", "5", "--height", "4", "--spp", "1"});
  ASSERT_EQ(exr.status, 0) << exr.err;
  OIIO::ImageBuf linear(dir / "image.exr");
  ASSERT_TRUE(linear.read()) << linear.geterror();
  EXPECT_EQ(linear.spec().width, 5);
  EXPECT_EQ(linear.spec().format, OIIO::TypeDesc::HALF);
  // Nothing else was left behind (no temporary files).
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "bottle.csv", "image.png", "image.exr", "stats.json"}));
}

struct BadCase {
  const char* name;
  std::string scene;                  // the scene file's text
  std::vector<std::string> extraArgs;  // after the scene; "-o old.png" unless they name an output
  std::string expected;               // a substring of the one stderr line
  std::string csv = kBottleCsv;       // bottle.csv's text ("" = no file)
};

std::vector<BadCase> badCases() {
  return {
      {"MissingKey", replaced(kScene, R"("fov": 40, )", ""), {}, R"(scene.json: camera: missing key "fov")"},
      {"WrongType", replaced(kScene, R"("fov": 40)", R"("fov": "wide")"), {}, "scene.json: camera.fov: expected a number, found string"},
      {"UnknownProfileName", replaced(kScene, R"("profile": "bottle")", R"("profile": "botle")"), {},
       R"(scene.json: objects[1].profile: no profile named "botle")"},
      {"UnknownMaterialName", replaced(kScene, R"("profile": "ball", "material": "white")", R"("profile": "ball", "material": "paper")"), {},
       R"(objects[0].material: no material named "paper")"},
      {"UnknownKey", replaced(kScene, R"("color": [0.8, 0.8, 0.8])", R"("colour": [0.8, 0.8, 0.8])"), {},
       "materials.white.colour: unknown key; expected one of: type, color"},
      {"UnknownTopLevelKey", replaced(kScene, R"("lights")", R"("lightz")"), {}, "scene.json: lightz: unknown key"},
      {"SelfIntersectingProfile", replaced(kScene, "[0.5, 0.8], [0, 1]", "[0.5, 0.8], [0.7, 0.1], [0, 1]"), {},
       "profiles.ball.points[1]: the segment from profile point 1"},
      {"NegativeRadius", replaced(kScene, "[0.5, 0.2]", "[-0.5, 0.2]"), {}, "profiles.ball.points[1]: profile point 1 (r = -0.5"},
      {"BadCsvLine", kScene, {}, "profiles.bottle.csv: bottle.csv:3: r = \"abc\" is not a number", "r,z\n0,0\nabc,0\n0,1\n"},
      {"MissingCsv", kScene, {}, "profiles.bottle.csv: bottle.csv:0: cannot open", ""},
      {"BadCsvProfile", kScene, {}, "profiles.bottle.csv: bottle.csv:3: profile point 1 (r = -1", "r,z\n0,0\n-1,0\n0,1\n"},
      {"InvalidJson", kScene.substr(0, 200), {}, "scene.json: not valid JSON: parse error at line"},
      {"RepeatedKey", replaced(kScene, R"("fov": 40)", R"("fov": 40, "fov": 50)"), {}, R"(key "fov" appears twice)"},
      {"UnknownMaterialType", replaced(kScene, R"("type": "diffuse")", R"("type": "plastic")"), {},
       R"(materials.white.type: "plastic" is not a material type)"},
      {"ReflectanceAboveOne", replaced(kScene, "[0.8, 0.8, 0.8]", "[1.5, 0.8, 0.8]"), {},
       "materials.white.color[0]: 1.5 is out of range: a reflectance lies in [0, 1]"},
      {"ZeroRotationAxis", replaced(kScene, "[1, 0, 0, 10]", "[0, 0, 0, 10]"), {}, "objects[1].rotate: the rotation axis is zero"},
      {"NegativeScale", replaced(kScene, R"("scale": 0.5)", R"("scale": -0.5)"), {}, "objects[1].scale: -0.5 is not positive"},
      {"DegenerateQuad", replaced(kScene, "[5, 5, 0], [-5, 5, 0]", "[5, -5, 0], [-5, 5, 0]"), {}, "quads[0].corners: corners 0, 1 and 2 are collinear"},
      {"UpAlongTheView", replaced(kScene, R"("up": [0, 0, 1])", R"("up": [0, 3, -0.5])"), {}, "camera.up: is parallel to the view direction"},
      {"UnknownLightType", replaced(kScene, R"("type": "sun")", R"("type": "spot")"), {}, R"(lights[0].type: "spot" is not a light type)"},
      {"SunAngleTooWide", replaced(kScene, R"("irradiance": [1, 1, 1])", R"("irradiance": [1, 1, 1], "angle": 90)"), {},
       "lights[0].angle: 90 is out of range"},
      {"ObjectsNotAList", replaced(kScene, R"("objects": [)", R"("objects": {"a": )"), {}, "not valid JSON"},
      {"UnwritableOutput", kScene, {"-o", "no/such/folder/out.png"}, "no/such/folder/out.png: cannot create a file in no/such/folder"},
      {"UnknownImageExtension", kScene, {"-o", "out.jpg"}, R"(out.jpg: unsupported image extension ".jpg")"},
      {"UnwritableStats", kScene, {"--stats", "no/such/stats.json"}, "no/such/stats.json: cannot create a file"},
  };
}

class RevolveRenderBadInputTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(RevolveRenderBadInputTest, OneLineNonZeroExitNoImageAndTheOldImageUntouched) {
  const BadCase& bad = GetParam();
  const ScratchDirectory dir;
  dir.write("scene.json", bad.scene);
  if (!bad.csv.empty()) dir.write("bottle.csv", bad.csv);
  dir.write("old.png", "an existing image");
  const std::set<std::string> before = dir.entries();
  std::vector<std::string> args{"scene.json"};
  if (std::find(bad.extraArgs.begin(), bad.extraArgs.end(), "-o") == bad.extraArgs.end()) {
    args.insert(args.end(), {"-o", "old.png"});
  }
  args.insert(args.end(), bad.extraArgs.begin(), bad.extraArgs.end());
  const Result result = runRender(dir.path(), args);
  EXPECT_NE(result.status, 0);
  EXPECT_LT(result.status, 128) << "crashed";
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_THAT(result.err, StartsWith("revolve-render: "));
  EXPECT_THAT(result.err, HasSubstr(bad.expected));
  EXPECT_EQ(readWholeFile(dir / "old.png"), "an existing image");
  EXPECT_EQ(dir.entries(), before) << "no image, no temporary file";
}

INSTANTIATE_TEST_SUITE_P(Cases, RevolveRenderBadInputTest, ::testing::ValuesIn(badCases()),
                         [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(RevolveRenderCliTest, MissingSceneFileIsOneLine) {
  const ScratchDirectory dir;
  const Result result = runRender(dir.path(), {"absent.json", "-o", "out.png"});
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_THAT(result.err, HasSubstr("absent.json:0: cannot open"));
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace revolve
