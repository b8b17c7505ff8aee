// Glass objects whose profile is open or runs the wrong way are named in a warning, once per
// object; closed profiles listed from the axis at the bottom up the outside, and other materials,
// are not.
#include "render/glass_checks.h"
#include "io/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace revolve {
namespace {

using ::testing::HasSubstr;

io::SceneDescription scene(const std::string& objects) {
  return io::parseScene(R"({"camera": {"from": [0, -5, 1], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 40},
      "profiles": {"solid": {"points": [[0, 0], [1, 0], [1, 1], [0, 1]]},
                   "bubble": {"points": [[0, 1], [1, 1], [1, 0], [0, 0]]},
                   "sheet": {"points": [[1, 0], [1, 1]]},
                   "ring": {"points": [[1, 0], [2, 0], [2, 1], [1, 1], [1, 0]]},
                   "inside_out_ring": {"points": [[1, 0], [1, 1], [2, 1], [2, 0], [1, 0]]}},
      "materials": {"glass": {"type": "glass", "ior": 1.5}, "paint": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
      "objects": [)" + objects +
                            "]}",
                        "test.json", ".");
}

TEST(GlassChecksTest, ClosedProfilesListedOutwardsAndOtherMaterialsPassQuietly) {
  EXPECT_TRUE(render::glassWarnings(scene(R"({"profile": "solid", "material": "glass"},
      {"profile": "ring", "material": "glass"}, {"profile": "bubble", "material": "paint"},
      {"profile": "sheet", "material": "paint"})"))
                  .empty());
}

TEST(GlassChecksTest, OpenAndClockwiseGlassIsNamedOncePerObject) {
  const std::vector<std::string> warnings = render::glassWarnings(scene(R"({"profile": "solid", "material": "glass"},
      {"profile": "bubble", "material": "glass", "name": "b"}, {"profile": "sheet", "material": "glass"},
      {"profile": "bubble", "material": "glass"}, {"profile": "inside_out_ring", "material": "glass"})"));
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_THAT(warnings[0], HasSubstr("test.json: objects[1] (\"b\"): glass on profile \"bubble\" runs clockwise"));
  EXPECT_THAT(warnings[1], HasSubstr("objects[2]: glass on profile \"sheet\" is open"));
  EXPECT_THAT(warnings[2], HasSubstr("objects[3]: glass on profile \"bubble\" runs clockwise"));
  EXPECT_THAT(warnings[3], HasSubstr("objects[4]: glass on profile \"inside_out_ring\" runs clockwise"));
}

}  // namespace
}  // namespace revolve
