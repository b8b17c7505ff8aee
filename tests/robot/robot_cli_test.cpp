// revolve-lidar, revolve-clearance and revolve-render --pick as their users run them: processes
// judged by exit status, stdout, stderr and the files they leave. Good runs are checked against
// closed forms; every bad input must give one stderr line naming the file and key path or line
// (or the argument) and the rule, a non-zero exit, no output, and leave an existing output as it was.
#include "support/process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using testing::readWholeFile;
using testing::runProcess;
using testing::ScratchDirectory;
using ::testing::StartsWith;

// A pole of radius 0.25 at (2, 0), 2 m tall, and a floor.
const std::string kScene = R"({
  "camera": {"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40, "width": 40, "height": 30},
  "profiles": {"pole": {"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]}},
  "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
  "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0], "name": "pole 1"}],
  "quads": [{"corners": [[-10, -10, 0], [10, -10, 0], [10, 10, 0], [-10, 10, 0]], "material": "grey"}]
})";

// Three beams at -pi/2, 0, pi/2 in the plane 0.5 above the floor.
const std::string kSensor = R"({
  "pose": {"position": [0, 0, 0.5], "yaw": 0},
  "horizontal": {"samples": 3, "min_angle": -1.5707963267948966, "max_angle": 1.5707963267948966},
  "range": {"min": 0.1, "max": 30}
})";

const std::string kPoses = "x,y,yaw\n0,0,0\n0.5,0,0\n0,0,3.141592653589793\n";

