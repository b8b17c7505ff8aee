// The scene reader's refusals, in process: every bad scene of bad_scenes.h must raise one
// SceneError whose message names the key path (or CSV file and line) and the rule. (The process
// test runs revolve-render on one case of each kind, for its exit status and the files it leaves.)
#include "bad_scenes.h"
#include "io/scene_file.h"
#include "../io/scratch_directory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using testing::BadCase;

// Runs in `directory` for the scope, so that the scene's relative CSV paths read as the tool's do.
class WorkingDirectory {
 public:
  explicit WorkingDirectory(const std::filesystem::path& directory) : previous_(std::filesystem::current_path()) {
    std::filesystem::current_path(directory);
  }
  ~WorkingDirectory() { std::filesystem::current_path(previous_); }

 private:
  std::filesystem::path previous_;
};

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

}  // namespace
}  // namespace revolve
