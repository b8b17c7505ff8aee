// revolve-render as its users see it: a process given a scene file and options, judged by its exit
// status, its stderr and the files it leaves. Every bad input must give one line on stderr naming
// where the problem is (JSON key path, or CSV file and line) and the rule, a non-zero exit, no
// image, and leave an existing image untouched.
#include "../io/scratch_directory.h"
#include "bad_scenes.h"
#include "support/process.h"

#include <OpenImageIO/imagebuf.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace revolve {
namespace {

using testing::BadCase;
using ::testing::HasSubstr;
using testing::kBottleCsv;
using testing::kScene;
using testing::readWholeFile;
using testing::replaced;
using testing::ScratchDirectory;
using ::testing::StartsWith;

using Result = testing::ProcessResult;

// Runs revolve-render in `directory`; its stdout and stderr go to a capture directory of their own
// so that `directory` holds only what the tool made.
Result runRender(const std::string& directory, const std::vector<std::string>& args) {
  return testing::runProcess(REVOLVE_RENDER_PATH, args, directory);
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

  const Result exr =
      runRender(dir.path(), {"scene.json", "-o", "image.exr", "--width", "5", "--height", "4", "--spp", "1"});
  ASSERT_EQ(exr.status, 0) << exr.err;
  OIIO::ImageBuf linear(dir / "image.exr");
  ASSERT_TRUE(linear.read()) << linear.geterror();
  EXPECT_EQ(linear.spec().width, 5);
  EXPECT_EQ(linear.spec().format, OIIO::TypeDesc::HALF);
  // Nothing else was left behind (no temporary files).
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "bottle.csv", "image.png", "image.exr", "stats.json"}));
}

// --stats says where the render's time went: a share for each phase, each in [0, 1], summing to 1
// (every moment of a tile is charged to exactly one phase; 1e-9 covers the rounding of four double
// divisions and their sum). Without shadow rays (whitted --no-shadows) the shadows' share is 0;
// with path tracing, whose every diffuse hit sends one, it is not; every render traces and draws.
TEST(RevolveRenderCliTest, StatsSayWhereTheTimeGoes) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  const auto shares = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"scene.json", "-o", "image.png", "--stats", "stats.json", "--spp", "4"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result run = runRender(dir.path(), args);
    EXPECT_EQ(run.status, 0) << run.err;
    return nlohmann::json::parse(readWholeFile(dir / "stats.json"))["time_shares"];
  };
  for (const auto& extra : {std::vector<std::string>{}, {"--integrator", "whitted", "--no-shadows"}}) {
    const nlohmann::json time = shares(extra);
    double sum = 0;
    for (const char* key : {"intersection", "shadows", "sampling", "shading"}) {
      ASSERT_TRUE(time.contains(key)) << key;
      const double share = time[key].get<double>();
      EXPECT_GE(share, 0.0) << key;
      EXPECT_LE(share, 1.0) << key;
      sum += share;
    }
    EXPECT_NEAR(sum, 1.0, 1e-9);
    EXPECT_EQ(time.size(), 4u);
    EXPECT_GT(time["intersection"].get<double>(), 0.0);
    EXPECT_GT(time["sampling"].get<double>(), 0.0);
    if (extra.empty())
      EXPECT_GT(time["shadows"].get<double>(), 0.0);
    else
      EXPECT_EQ(time["shadows"].get<double>(), 0.0);
  }
}

// Embree's own linear cone curve in place of revolve's geometry, for the scenes it can express.
TEST(RevolveRenderCliTest, RendersWithEmbreeConeCurves) {
  const ScratchDirectory dir;
  dir.write("scene.json", testing::replaced(kScene, R"(, "scale": 0.5)", ""));
  dir.write("bottle.csv", kBottleCsv);
  const Result cone =
      runRender(dir.path(), {"scene.json", "-o", "image.png", "--geometry", "embree-cone", "--stats", "stats.json"});
  ASSERT_EQ(cone.status, 0) << cone.err;
  OIIO::ImageBuf image(dir / "image.png");
  ASSERT_TRUE(image.read()) << image.geterror();
  EXPECT_EQ(image.spec().width, 8);
  const nlohmann::json stats = nlohmann::json::parse(readWholeFile(dir / "stats.json"));
  EXPECT_EQ(stats["geometry"], "embree-cone");
  EXPECT_GT(stats["memory"]["revolve_bytes"].get<long>(), 0);  // the shading normals
  EXPECT_EQ(stats["mibit"]["queries"].get<long>(), 0);         // no revolve geometry traced
}

