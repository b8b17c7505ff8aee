// Beam patterns: the pattern file's reader (each rule names the file, line and column), a sensor
// naming its pattern relative to itself, and a pattern scan checked against closed forms: every beam
// at its own azimuth, elevation and firing time, traced from where a moving sensor is then.
#include "io/beam_pattern_file.h"
#include "io/input_file.h"
#include "io/scratch_directory.h"
#include "io/sensor_file.h"
#include "robot/lidar.h"
#include "robot_scenes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace revolve {
namespace {

using revolve::testing::ScratchDirectory;
using ::testing::HasSubstr;

TEST(BeamPatternTest, ReadsEveryBeamInTheFilesOrder) {
  const std::vector<io::PatternBeam> beams =
      io::parseBeamPattern("azimuth,elevation,time\n0.5,-0.25,0\n\n-3.0, 0.125 ,1.5e-6\r\n0,1.5,0.01\n", "p.csv");
  ASSERT_EQ(beams.size(), 3u);
  EXPECT_EQ(beams[0].azimuth, 0.5);
  EXPECT_EQ(beams[0].elevation, -0.25);
  EXPECT_EQ(beams[1].azimuth, -3.0);
  EXPECT_EQ(beams[1].elevation, 0.125);
  EXPECT_EQ(beams[1].time, 1.5e-6);
  EXPECT_EQ(beams[2].time, 0.01);
}

TEST(BeamPatternTest, EachBadLineNamesTheFileLineColumnAndRule) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"", "p.csv: empty: expected the header \"azimuth,elevation,time\""},
      {"azimuth,elevation\n0,0\n", "p.csv:1: header \"azimuth,elevation\": a beam pattern's header is"},
      {"azimuth,elevation,time\n", "p.csv: no beams after the header"},
      {"azimuth,elevation,time\n0,0,0\n0,0\n", "p.csv:3: expected 3 comma-separated values"},
      {"azimuth,elevation,time\n0,x,0\n", "p.csv:2: column 2 (elevation) = \"x\" is not a number"},
      {"azimuth,elevation,time\n90,0,0\n",
       "p.csv:2: column 1 (azimuth) = \"90\" is out of range: angles are in radians"},
      {"azimuth,elevation,time\n0,1.6,0\n", "p.csv:2: column 2 (elevation) = \"1.6\" is out of range"},
      {"azimuth,elevation,time\n0,0,-1e-6\n", "p.csv:2: column 3 (time) = \"-1e-6\" is out of range: a firing time"},
      {"azimuth,elevation,time\n0,0,nan\n", "p.csv:2: column 3 (time) = \"nan\""},
      {"azimuth,elevation,time\n0,0,inf\n", "p.csv:2: column 3 (time) = \"inf\""},
  };
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(text);
    try {
      io::parseBeamPattern(text, "p.csv");
      ADD_FAILURE() << "accepted";
    } catch (const io::InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr(expected));
    }
  }
}

TEST(BeamPatternTest, ASensorReadsItsPatternBesideIt) {
  const ScratchDirectory dir;
  std::filesystem::create_directories(dir.path() / "sensors");
  dir.write("sensors/beams.csv", "azimuth,elevation,time\n0.1,0.2,0\n0.3,-0.4,0.002\n");
  dir.write("sensors/sensor.json", R"({"pose": {"position": [0, 0, 1]}, "pattern": "beams.csv",
                                      "range": {"min": 0, "max": 50}})");
  const io::SensorDescription s = io::readSensor(dir / "sensors/sensor.json");
  ASSERT_EQ(s.pattern.size(), 2u);
  EXPECT_EQ(s.columnTime(1), 0.002);  // the one place a beam's time comes from
  EXPECT_EQ(s.sweepDuration(), 0.002);
  const io::ScanLayout layout = io::scanLayout(s, 3);
  EXPECT_TRUE(layout.pattern);
  EXPECT_EQ(layout.rings(), 1u);
  EXPECT_EQ(layout.beamsPerPose(), 2u);
  EXPECT_EQ(layout.elevation(0, 1), -0.4);
  // A bad line of the pattern names the sensor's key and the pattern's own line.
  dir.write("sensors/beams.csv", "azimuth,elevation,time\n0.1,0.2,0\n0.3,-0.4,later\n");
  try {
    io::readSensor(dir / "sensors/sensor.json");
    FAIL() << "accepted";
  } catch (const io::SensorError& error) {
    EXPECT_THAT(error.what(), HasSubstr("pattern: "));
    EXPECT_THAT(error.what(), HasSubstr("beams.csv:3: column 3 (time) = \"later\" is not a number"));
  }
}

// A pattern sensor moving at v along +x toward the wall x = W: beam k, at azimuth a_k and elevation
// e_k, fires at t_k and is traced from (v t_k, 0, h); its range is (W - v t_k) / (cos e_k cos a_k).
TEST(BeamPatternTest, APatternsBeamsFireAtTheirOwnTimesFromWhereTheMovingSensorIs) {
  io::SensorDescription s;
  s.pose.position = {0, 0, 0.5};
  s.rangeMin = 0;
  s.rangeMax = 100;
  for (int k = 0; k < 200; ++k) {
    // A rosette-like scatter: azimuths and elevations from two incommensurate turns, times out of order.
    s.pattern.push_back({0.4 * std::sin(0.37 * k), 0.2 * std::sin(0.61 * k), 0.001 * ((k * 37) % 100)});
  }
  s.elevations = {0.0};
  s.planar = false;
  const double wall = 6, speed = 2;
  const scene::EmbreeScene built(testing::sceneOf({}, {{testing::Vec3d{wall, -6, -3}, testing::Vec3d{wall, 6, -3},
                                                        testing::Vec3d{wall, 6, 3}, testing::Vec3d{wall, -6, 3}}}),
                                 {});
  const robot::Lidar lidar(built, s);
  io::RobotPose start, end;
  start.time = 0;
  end.time = 1, end.x = speed;
  const io::ScanTable scan = lidar.scan(std::vector<io::RobotPose>{start, end});
  ASSERT_TRUE(scan.pattern);
  ASSERT_EQ(scan.points.size(), 400u);
  for (std::size_t k = 0; k < 200; ++k) {
    SCOPED_TRACE(k);
    const io::PatternBeam& b = s.pattern[k];
    const io::BeamReturn& r = scan.at(0, 0, k);
    EXPECT_EQ(r.time, float(b.time));
    const double x = speed * b.time;
    const double range = (wall - x) / (std::cos(b.elevation) * std::cos(b.azimuth));
    const double tolerance = 0x1p-20 * (wall + range);
    EXPECT_NEAR(r.range, range, tolerance);
    EXPECT_NEAR(r.x, wall, tolerance);
    EXPECT_NEAR(r.z, 0.5 + range * std::sin(b.elevation), tolerance);
  }
}

}  // namespace
}  // namespace revolve