std::size_t lineCount(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// The numbers of a CSV row (or a space-separated one); empty fields and "inf" as +inf.
std::vector<double> numbers(const std::string& row, char separator = ',') {
  std::vector<double> out;
  std::string field;
  std::istringstream in(row + separator);
  while (std::getline(in, field, separator)) out.push_back(field.empty() ? INFINITY : std::stod(field));
  return out;
}

// Within float rounding of metre-sized values.
void expectRow(const std::string& row, const std::vector<double>& expected, char separator = ',') {
  const std::vector<double> got = numbers(row, separator);
  ASSERT_EQ(got.size(), expected.size()) << row;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (std::isinf(expected[i])) {
      EXPECT_TRUE(std::isinf(got[i])) << row;
    } else {
      EXPECT_NEAR(got[i], expected[i], 1e-6) << row << " field " << i;
    }
  }
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(RevolveLidarCliTest, WritesCsvPcdAndPlotWithTheClosedFormRanges) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("sensor.json", kSensor);
  dir.write("poses.csv", kPoses);
  const testing::ProcessResult run =
      runProcess(REVOLVE_LIDAR_PATH, {dir / "scene.json", "--sensor", dir / "sensor.json", "--poses", dir / "poses.csv",
                                      "-o", dir / "scan.csv", "--plot", dir / "scan.png"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("3 poses x 3 beams (1 ring x 3 azimuths)"));
  const std::vector<std::string> rows = lines(readWholeFile(dir / "scan.csv"));
  ASSERT_EQ(rows.size(), 10u);
  EXPECT_EQ(rows[0], "pose,ring,return,azimuth,elevation,range,x,y,z,object,intensity,time");
  // Pose 0, beam 1 looks along +x at the pole: 2 - 0.25 = 1.75; pose 1 from 0.5 further on: 1.25;
  // pose 2 faces -x: nothing. Beams at +-pi/2 see nothing (the floor is below the plane).
  // Head-on (the pole's normal along the beam), reflectivity 1: intensity 1 / range^2.
  // No rotation_rate: every beam at the pose's instant, time 0.
  expectRow(rows[2], {0, 0, 0, 0, 0, 1.75, 1.75, 0, 0.5, 0, 1 / (1.75 * 1.75), 0});
  expectRow(rows[5], {1, 0, 0, 0, 0, 1.25, 1.75, 0, 0.5, 0, 1 / (1.25 * 1.25), 0});
  EXPECT_EQ(rows[8], "2,0,0,0,0,inf,,,,,,0");
  EXPECT_EQ(rows[1], "0,0,0,-1.57079633,0,inf,,,,,,0");

  const testing::ProcessResult pcd =
      runProcess(REVOLVE_LIDAR_PATH, {dir / "scene.json", "--sensor", dir / "sensor.json", "--poses", dir / "poses.csv",
                                      "-o", dir / "scan.pcd", "--threads", "1"});
  ASSERT_EQ(pcd.status, 0) << pcd.err;
  const std::string cloud = readWholeFile(dir / "scan.pcd");
  EXPECT_THAT(cloud, HasSubstr("\nWIDTH 3\nHEIGHT 3\n"));
  const std::vector<std::string> points = lines(cloud);
  ASSERT_EQ(points.size(), 11u + 9);  // the header's 11 lines, then WIDTH x HEIGHT points
  expectRow(points[11 + 1], {1.75, 0, 0.5, 1.75, 0, 0, 0, 1 / (1.75 * 1.75), 0}, ' ');
  EXPECT_EQ(points[11 + 0], "nan nan nan nan 0 0 -1 nan 0");
  // A PNG (its signature, then the IHDR chunk's big-endian width and height), of a readable size.
  const std::string png = readWholeFile(dir / "scan.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  const auto bigEndian = [&](std::size_t at) {
    return (unsigned(std::uint8_t(png[at])) << 24) | (unsigned(std::uint8_t(png[at + 1])) << 16) |
           (unsigned(std::uint8_t(png[at + 2])) << 8) | unsigned(std::uint8_t(png[at + 3]));
  };
  EXPECT_GT(bigEndian(16), 400u);
  EXPECT_GT(bigEndian(20), 200u);
  EXPECT_EQ(dir.entries(),
            (std::set<std::string>{"scene.json", "sensor.json", "poses.csv", "scan.csv", "scan.pcd", "scan.png"}));
}

// A spinning sensor on a robot driving at 2 m/s along +x toward the pole, poses with times: each
// beam fires at column / (samples x rate) and is traced from where the sensor is then; the path
// ends at the last pose, whose sweep is traced at rest.
TEST(RevolveLidarCliTest, AMovingSensorsBeamsCarryTheirTimeAndRangeFromWhereTheyFire) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  // 5 beams over [-0.01, 0.01] rad at 10 Hz: column k fires at k / 50 s.
  dir.write("sensor.json", R"({
    "pose": {"position": [0, 0, 0.5], "yaw": 0},
    "horizontal": {"samples": 5, "min_angle": -0.01, "max_angle": 0.01},
    "range": {"min": 0.1, "max": 30},
    "rotation_rate": 10
  })");
  dir.write("poses.csv", "time,x,y,yaw\n100,0,0,0\n100.25,0.5,0,0\n100.5,1,0,0\n");
  const testing::ProcessResult run = runProcess(
      REVOLVE_LIDAR_PATH,
      {dir / "scene.json", "--sensor", dir / "sensor.json", "--poses", dir / "poses.csv", "-o", dir / "scan.csv"});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::vector<std::string> rows = lines(readWholeFile(dir / "scan.csv"));
  ASSERT_EQ(rows.size(), 16u);
  for (int pose = 0; pose < 3; ++pose) {
    for (int k = 0; k < 5; ++k) {
      const std::vector<double> row = numbers(rows[std::size_t(1 + 5 * pose + k)]);
      const double time = k / 50.0, azimuth = -0.01 + 0.005 * k;
      const double x = pose < 2 ? 0.5 * pose + 2 * time : 1;  // the sensor when the beam fires
      // The pole (radius 0.25 at (2, 0)) along the beam from (x, 0): the nearer root of
      // |(x, 0) + t (cos a, sin a) - (2, 0)| = 0.25.
      const double b = (x - 2) * std::cos(azimuth), c = (x - 2) * (x - 2) - 0.0625;
      const double range = -b - std::sqrt(b * b - c);
      EXPECT_EQ(float(row[11]), float(time)) << rows[std::size_t(1 + 5 * pose + k)];
      EXPECT_NEAR(row[5], range, 1e-6) << rows[std::size_t(1 + 5 * pose + k)];
      EXPECT_NEAR(row[6], x + range * std::cos(azimuth), 1e-6);
    }
  }
}