TEST(RevolveRenderCliTest, ToleranceTracesSplinesAsPolylinesWithinThePixelFootprint) {
  // The ball as one cubic Bezier piece (its widest radius 0.375 at z = 0.5). Seen by the camera at
  // (0, -3, 1) with a 40-degree field over 60 rows, the nearest point of its bounding sphere (centre
  // (0, 0, 0.5), radius hypot(0.375, 0.5)) lies hypot(3, 0.5) - 0.625 away, where a pixel spans
  // that distance times 2 tan(20 degrees) / 60.
  const ScratchDirectory dir;
  dir.write("scene.json", testing::replaced(kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )"));
  dir.write("bottle.csv", kBottleCsv);
  const Result result = runRender(dir.path(), {"scene.json", "-o", "image.png", "--width", "80", "--height", "60",
                                               "--spp", "1", "--tolerance", "pixel", "--stats", "stats.json"});
  ASSERT_EQ(result.status, 0) << result.err;
  const nlohmann::json stats = nlohmann::json::parse(readWholeFile(dir / "stats.json"));
  ASSERT_EQ(stats["curves_as_polylines"].size(), 1u);  // the bottle is a polyline already
  const nlohmann::json& ball = stats["curves_as_polylines"][0];
  EXPECT_EQ(ball["profile"], "ball");
  const double footprint = (std::hypot(3.0, 0.5) - std::hypot(0.375, 0.5)) * 2 * std::tan(20 * M_PI / 180) / 60;
  EXPECT_NEAR(ball["tolerance"].get<double>(), footprint, 1e-4 * footprint);
  EXPECT_GE(ball["points"].get<int>(), 3);
  // A number is a tolerance in the profile's units.
  const Result fixed = runRender(dir.path(), {"scene.json", "-o", "image.png", "--width", "8", "--height", "6", "--spp",
                                              "1", "--tolerance", "0.001", "--stats", "stats.json"});
  ASSERT_EQ(fixed.status, 0) << fixed.err;
  EXPECT_EQ(nlohmann::json::parse(readWholeFile(dir / "stats.json"))["curves_as_polylines"][0]["tolerance"], 0.001);
}

// The 8-bit sRGB pixels of a PNG.
std::vector<unsigned char> pngPixels(const std::string& path, int& width, int& height) {
  OIIO::ImageBuf image(path);
  std::vector<unsigned char> pixels;
  if (!image.read(0, 0, true, OIIO::TypeDesc::UINT8)) return pixels;
  width = image.spec().width, height = image.spec().height;
  pixels.resize(std::size_t(width) * height * 3);
  image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, pixels.data());
  return pixels;
}

