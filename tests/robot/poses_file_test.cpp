// The poses reader: both headers, an empty z, and each rule's error naming the file and line.
#include "io/poses_file.h"
#include "io/text_files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace revolve::io {
namespace {

using ::testing::HasSubstr;

TEST(PosesFileTest, ReadsBothHeadersAndAnEmptyZ) {
  const std::vector<RobotPose> withZ = parsePosesCsv("x,y,z,yaw\n1,2,0.5,0.25\n\n -3 , 4 , , -1.5\r\n", "p.csv");
  ASSERT_EQ(withZ.size(), 2u);
  EXPECT_EQ(withZ[0].x, 1);
  EXPECT_EQ(withZ[0].y, 2);
  EXPECT_EQ(withZ[0].z, 0.5);
  EXPECT_EQ(withZ[0].yaw, 0.25);
  EXPECT_EQ(withZ[1].x, -3);
  EXPECT_EQ(withZ[1].z, 0);  // empty: the sensor's (or robot's) own height
  EXPECT_EQ(withZ[1].yaw, -1.5);
  const std::vector<RobotPose> withoutZ = parsePosesCsv("x,y,yaw\n1,2,7.5\n", "p.csv");
  ASSERT_EQ(withoutZ.size(), 1u);
  EXPECT_EQ(withoutZ[0].z, 0);
  EXPECT_EQ(withoutZ[0].yaw, 7.5);  // any number of turns: odometry accumulates yaw
}

struct BadPoses {
  const char* name;
  std::string text;
  std::string expected;
};

// Every rule, one case each (in one test: a process per case costs seconds under the sanitizers).
TEST(PosesFileTest, EachRuleNamesTheLineAndTheRule) {
  const std::vector<BadPoses> cases{
      BadPoses{"Empty", "\n\n", "p.csv: empty: expected the header"},
      BadPoses{"NoHeader", "1,2,0,0\n", "p.csv:1: header \"1,2,0,0\" is not \"x,y,z,yaw\" or \"x,y,yaw\""},
      BadPoses{"WrongHeader", "x,y,theta\n1,2,0\n", "p.csv:1: header \"x,y,theta\" is not"},
      BadPoses{"HeaderOnly", "x,y,yaw\n", "p.csv: no poses after the header"},
      BadPoses{"TooFewValues", "x,y,z,yaw\n1,2,3,4\n1,2,3\n",
               "p.csv:3: expected 4 comma-separated values (x,y,z,yaw), found 3"},
      BadPoses{"NotANumber", "x,y,yaw\n1,two,0\n", "p.csv:2: y = \"two\" is not a number"},
      BadPoses{"EmptyX", "x,y,yaw\n,2,0\n", "p.csv:2: x = \"\" is not a number"},
      BadPoses{"EmptyYaw", "x,y,z,yaw\n1,2,3,\n", "p.csv:2: yaw = \"\" is not a number"},
      BadPoses{"Infinite", "x,y,yaw\n1,2,inf\n", "p.csv:2: yaw = \"inf\" is not finite"},
      BadPoses{"Overflow", "x,y,yaw\n1e999,2,0\n", "p.csv:2: x = \"1e999\" is not finite"}};
  for (const BadPoses& bad : cases) {
    SCOPED_TRACE(bad.name);
    try {
      parsePosesCsv(bad.text, "p.csv");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr(bad.expected));
    }
  }
}

}  // namespace
}  // namespace revolve::io