struct BadRun {
  const char* name;
  std::vector<std::string> args;  // {scene}, {sensor}, {poses}, {out}, {dir} are replaced
  std::string expected;
  std::string scene = kScene, sensor = kSensor, poses = kPoses;
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void expectOneLineFailure(const char* tool, const BadRun& bad, const char* prefix) {
  const ScratchDirectory dir;
  dir.write("scene.json", bad.scene);
  dir.write("sensor.json", bad.sensor);
  dir.write("poses.csv", bad.poses);
  dir.write("old.csv", "an existing output");
  const std::set<std::string> before = dir.entries();
  std::vector<std::string> args;
  for (std::string arg : bad.args) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{scene}", dir / "scene.json"},
                                     {"{sensor}", dir / "sensor.json"},
                                     {"{poses}", dir / "poses.csv"},
                                     {"{out}", dir / "old.csv"},
                                     {"{dir}", dir.path().string()}}) {
      if (const std::size_t at = arg.find(key); at != std::string::npos) arg.replace(at, key.size(), value);
    }
    args.push_back(arg);
  }
  const testing::ProcessResult run = runProcess(tool, args);
  EXPECT_NE(run.status, 0);
  EXPECT_LT(run.status, 128) << "crashed";
  EXPECT_EQ(lineCount(run.err), 1u) << run.err;
  EXPECT_THAT(run.err, StartsWith(prefix));
  EXPECT_THAT(run.err, HasSubstr(bad.expected));
  EXPECT_EQ(readWholeFile(dir / "old.csv"), "an existing output");
  EXPECT_EQ(dir.entries(), before) << "no output, no temporary file";
}

const std::vector<std::string> kLidarArgs{"{scene}", "--sensor", "{sensor}", "--poses", "{poses}", "-o", "{out}"};

std::vector<BadRun> badLidarRuns() {
  std::vector<std::string> plotJpg = kLidarArgs;
  plotJpg.insert(plotJpg.end(), {"--plot", "{dir}/scan.jpg"});
  std::vector<std::string> pcdElsewhere = kLidarArgs;
  pcdElsewhere.back() = "{dir}/no/such/folder/scan.pcd";
  std::vector<std::string> threadsZero = kLidarArgs;
  threadsZero.insert(threadsZero.end(), {"--threads", "0"});
  std::vector<std::string> txt = kLidarArgs;
  txt.back() = "{dir}/scan.txt";
  std::vector<std::string> plotRing = kLidarArgs;
  plotRing.insert(plotRing.end(), {"--plot", "{dir}/scan.png", "--plot-ring", "1"});
  return {
      {"SensorDegrees", kLidarArgs, "sensor.json: horizontal.max_angle: 90 is out of range: angles are in radians",
       kScene, replaced(kSensor, R"("max_angle": 1.5707963267948966)", R"("max_angle": 90)")},
      {"PosesBadNumber", kLidarArgs, "poses.csv:3: y = \"zero\" is not a number", kScene, kSensor,
       "x,y,yaw\n0,0,0\n1,zero,0\n"},
      {"SceneBad", kLidarArgs, "scene.json: objects[0].profile: no profile named \"pol\"",
       replaced(kScene, R"("profile": "pole")", R"("profile": "pol")")},
      {"OutputExtension", txt, R"(scan.txt: unsupported scan extension ".txt"; use .csv)"},
      {"OutputFolderMissing", pcdElsewhere, "no/such/folder/scan.pcd: cannot create a file there"},
      {"PlotExtension", plotJpg, R"(scan.jpg: unsupported plot extension ".jpg")"},
      {"ThreadsZero", threadsZero, "--threads: 0 is out of range: it must lie in [1, 1024] (see --help)"},
      {"PlotRingBeyondTheSensors", plotRing, "sensor.json has 1 ring, numbered from 0"},
      {"RotationRateNegative", kLidarArgs, "sensor.json: rotation_rate: -10 is out of range: a rotation rate", kScene,
       replaced(kSensor, R"("range")", R"("rotation_rate": -10, "range")")},
      {"TimesNotIncreasing", kLidarArgs,
       "poses.csv:3: time = \"0.1\" does not increase: times are strictly increasing (the pose on line 2 is at 0.2)",
       kScene, kSensor, "x,y,yaw,time\n0,0,0,0.2\n1,0,0,0.1\n"},
      {"SubraysZero", kLidarArgs, "sensor.json: subrays: 0 is out of range: must lie in [1, 256]", kScene,
       replaced(kSensor, R"("range")", R"("subrays": 0, "range")")},
      {"ReturnsUnknown", kLidarArgs, R"(sensor.json: returns: "dual" is not a return mode)", kScene,
       replaced(kSensor, R"("range")", R"("returns": "dual", "range")")},
      {"DivergenceInDegrees", kLidarArgs, "sensor.json: divergence: 3 is out of range", kScene,
       replaced(kSensor, R"("range")", R"("divergence": 3, "range")")},
      // The poses file named as the pattern: its first line is no pattern's header.
      {"PatternBadLine", kLidarArgs, R"(poses.csv:1: header "x,y,yaw": a beam pattern's header is)", kScene,
       R"({"pose": {"position": [0, 0, 0.5]}, "pattern": "poses.csv", "range": {"min": 0.1, "max": 30}})"},
  };
}