// --tolerance pixel keeps every silhouette within a pixel of the curve's, so an image of the
// polylines may differ from the exact one where the exact image has an edge nearby, and nowhere
// else: wherever no pixel within two of it differs by more than 16/255 in a channel (a smooth
// region), the two images must agree within 32/255. With normals interpolated between the chords,
// the glazed vase of scenes/spline_still_life.json under Whitted moved its highlights: 59 smooth
// pixels differed by up to 135/255 at this size.
TEST(RevolveRenderCliTest, ToleranceByThePixelShadesWithTheCurvesNormalsAndLooksLikeTheExactRender) {
  nlohmann::json scene =
      nlohmann::json::parse(readWholeFile(std::string(REVOLVE_SOURCE_DIR) + "/scenes/spline_still_life.json"));
  nlohmann::json objects = nlohmann::json::array(), profiles = nlohmann::json::object();
  for (const nlohmann::json& object : scene["objects"]) {
    if (object["name"] == "vase" || object["name"] == "table") {
      objects.push_back(object);
      profiles[object["profile"].get<std::string>()] = scene["profiles"][object["profile"].get<std::string>()];
    }
  }
  scene["objects"] = objects;
  scene["profiles"] = profiles;
  const ScratchDirectory dir;
  dir.write("vase.json", scene.dump());
  const std::vector<std::string> common{"vase.json", "--integrator", "whitted", "--width", "320",
                                        "--height",  "210",          "--spp",   "4"};
  std::vector<std::string> exact = common, pixel = common;
  exact.insert(exact.end(), {"-o", "exact.png"});
  pixel.insert(pixel.end(), {"-o", "pixel.png", "--tolerance", "pixel", "--stats", "stats.json"});
  for (const auto& args : {exact, pixel}) {
    const Result run = runRender(dir.path(), args);
    ASSERT_EQ(run.status, 0) << run.err;
  }
  const nlohmann::json stats = nlohmann::json::parse(readWholeFile(dir / "stats.json"));
  ASSERT_EQ(stats["curves_as_polylines"].size(), 1u);
  EXPECT_LT(stats["curves_as_polylines"][0]["points"].get<int>(), 40) << "a coarse polyline, or the test shows nothing";
  int width = 0, height = 0, w2 = 0, h2 = 0;
  const std::vector<unsigned char> a = pngPixels(dir / "exact.png", width, height),
                                   b = pngPixels(dir / "pixel.png", w2, h2);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  const auto at = [&](const std::vector<unsigned char>& image, int x, int y, int c) {
    return int(image[(std::size_t(y) * width + x) * 3 + c]);
  };
  int smooth = 0, differing = 0, worst = 0;
  for (int y = 2; y < height - 2; ++y) {
    for (int x = 2; x < width - 2; ++x) {
      bool flat = true;
      for (int dy = -2; dy <= 2 && flat; ++dy) {
        for (int dx = -2; dx <= 2 && flat; ++dx) {
          for (int c = 0; c < 3; ++c) flat = flat && std::abs(at(a, x + dx, y + dy, c) - at(a, x, y, c)) <= 16;
        }
      }
      if (!flat) continue;
      ++smooth;
      int difference = 0;
      for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(at(a, x, y, c) - at(b, x, y, c)));
      worst = std::max(worst, difference);
      differing += difference > 32;
    }
  }
  EXPECT_GT(smooth, width * height / 2) << "most of the image is smooth";
  EXPECT_EQ(differing, 0) << "smooth pixels differing by more than 32/255 (worst " << worst << ")";
}

// A tolerance of a pixel always exists: the still life from a view a pixel high, from 10^6 units
// away (every object far below a pixel: a curve whose polyline would collapse onto the axis stays
// exact, the others keep at least their corners),
// and at 160 x 105 (the wine glass's foot and bowl come closer than two pixels' footprint: its
// chords are refined rather than refused).
TEST(RevolveRenderCliTest, ToleranceByThePixelRendersEveryValidScene) {
  const std::string stillLife = std::string(REVOLVE_SOURCE_DIR) + "/scenes/spline_still_life.json";
  nlohmann::json far = nlohmann::json::parse(readWholeFile(stillLife));
  far["camera"]["from"] = {0.05, -1e6, 1.12};
  const ScratchDirectory dir;
  dir.write("far.json", far.dump());
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{stillLife, "--width", "160", "--height", "105"},
        std::vector<std::string>{stillLife, "--width", "1", "--height", "1"},
        std::vector<std::string>{"far.json", "--width", "200", "--height", "150"}}) {
    std::vector<std::string> run = args;
    run.insert(run.end(), {"--spp", "1", "--tolerance", "pixel", "-o", "image.png", "--stats", "stats.json"});
    SCOPED_TRACE(args[0] + " " + args[2] + " x " + args[4]);
    const Result result = runRender(dir.path(), run);
    EXPECT_EQ(result.status, 0) << result.err;
    // Nor a warning: a polyline collapsed onto the axis would be warned of as an object nothing hits.
    EXPECT_EQ(result.err.find("warning"), std::string::npos) << result.err;
  }
}

class RevolveRenderBadInputTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(RevolveRenderBadInputTest, OneLineNonZeroExitNoImageAndTheOldImageUntouched) {
  const BadCase& bad = GetParam();
  const ScratchDirectory dir;
  dir.write("scene.json", bad.scene);
  if (!bad.csv.empty()) dir.write("bottle.csv", bad.csv);
  dir.write("old.png", "an existing image");
  const std::set<std::string> before = dir.entries();
  const std::string sceneBefore = readWholeFile(dir / "scene.json");
  std::vector<std::string> args{"scene.json"};
  if (std::find(bad.extraArgs.begin(), bad.extraArgs.end(), "-o") == bad.extraArgs.end()) {
    args.insert(args.end(), {"-o", "old.png"});
  }
  args.insert(args.end(), bad.extraArgs.begin(), bad.extraArgs.end());
  const Result result = runRender(dir.path(), args);
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_THAT(result.err, StartsWith("revolve-render: "));
  EXPECT_THAT(result.err, HasSubstr(bad.expected));
  EXPECT_EQ(readWholeFile(dir / "old.png"), "an existing image");
  EXPECT_EQ(readWholeFile(dir / "scene.json"), sceneBefore) << "an input was overwritten";
  if (!bad.csv.empty()) {
    EXPECT_EQ(readWholeFile(dir / "bottle.csv"), bad.csv) << "an input was overwritten";
  }
  EXPECT_EQ(dir.entries(), before) << "no image, no temporary file";
}

std::vector<BadCase> processCases() {
  std::vector<BadCase> cases;
  for (const BadCase& bad : testing::badCases()) {
    if (bad.process) cases.push_back(bad);
  }
  return cases;
}

// Each process start costs half a second (OpenImageIO's hundreds of shared libraries), two under
// the sanitizers: the tool runs on one case of each kind; scene_file_test.cpp checks every
// message of the reader in process.
INSTANTIATE_TEST_SUITE_P(Cases, RevolveRenderBadInputTest, ::testing::ValuesIn(processCases()),
                         [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(RevolveRenderCliTest, ExportPovWritesTheSdlAndRendersOnlyWithAnOutput) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  const Result exported = runRender(dir.path(), {"scene.json", "--export-pov", "scene.pov"});
  ASSERT_EQ(exported.status, 0) << exported.err;
  EXPECT_EQ(exported.err, "") << "everything in this scene maps to POV-Ray exactly";
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "bottle.csv", "scene.pov"})) << "no image without -o";
  const std::string sdl = readWholeFile(dir / "scene.pov");
  EXPECT_GT(std::count(sdl.begin(), sdl.end(), '\n'), 20);
  EXPECT_THAT(sdl, HasSubstr("lathe {"));

  const Result both = runRender(dir.path(), {"scene.json", "--export-pov", "again.pov", "-o", "image.png"});
  ASSERT_EQ(both.status, 0) << both.err;
  EXPECT_EQ(readWholeFile(dir / "again.pov"), sdl);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "bottle.csv", "scene.pov", "again.pov", "image.png"}));

  // What maps only approximately is said on stderr, one warning a line, and the file is still written.
  dir.write("metal.json", replaced(kScene, R"({"type": "diffuse", "color": [0.8, 0.8, 0.8]})",
                                   R"({"type": "metal", "color": [0.8, 0.8, 0.8], "roughness": 0.4})"));
  const Result metal = runRender(dir.path(), {"metal.json", "--export-pov", "metal.pov"});
  ASSERT_EQ(metal.status, 0) << metal.err;
  EXPECT_EQ(metal.err,
            "revolve-render: warning: metal.pov: materials.white: metal of roughness 0.4 has no POV-Ray equivalent "
            "(no microfacet lobe); written as a mirror of its colour with a Blinn highlight\n");
}

TEST(RevolveRenderCliTest, StatsWithAnExportAloneIsAnError) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("bottle.csv", kBottleCsv);
  const Result result = runRender(dir.path(), {"scene.json", "--export-pov", "scene.pov", "--stats", "stats.json"});
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(result.err,
            "revolve-render: --stats: --export-pov without -o renders nothing to report; add -o to render as well\n");
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "bottle.csv"}));
}

TEST(RevolveRenderCliTest, MissingSceneFileIsOneLine) {
  const ScratchDirectory dir;
  const Result result = runRender(dir.path(), {"absent.json", "-o", "out.png"});
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_THAT(result.err, HasSubstr("absent.json: cannot open"));
  EXPECT_THAT(result.err, ::testing::Not(HasSubstr(":0")));  // a whole-file problem has no line
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace revolve
