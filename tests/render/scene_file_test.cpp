// The scene reader's refusals, in process: every bad scene of bad_scenes.h must raise one
// SceneError whose message names the key path (or CSV file and line) and the rule. (The process
// test runs revolve-render on one case of each kind, for its exit status and the files it leaves.)
#include "io/scene_file.h"
#include "../io/scratch_directory.h"
#include "bad_scenes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace revolve {
namespace {

using testing::BadCase;
using ::testing::HasSubstr;
using testing::WorkingDirectory;

std::vector<BadCase> sceneCases() {
  std::vector<BadCase> cases;
  for (const BadCase& bad : testing::badCases()) {
    if (bad.extraArgs.empty()) cases.push_back(bad);  // the rest are the tool's options
  }
  return cases;
}

class SceneFileBadInputTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneFileBadInputTest, OneSceneErrorNamingWhereAndWhy) {
  const BadCase& bad = GetParam();
  const testing::ScratchDirectory dir;
  dir.write("scene.json", bad.scene);
  if (!bad.csv.empty()) dir.write("bottle.csv", bad.csv);
  const WorkingDirectory inside(dir.path());
  try {
    io::readScene("scene.json");
    ADD_FAILURE() << "no error";
  } catch (const io::SceneError& error) {
    EXPECT_THAT(error.what(), HasSubstr(bad.expected));
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "one line";
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, SceneFileBadInputTest, ::testing::ValuesIn(sceneCases()),
                         [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(SceneFileTest, TheValidSceneReadsWithEveryPart) {
  const testing::ScratchDirectory dir;
  dir.write("scene.json", testing::kScene);
  dir.write("bottle.csv", testing::kBottleCsv);
  const WorkingDirectory inside(dir.path());
  const io::SceneDescription scene = io::readScene("scene.json");
  EXPECT_EQ(scene.profiles.size(), 2u);
  EXPECT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[1].profile, 1u);  // "bottle", from the CSV
  EXPECT_EQ(scene.quads.size(), 1u);
  EXPECT_EQ(scene.lights.size(), 1u);
}

// "reflectivity" (what a lidar's intensity scales by) on objects and quads: 1 unless given, the
// edges 0 and 1 taken.
TEST(SceneFileTest, ReflectivitiesDefaultToOneAndTakeTheirEdges) {
  const testing::ScratchDirectory dir;
  std::string text = testing::replaced(testing::kScene, R"({"profile": "ball", "material": "white"})",
                                       R"({"profile": "ball", "material": "white", "reflectivity": 0})");
  text = testing::replaced(text, R"("material": "white"}],)", R"("material": "white", "reflectivity": 0.25}],)");
  dir.write("scene.json", text);
  dir.write("bottle.csv", testing::kBottleCsv);
  const WorkingDirectory inside(dir.path());
  const io::SceneDescription scene = io::readScene("scene.json");
  EXPECT_EQ(scene.objects[0].reflectivity, 0.0);
  EXPECT_EQ(scene.objects[1].reflectivity, 1.0);
  EXPECT_EQ(scene.quads[0].reflectivity, 0.25);
}

// Directions read from the file are scaled by their largest component before they are normalised,
// so that one of 1e-200 (or a subnormal) is as good as one of 1: rotation axes, the camera's up,
// the sun's direction.
TEST(SceneFileTest, TinyDirectionsNormaliseAsUnitOnes) {
  std::string text = testing::replaced(testing::kScene, "[1, 0, 0, 10]", "[1e-200, 0, 0, 10]");
  text = testing::replaced(text, R"("up": [0, 0, 1])", R"("up": [0, 0, 5e-324])");
  text = testing::replaced(text, R"("direction": [0, 0.3, -1])", R"("direction": [0, 3e-301, -1e-300])");
  text = testing::replaced(text, R"("profile": "ball", "material": "white")",
                           R"("profile": "ball", "material": "white", "rotate": [1e300, 1e300, 0, 90])");
  const testing::ScratchDirectory dir;
  dir.write("bottle.csv", testing::kBottleCsv);
  const io::SceneDescription scene = io::parseScene(text, "scene.json", dir.path().string());
  EXPECT_EQ(scene.objects[1].transform.rotateAxis, (app::Vec3d{1, 0, 0}));
  EXPECT_EQ(scene.camera.up, (app::Vec3d{0, 0, 1}));
  const double n = std::sqrt(0.3 * 0.3 + 1);
  EXPECT_NEAR(scene.lights[0].direction[1], 0.3 / n, 1e-15);
  EXPECT_NEAR(scene.lights[0].direction[2], -1 / n, 1e-15);
  EXPECT_NEAR(scene.objects[0].transform.rotateAxis[0], std::sqrt(0.5), 1e-15);  // 1e300 squared would overflow
  EXPECT_NEAR(scene.objects[0].transform.rotateAxis[1], std::sqrt(0.5), 1e-15);
}

// The limits at their edges: 2^40 is a position, a hair beyond is not; 2^-16 and 2^40 are scales.
TEST(SceneFileTest, TheLimitsAcceptTheirEdges) {
  std::string text = testing::replaced(testing::kScene, R"("from": [0, -3, 1])", R"("from": [0, -1099511627776, 1])");
  text = testing::replaced(text, R"("scale": 0.5)", R"("scale": [1.52587890625e-05, 1, 1])");
  const testing::ScratchDirectory dir;
  dir.write("bottle.csv", testing::kBottleCsv);
  const std::string folder = dir.path().string();
  EXPECT_EQ(io::parseScene(text, "scene.json", folder).objects.size(), 2u);
  EXPECT_THROW(io::parseScene(testing::replaced(text, "-1099511627776", "-1099511627777"), "scene.json", folder),
               io::SceneError);
  EXPECT_THROW(io::parseScene(testing::replaced(text, "1.52587890625e-05", "1.5258789e-05"), "scene.json", folder),
               io::SceneError);
}

TEST(SceneFileTest, SplineProfilesReadExactOrAsPolylines) {
  // The ball's points as a cubic Bezier piece: traced exactly, or as a polyline within a tolerance.
  const testing::ScratchDirectory dir;
  std::string scene = testing::replaced(testing::kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )");
  scene =
      testing::replaced(scene, R"("bottle": {"csv")", R"("bottle": {"spline": "natural", "tolerance": 0.001, "csv")");
  dir.write("scene.json", scene);
  dir.write("bottle.csv", testing::kBottleCsv);
  const WorkingDirectory inside(dir.path());
  const io::SceneDescription read = io::readScene("scene.json");
  const io::SceneProfile& ball = read.profiles[0];
  ASSERT_TRUE(ball.spline.has_value());
  EXPECT_EQ(ball.spline->kind(), SplineKind::bezier);
  EXPECT_EQ(ball.tolerance, 0);
  // Its polyline for the tools that need one, within 1e-5 of the curve's size: its vertices lie on
  // the cubic, r(u) = 1.5 u (1 - u) (controls 0, 0.5, 0.5, 0) where z(u) = 0.6 u + 1.2 u^2 - 0.8 u^3.
  EXPECT_GT(ball.polyline().points().size(), 10u);
  for (const Point2& p : ball.polyline().points()) {
    double lo = 0, hi = 1;  // z is increasing: the vertex's u by bisection
    for (int i = 0; i < 100; ++i) {
      const double u = 0.5 * (lo + hi);
      (0.6 * u + 1.2 * u * u - 0.8 * u * u * u < p.z ? lo : hi) = u;
    }
    EXPECT_NEAR(p.r, 1.5 * lo * (1 - lo), 1e-12);
  }
  const io::SceneProfile& bottle = read.profiles[1];
  EXPECT_FALSE(bottle.spline.has_value());
  EXPECT_EQ(bottle.tolerance, 0.001);
  EXPECT_EQ(bottle.polyline().points().front().r, 0.0);
  EXPECT_EQ(bottle.polyline().points().back().z, 1.0);
  // A natural spline through 6 points with corners rounded: more points than its own 6.
  EXPECT_GT(bottle.polyline().points().size(), 6u);
}

// Reading a spline traced exactly draws no polyline (the exact build never reads one): it is drawn
// when a tool first asks, from any thread, once, and is Profile::fromCurve of the spline within
// kDrawingFraction of its largest coordinate, computed here again.
TEST(SceneFileTest, AnExactSplineIsDrawnOnlyWhenAsked) {
  const testing::ScratchDirectory dir;
  dir.write("scene.json", testing::replaced(testing::kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )"));
  dir.write("bottle.csv", testing::kBottleCsv);
  const WorkingDirectory inside(dir.path());
  const io::SceneDescription read = io::readScene("scene.json");
  const io::SceneProfile& ball = read.profiles[0];
  ASSERT_TRUE(ball.spline.has_value());
  EXPECT_FALSE(ball.profile.has_value());
  EXPECT_FALSE(ball.drawing->polyline.has_value());
  const io::SceneProfile copy = ball;  // a copy shares the one drawing

  double size = 0;
  for (const Point2& p : ball.spline->bezier()) size = std::max({size, std::abs(p.r), std::abs(p.z)});
  const Profile expected = Profile::fromCurve(*ball.spline, 1e-5 * size);

  std::vector<const Profile*> drawn(4, nullptr);
  {
    std::vector<std::jthread> askers;
    for (std::size_t i = 0; i < drawn.size(); ++i) askers.emplace_back([&, i] { drawn[i] = &ball.polyline(); });
  }
  for (const Profile* p : drawn) EXPECT_EQ(p, drawn[0]);  // drawn once
  EXPECT_EQ(&copy.polyline(), drawn[0]);
  const std::span<const Point2> a = drawn[0]->points(), b = expected.points();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(a[k].r == b[k].r && a[k].z == b[k].z) << k;
  const std::span<const double> ta = drawn[0]->curveParameters(), tb = expected.curveParameters();
  EXPECT_TRUE(std::equal(ta.begin(), ta.end(), tb.begin(), tb.end()));

  // A polyline profile is its own polyline.
  const io::SceneProfile& bottle = read.profiles[1];
  ASSERT_TRUE(bottle.profile.has_value());
  EXPECT_EQ(&bottle.polyline(), &*bottle.profile);
}

// A scene rebuilt from texts alone (what a Python pickle of a Scene holds): the texts readScene
// kept give the same description where the files are not, and a CSV missing from them, or bad in
// them, is refused naming the file as reading it from disk would.
TEST(SceneFileTest, SuppliedTextsRebuildTheSceneWithoutItsFiles) {
  std::string text;
  io::FileTexts csvs;
  io::SceneDescription read;
  {
    const testing::ScratchDirectory dir;
    dir.write("scene.json", testing::kScene);
    dir.write("bottle.csv", testing::kBottleCsv);
    const WorkingDirectory inside(dir.path());
    read = io::readScene("scene.json", text, csvs);
  }
  EXPECT_EQ(text, testing::kScene);
  ASSERT_EQ(csvs.texts.size(), 1u);
  EXPECT_EQ(csvs.texts.begin()->first, "bottle.csv");
  EXPECT_EQ(csvs.texts.begin()->second, testing::kBottleCsv);

  const testing::ScratchDirectory empty;  // neither file is here
  const WorkingDirectory inside(empty.path());
  io::FileTexts supplied{csvs.texts, false};
  const io::SceneDescription rebuilt = io::parseScene(text, "scene.json", "", supplied);
  ASSERT_EQ(rebuilt.profiles.size(), read.profiles.size());
  for (std::size_t i = 0; i < read.profiles.size(); ++i) {
    const auto a = read.profiles[i].polyline().points(), b = rebuilt.profiles[i].polyline().points();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].r, b[k].r);
      EXPECT_EQ(a[k].z, b[k].z);
    }
    EXPECT_EQ(rebuilt.profiles[i].csvFile, read.profiles[i].csvFile);
  }

  io::FileTexts none{{}, false};
  try {
    (void)io::parseScene(text, "scene.json", "", none);
    ADD_FAILURE() << "no error";
  } catch (const io::SceneError& error) {
    EXPECT_THAT(error.what(), HasSubstr("bottle.csv: not among the files supplied"));
  }
  io::FileTexts bad{{{"bottle.csv", "r,z\n0,0\n0.3,x\n"}}, false};
  try {
    (void)io::parseScene(text, "scene.json", "", bad);
    ADD_FAILURE() << "no error";
  } catch (const io::SceneError& error) {
    EXPECT_THAT(error.what(), HasSubstr("bottle.csv:3"));
  }
}

}  // namespace
}  // namespace revolve