// A sonar on the robot, 0.5 above the floor, looking along +X with a 0.4 rad cone.
const std::string kSonar = R"({
  "type": "range", "pose": {"position": [0, 0, 0.5]}, "field_of_view": 0.4, "min_range": 0.1, "max_range": 5,
  "radiation_type": "ultrasound"
})";

std::vector<BadRun> badRangeRuns() {
  std::vector<std::string> pcd = kLidarArgs;
  pcd.back() = "{dir}/ranges.pcd";
  std::vector<std::string> plot = kLidarArgs;
  plot.insert(plot.end(), {"--plot", "{dir}/ranges.png"});
  return {
      {"ConeAngleZero", kLidarArgs, "sensor.json: field_of_view: 0 is out of range", kScene,
       replaced(kSonar, R"("field_of_view": 0.4)", R"("field_of_view": 0)")},
      {"ConeAngleOverPi", kLidarArgs, "sensor.json: field_of_view: 4 is out of range", kScene,
       replaced(kSonar, R"("field_of_view": 0.4)", R"("field_of_view": 4)")},
      {"MinAboveMax", kLidarArgs, "sensor.json: max_range: 5 is not above min_range = 6", kScene,
       replaced(kSonar, R"("min_range": 0.1)", R"("min_range": 6)")},
      {"UnknownRadiation", kLidarArgs, R"(sensor.json: radiation_type: "sound" is not a radiation type)", kScene,
       replaced(kSonar, R"("ultrasound")", R"("sound")")},
      {"NoPoses", kLidarArgs, "poses.csv: no poses after the header", kScene, kSonar, "x,y,yaw\n"},
      {"PcdOutput", pcd, "describes range sensors, whose readings are a CSV table", kScene, kSonar},
      {"Plot", plot, "--plot draws a lidar's scan", kScene, kSonar},
      {"UnequalScale", kLidarArgs, "a range sensor's exact reading needs an object scaled equally",
       replaced(kScene, R"("translate": [2, 0, 0])", R"("translate": [2, 0, 0], "scale": [1, 1, 2])"), kSonar},
  };
}

// One bad input of each kind per tool (the readers' and the --robot argument's every rule are
// checked in process), in one test: each process costs about a second under the sanitizers.
TEST(RevolveLidarCliTest, RangeSensorsBadInputsGiveOneLineANonZeroExitAndNoOutput) {
  for (const BadRun& bad : badRangeRuns()) {
    SCOPED_TRACE(bad.name);
    expectOneLineFailure(REVOLVE_LIDAR_PATH, bad, "revolve-lidar: ");
  }
}

