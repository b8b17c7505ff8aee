// The poses reader: its headers (z, roll, pitch and time optional, any order), an empty z, times, and each
// rule's error naming the file and line.
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

TEST(PosesFileTest, ReadsATimeColumnInAnyOrder) {
  const std::vector<RobotPose> poses = parsePosesCsv("yaw,time,y,x\n0.5,-2.5,2,1\n0.75,1e9,4,3\n", "p.csv");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].x, 1);
  EXPECT_EQ(poses[0].y, 2);
  EXPECT_EQ(poses[0].z, 0);
  EXPECT_EQ(poses[0].yaw, 0.5);
  EXPECT_TRUE(poses[0].timed());
  EXPECT_EQ(poses[0].time, -2.5);
  EXPECT_EQ(poses[1].time, 1e9);
  EXPECT_EQ(poses[1].x, 3);
  EXPECT_FALSE(parsePosesCsv("x,y,yaw\n1,2,0\n", "p.csv")[0].timed());
}

TEST(PosesFileTest, ReadsRollAndPitchInAnyOrder) {
  const std::vector<RobotPose> poses = parsePosesCsv("pitch,x,y,roll,yaw\n0.1,1,2,-0.2,0.3\n", "p.csv");
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_EQ(poses[0].pitch, 0.1);
  EXPECT_EQ(poses[0].roll, -0.2);
  EXPECT_EQ(poses[0].yaw, 0.3);
  EXPECT_FALSE(poses[0].level());
  const RobotPose level = parsePosesCsv("x,y,yaw\n1,2,0\n", "p.csv")[0];
  EXPECT_TRUE(level.level());  // no roll or pitch column: 0, level ground
  EXPECT_THROW(parsePosesCsv("x,y,yaw,roll,roll\n1,2,0,0,0\n", "p.csv"), InputError);  // each once
  EXPECT_THROW(parsePosesCsv("x,y,yaw,pitch\n1,2,0,inf\n", "p.csv"), InputError);      // finite
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
      BadPoses{"NoHeader", "1,2,0,0\n",
               "p.csv:1: header \"1,2,0,0\": column 1 \"1\" is not a pose column; the columns are x, y and yaw, with "
               "z, roll, pitch and time optional, each once (x,y,z,yaw)"},
      BadPoses{"WrongHeader", "x,y,theta\n1,2,0\n", "p.csv:1: header \"x,y,theta\": column 3 \"theta\" is not a pose"},
      BadPoses{"RepeatedColumn", "x,y,yaw,x\n1,2,0,1\n", "p.csv:1: header \"x,y,yaw,x\": column 4 \"x\" is repeated"},
      BadPoses{"NoYaw", "time,x,y\n0,1,2\n", "p.csv:1: header \"time,x,y\" lacks x, y or yaw"},
      BadPoses{"HeaderOnly", "x,y,yaw\n", "p.csv: no poses after the header"},
      BadPoses{"TooFewValues", "x,y,z,yaw\n1,2,3,4\n1,2,3\n",
               "p.csv:3: expected 4 comma-separated values (as the header), found 3"},
      BadPoses{"NotANumber", "x,y,yaw\n1,two,0\n", "p.csv:2: y = \"two\" is not a number"},
      BadPoses{"EmptyX", "x,y,yaw\n,2,0\n", "p.csv:2: x = \"\" is not a number"},
      BadPoses{"EmptyYaw", "x,y,z,yaw\n1,2,3,\n", "p.csv:2: yaw = \"\" is not a number"},
      BadPoses{"Infinite", "x,y,yaw\n1,2,inf\n", "p.csv:2: yaw = \"inf\" is not finite"},
      BadPoses{"Overflow", "x,y,yaw\n1e999,2,0\n", "p.csv:2: x = \"1e999\" is not finite"},
      BadPoses{"TimeNotANumber", "time,x,y,yaw\nnow,1,2,0\n", "p.csv:2: time = \"now\" is not a number"},
      BadPoses{"TimeNaN", "time,x,y,yaw\nnan,1,2,0\n", "p.csv:2: time = \"nan\" is not finite"},
      BadPoses{"TimeFarAway", "x,y,yaw,time\n1,2,0,2e12\n",
               "p.csv:2: time = \"2e12\" is out of range: a pose's time is a number of seconds within +-1e12"},
      BadPoses{"TimeRepeated", "time,x,y,yaw\n0.1,1,2,0\n\n0.1,1,2,0\n",
               "p.csv:4: time = \"0.1\" does not increase: times are strictly increasing (the pose on line 2 is at "
               "0.1)"},
      BadPoses{"TimeBackwards", "time,x,y,yaw\n0,1,2,0\n0.2,1,2,0\n0.15,1,2,0\n",
               "p.csv:4: time = \"0.15\" does not increase: times are strictly increasing (the pose on line 3 is at "
               "0.2)"}};
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