TEST(RevolveLidarCliTest, RangeSensorsReadTheNearestSurfaceInsideTheirCone) {
  // The pole (radius 0.25 at (2, 0)) seen from 0.5 above the floor: straight on, the nearest point
  // is the pole's, 1.75 away; turned by b from it, the nearest point inside the cone of half-angle
  // a = 0.2 lies on the boundary ray nearest the pole's axis (at b - a from it), on the circle of
  // radius 0.25 about (2, 0) in the sonar's plane, unless the floor (0.5 below, seen at
  // 0.5 / sin(a) = 2.52 at the cone's lowest ray) is nearer; turned away, the floor alone.
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  dir.write("sensor.json", kSonar);
  dir.write("poses.csv", "x,y,yaw\n0,0,0\n0,0,0.3\n0,0,1.5\n");
  const testing::ProcessResult run = runProcess(
      REVOLVE_LIDAR_PATH,
      {dir / "scene.json", "--sensor", dir / "sensor.json", "--poses", dir / "poses.csv", "-o", dir / "ranges.csv"});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::vector<std::string> rows = lines(readWholeFile(dir / "ranges.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], "pose,sensor,range,x,y,z,object");
  expectRow(rows[1], {0, 0, 1.75, 1.75, 0, 0.5, 0});
  const double a = 0.2, D = 2, R = 0.25, gamma = 0.3 - a;
  const double s = D * std::cos(gamma) - std::sqrt(R * R - D * D * std::sin(gamma) * std::sin(gamma));
  // The boundary ray at yaw 0.3 - 0.2 = 0.1: the point at angle 0.1 from +X.
  expectRow(rows[2], {1, 0, s, s * std::cos(0.1), s * std::sin(0.1), 0.5, 0});
  const double floor = 0.5 / std::sin(a);
  const std::vector<double> third = numbers(rows[3]);
  ASSERT_EQ(third.size(), 7u) << rows[3];
  EXPECT_NEAR(third[2], floor, 1e-9) << rows[3];
  EXPECT_NEAR(third[5], 0.0, 1e-9) << rows[3];
  EXPECT_EQ(third[6], 1) << "the floor, the quad after the one object";
}

TEST(RevolveLidarCliTest, BadInputsGiveOneLineANonZeroExitAndNoOutput) {
  for (const BadRun& bad : badLidarRuns()) {
    SCOPED_TRACE(bad.name);
    expectOneLineFailure(REVOLVE_LIDAR_PATH, bad, "revolve-lidar: ");
  }
}

TEST(RevolveClearanceCliTest, WritesTheClosedFormClearancePerPose) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  // Robot of radius 0.3 from 0.05 to 1.2 above each pose: at x = 0 the pole is 2 - 0.25 - 0.3 =
  // 1.45 away and the floor 0.05 under it, so the floor is nearest; lifted by 1.6 m (z column) to
  // span 1.65 to 2.8, the pole (up to 2) is; at x = 1.5 the pole's side is 0.25 from the robot's
  // axis, 0.05 inside its radius.
  dir.write("poses.csv", "x,y,z,yaw\n0,0,,0\n0,0,1.6,0\n1.5,0,1.6,0\n");
  const testing::ProcessResult run = runProcess(
      REVOLVE_CLEARANCE_PATH,
      {dir / "scene.json", "--robot", "0.3,0.05,1.2", "--poses", dir / "poses.csv", "-o", dir / "clearance.csv"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("3 poses, 1 collides"));
  const std::vector<std::string> rows = lines(readWholeFile(dir / "clearance.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], "pose,clearance,collides,object,px,py,pz");
  const std::vector<double> floor = numbers(rows[1]);
  ASSERT_EQ(floor.size(), 7u);
  expectRow(rows[1], {0, 0.05, 0, 1, floor[4], floor[5], 0});  // the floor, quads[0] = object 1, under the robot
  EXPECT_LE(std::hypot(floor[4], floor[5]), 0.3);
  const std::vector<double> beside = numbers(rows[2]);
  expectRow(rows[2], {1, 1.45, 0, 0, 1.75, 0, beside[6]});
  EXPECT_GE(beside[6], 1.65 - 1e-9);
  EXPECT_LE(beside[6], 2 + 1e-9);
  const std::vector<double> into = numbers(rows[3]);
  expectRow(rows[3], {2, -0.05, 1, 0, 1.75, 0, into[6]});
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"scene.json", "poses.csv", "clearance.csv"}));
  // With the floor as the ground the robot drives on, the pole is the nearest obstacle at once.
  const testing::ProcessResult grounded =
      runProcess(REVOLVE_CLEARANCE_PATH, {dir / "scene.json", "--robot", "0.3,0.05,1.2", "--poses", dir / "poses.csv",
                                          "-o", dir / "clearance.csv", "--ground", "0"});
  ASSERT_EQ(grounded.status, 0) << grounded.err;
  const std::vector<double> pole = numbers(lines(readWholeFile(dir / "clearance.csv"))[1]);
  expectRow(lines(readWholeFile(dir / "clearance.csv"))[1], {0, 1.45, 0, 0, 1.75, 0, pole[6]});
}

const std::vector<std::string> kClearanceArgs{"{scene}", "--robot", "0.3,0.05,1.2", "--poses",
                                              "{poses}", "-o",      "{out}"};

std::vector<BadRun> badClearanceRuns() {
  const auto robot = [](const std::string& value) {
    std::vector<std::string> args = kClearanceArgs;
    args[2] = value;
    return args;
  };
  std::vector<std::string> pcd = kClearanceArgs;
  pcd.back() = "{dir}/out.pcd";
  return {
      {"RobotTwoValues", robot("0.3,1.2"),
       "--robot \"0.3,1.2\": expected RADIUS,ZMIN,ZMAX (3 comma-separated numbers), found 2"},
      {"RobotMissing", {"{scene}", "--poses", "{poses}", "-o", "{out}"}, "--robot is required (see --help)"},
      {"GroundNotANumber",
       {"{scene}", "--robot", "0.3,0,1", "--poses", "{poses}", "-o", "{out}", "--ground", "floor"},
       "--ground \"floor\" is not a finite number"},
      {"PosesBad", kClearanceArgs, "poses.csv:2: x = \"\" is not a number", kScene, kSensor, "x,y,yaw\n,0,0\n"},
      {"SceneBad", kClearanceArgs, "scene.json: not valid JSON", "{"},
      {"OutputExtension", pcd, R"(out.pcd: unsupported extension ".pcd"; the clearance table is a .csv)"},
      {"TiltedPose", kClearanceArgs,
       "poses.csv: pose 1 (counting from 0) has roll = 0, pitch = 0.1: the clearance robot is an upright cylinder on "
       "level ground",
       kScene, kSensor, "x,y,yaw,pitch\n0,0,0,0\n1,0,0,0.1\n"},
  };
}

TEST(RevolveClearanceCliTest, BadInputsGiveOneLineANonZeroExitAndNoOutput) {
  for (const BadRun& bad : badClearanceRuns()) {
    SCOPED_TRACE(bad.name);
    expectOneLineFailure(REVOLVE_CLEARANCE_PATH, bad, "revolve-clearance: ");
  }
}

TEST(RevolveRenderPickCliTest, PrintsTheObjectUnderThePixelOrNothing) {
  const ScratchDirectory dir;
  dir.write("scene.json", kScene);
  // The 40 x 30 view looks along +x at the pole from 5 m: pixel (20, 15) is just right of and below
  // the centre, on the pole. The camera's ray meets the pole's front near x = 1.75.
  const testing::ProcessResult hit = runProcess(REVOLVE_RENDER_PATH, {dir / "scene.json", "--pick", "20,15"});
  ASSERT_EQ(hit.status, 0) << hit.err;
  EXPECT_THAT(hit.out, StartsWith("object 0 \"pole 1\" point 1.7"));
  std::istringstream fields(hit.out.substr(hit.out.find("point")));
  std::string word;
  double x, y, z, distance;
  fields >> word >> x >> y >> z >> word >> distance;
  EXPECT_NEAR(std::hypot(x - 2, y), 0.25, 1e-5);  // on the pole's side
  EXPECT_NEAR(distance, std::hypot(x + 3, y, z - 1), 1e-5);
  // The top left pixel sees the sky.
  const testing::ProcessResult sky = runProcess(REVOLVE_RENDER_PATH, {dir / "scene.json", "--pick", "0,0"});
  ASSERT_EQ(sky.status, 0) << sky.err;
  EXPECT_EQ(sky.out, "nothing\n");
  // The bottom row sees the floor, quads[0].
  const testing::ProcessResult floor = runProcess(REVOLVE_RENDER_PATH, {dir / "scene.json", "--pick", "3,29"});
  EXPECT_THAT(floor.out, StartsWith("object 1 \"quads[0]\" point"));
  EXPECT_EQ(dir.entries(), std::set<std::string>{"scene.json"}) << "picking renders nothing";
  for (const auto& [value, expected] : {std::pair<std::string, std::string>{"a,3", "--pick \"a,3\": expected X,Y"},
                                        {"40,3", "--pick: X = 40 is outside the image: 0 <= X < width = 40"}}) {
    const testing::ProcessResult bad = runProcess(REVOLVE_RENDER_PATH, {dir / "scene.json", "--pick", value});
    EXPECT_EQ(bad.status, 1) << value;
    EXPECT_EQ(lineCount(bad.err), 1u) << bad.err;
    EXPECT_THAT(bad.err, HasSubstr(expected));
  }
}

}  // namespace
}  // namespace revolve
