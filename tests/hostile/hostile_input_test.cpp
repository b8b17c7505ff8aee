// Hostile input, the tools run as processes as a user (or another program) would run them: far and
// non-finite coordinates against Embree's ray contract, tiny direction vectors, special and
// oversized files, empty option values, option errors, outputs that name an input, and scenes that
// are valid but show nothing. Every refusal must be one stderr line naming the input and the rule,
// status 1, and leave every file as it was; nothing may end with a signal.
#include "hostile_fixtures.h"

#include <OpenImageIO/imagebuf.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace revolve {
namespace {

using testing::expectRefusal;
using ::testing::HasSubstr;
using testing::kPlanarSensor;
using testing::kPoleScene;
using testing::kPoses;
using testing::lineCount;
using testing::ProcessOptions;
using testing::ProcessResult;
using testing::readWholeFile;
using testing::replacedIn;
using testing::runProcess;
using testing::ScratchDirectory;
using ::testing::StartsWith;

const std::string kLidar = REVOLVE_LIDAR_PATH, kRender = REVOLVE_RENDER_PATH, kTrace = REVOLVE_TRACE_PATH,
                  kClearance = REVOLVE_CLEARANCE_PATH;

ProcessResult runIn(const ScratchDirectory& dir, const std::string& tool, const std::vector<std::string>& args) {
  return runProcess(tool, args, ProcessOptions{.directory = dir.path().string()}, 60);
}

// ---------------------------------------------------------------------------------------------
// Embree's ray contract: every position within +-2^40, every ray file coordinate within +-2^60.

TEST(EmbreeContract, FarPositionsAreRefusedByLineOrKeyPathWithTheLimit) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kPlanarSensor);
  dir.write("far_sensor.json", replacedIn(kPlanarSensor, "[0, 0, 0.5]", "[0, 0, 1e20]"));
  dir.write("poses.csv", "x,y,yaw\n0,0,0\n1e20,0,0\n");
  dir.write("p.csv", "r,z\n0,0\n1,0\n1,1\n0,1\n");
  dir.write("far_origin.csv", "ox,oy,oz,dx,dy,dz,tnear,tfar\n2e18,0,0.5,-1,0,0,0,inf\n");
  dir.write("far_direction.csv", "-5,0,0.5,1,0,0,0,inf\n-5,0,0.5,1e19,0,0,0,inf\n");
  expectRefusal(kLidar, "revolve-lidar", dir,
                {"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o", "scan.csv"},
                "poses.csv:3: x = \"1e20\" is beyond the coordinate limit: positions lie within +-2^40 (1.1e12)");
  expectRefusal(kLidar, "revolve-lidar", dir, {"scene.json", "--sensor", "far_sensor.json", "-o", "scan.csv"},
                "far_sensor.json: pose.position[2]: 1e+20 is beyond the coordinate limit");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "p.csv", "--rays", "far_origin.csv", "--out", "h.csv"},
                "far_origin.csv:2: ox = \"2e18\" is beyond +-2^60 (1.15e18), the largest coordinate revolve traces and "
                "Embree accepts");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "p.csv", "--rays", "far_direction.csv", "--out", "h.csv"},
                "far_direction.csv:2: dx = \"1e19\" is beyond +-2^60");
}

// The limits are derived so that the worst ray they allow stays inside Embree's range in every
// instance (common/ray_limits.h). At their extremes: an object scaled by 2^-16 and turned about
// (1, 1, 1) (the largest stretch of its inverse), placed 1.09e12 out, seen by a sensor 1.09e12 out
// on the other side. Embree would abort the process on a ray beyond its range; here the beam aimed
// at the object must return, from 2.18e12 away.
TEST(EmbreeContract, RaysAtTheLimitsStayWithinEmbreesRange) {
  const ScratchDirectory dir;
  // A capped cylinder of radius and half-height 1e12 (the profile may reach 2^60), scaled to 1.5e7.
  dir.write("scene.json", R"({
    "camera": {"from": [0, 0, 1], "to": [1, 0, 1], "up": [0, 0, 1], "fov": 40},
    "profiles": {"drum": {"points": [[0, -1e12], [1e12, -1e12], [1e12, 1e12], [0, 1e12]]}},
    "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
    "objects": [{"profile": "drum", "material": "grey", "translate": [-1.09e12, 0, 0.5],
                 "rotate": [1, 1, 1, 45], "scale": 1.52587890625e-05}]
  })");
  dir.write("sensor.json", R"({
    "pose": {"position": [0, 0, 0.5]},
    "horizontal": {"samples": 5, "min_angle": -0.002, "max_angle": 0.002},
    "range": {"min": 0.1, "max": 1e13}
  })");
  dir.write("poses.csv", "x,y,yaw\n1.09e12,0,3.141592653589793\n");
  const ProcessResult run =
      runIn(dir, kLidar, {"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o", "scan.csv"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "") << "no warning, and no ray refused";
  std::istringstream rows(readWholeFile(dir / "scan.csv"));
  std::string row;
  std::vector<std::string> lines;
  while (std::getline(rows, row)) lines.push_back(row);
  ASSERT_EQ(lines.size(), 6u);
  // The middle beam runs along the object's centre line: it meets the surface within the drum's
  // reach (sqrt 3 times 1.5e7, whatever its turn) of the centre, 2.18e12 away.
  std::istringstream fields(lines[3]);
  std::vector<std::string> f;
  for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
  ASSERT_EQ(lines[0].rfind("pose,ring,return,azimuth,elevation,range,", 0), 0u) << lines[0];
  ASSERT_GE(f.size(), 6u) << lines[3];
  ASSERT_NE(f[5], "inf") << "the beam at the object missed it";
  const double range = std::stod(f[5]);
  EXPECT_LE(range, 2.18e12);
  EXPECT_GE(range, 2.18e12 - std::sqrt(3.0) * 1.52587890625e-05 * 1e12);
}

// A tiny non-zero rotation axis (1e-200, even the smallest subnormal) turns the object exactly as
// the unit axis does: the scans are the same byte for byte, and the turned pole is where the
// rotation puts it.
TEST(EmbreeContract, ATinyRotationAxisTurnsTheObjectAsTheUnitAxisDoes) {
  const ScratchDirectory dir;
  const std::string tilted =
      replacedIn(kPoleScene, R"("translate": [2, 0, 0])", R"("translate": [2, 0, 0], "rotate": [0, 1, 0, 30])");
  dir.write("unit.json", tilted);
  dir.write("tiny.json", replacedIn(tilted, "[0, 1, 0, 30]", "[0, 1e-200, 0, 30]"));
  dir.write("subnormal.json", replacedIn(tilted, "[0, 1, 0, 30]", "[0, 5e-324, 0, 30]"));
  dir.write("sensor.json", kPlanarSensor);
  for (const char* scene : {"unit", "tiny", "subnormal"}) {
    const ProcessResult run = runIn(
        dir, kLidar, {std::string(scene) + ".json", "--sensor", "sensor.json", "-o", std::string(scene) + ".csv"});
    ASSERT_EQ(run.status, 0) << scene << ": " << run.err;
  }
  const std::string unit = readWholeFile(dir / "unit.csv");
  EXPECT_EQ(readWholeFile(dir / "tiny.csv"), unit);
  EXPECT_EQ(readWholeFile(dir / "subnormal.csv"), unit);
  // Turned 30 degrees about y through its foot (2, 0, 0), the pole leans towards +x: its axis runs
  // along (sin 30, 0, cos 30), and its near side in the plane y = 0 along the same direction from
  // (2 - 0.25 cos 30, 0, 0.25 sin 30), which at the beam's height 0.5 lies at x = 2 exactly.
  std::istringstream rows(unit);
  std::string row;
  std::getline(rows, row);  // header
  ASSERT_EQ(row.rfind("pose,ring,return,azimuth,elevation,range,", 0), 0u) << row;
  std::getline(rows, row);  // beam 0, at -pi/2
  std::getline(rows, row);  // beam 1, along +x
  std::vector<std::string> f;
  std::istringstream fields(row);
  for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
  ASSERT_GE(f.size(), 6u) << row;
  ASSERT_NE(f[5], "inf") << "the turned pole vanished";
  EXPECT_NEAR(std::stod(f[5]), 2.0, 1e-6);
}

// Directions of 2^-100 (far below float's squares) give the same camera, sun and image as unit
// ones: the frame is normalised in double, scaled by the largest component first.
TEST(EmbreeContract, TinyViewUpAndSunDirectionsRenderAsUnitOnes) {
  const ScratchDirectory dir;
  const std::string unit = R"({
    "camera": {"from": [0, 0, 1], "to": [0, 1, 1], "up": [0, 0, 1], "fov": 60, "width": 16, "height": 12, "spp": 1},
    "profiles": {"pole": {"points": [[0, 0], [0.5, 0], [0.5, 2], [0, 2]]}},
    "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
    "objects": [{"profile": "pole", "material": "grey", "translate": [0, 3, 0]}],
    "lights": [{"type": "sun", "direction": [0, 0.5, -1], "irradiance": [3, 3, 3]}],
    "environment": {"color": [0.1, 0.1, 0.1]}
  })";
  dir.write("unit.json", unit);
  // 2^-100 and 2^-101, written as their shortest round-trip decimals.
  std::string tiny = replacedIn(unit, R"("to": [0, 1, 1])", R"("to": [0, 7.888609052210118e-31, 1])");
  tiny = replacedIn(tiny, R"("up": [0, 0, 1])", R"("up": [0, 0, 7.888609052210118e-31])");
  tiny = replacedIn(tiny, R"("direction": [0, 0.5, -1])",
                    R"("direction": [0, 3.944304526105059e-31, -7.888609052210118e-31])");
  dir.write("tiny.json", tiny);
  for (const char* scene : {"unit", "tiny"}) {
    const ProcessResult run = runIn(dir, kRender, {std::string(scene) + ".json", "-o", std::string(scene) + ".exr"});
    ASSERT_EQ(run.status, 0) << scene << ": " << run.err;
  }
  OIIO::ImageBuf a(dir / "unit.exr"), b(dir / "tiny.exr");
  ASSERT_TRUE(a.read() && b.read());
  std::vector<float> pa(16 * 12 * 3), pb(pa.size());
  a.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pa.data());
  b.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pb.data());
  EXPECT_EQ(pa, pb);
  EXPECT_GT(*std::max_element(pa.begin(), pa.end()), 0.2f) << "the sunlit pole is in view";
  for (const float v : pb) EXPECT_TRUE(std::isfinite(v));
}

// ---------------------------------------------------------------------------------------------
// Files that are not regular, or too large: refused by name at once, never read.

TEST(SpecialFiles, DevicesFifosDirectoriesAndOversizedFilesAreRefusedByName) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kPlanarSensor);
  dir.write("poses.csv", kPoses);
  dir.write("p.csv", "r,z\n0,0\n1,0\n1,1\n0,1\n");
  dir.write("r.csv", "-5,0,0.5,1,0,0,0,inf\n");
  dir.write("device_profile.json",
            replacedIn(kPoleScene, R"({"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]})", R"({"csv": "/dev/zero"})"));
  ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
  std::filesystem::create_directory(dir / "folder");
  // Sparse files (no disk used) just over each limit, and a line twice the line limit.
  const auto sparse = [&](const std::string& name, off_t size) {
    const std::string path = dir.write(name, "");
    ASSERT_EQ(truncate(path.c_str(), size), 0);
  };
  sparse("huge.json", (off_t{1} << 26) + 1);
  sparse("huge.csv", (off_t{1} << 28) + 1);
  dir.write("long_line.csv", std::string(8192, '1'));

  expectRefusal(kRender, "revolve-render", dir, {"/dev/zero", "-o", "out.png"},
                "/dev/zero: is a character device, not a regular file");
  expectRefusal(kLidar, "revolve-lidar", dir, {"scene.json", "--sensor", "/dev/urandom", "-o", "scan.csv"},
                "/dev/urandom: is a character device, not a regular file");
  expectRefusal(kLidar, "revolve-lidar", dir,
                {"scene.json", "--sensor", "sensor.json", "--poses", "pipe", "-o", "scan.csv"},
                "pipe: is a FIFO (named pipe), not a regular file");
  expectRefusal(kLidar, "revolve-lidar", dir, {"huge.json", "--sensor", "sensor.json", "-o", "scan.csv"},
                "huge.json: its 67.1 MB is too large: a JSON file is read up to 64 MiB");
  expectRefusal(kLidar, "revolve-lidar", dir, {"device_profile.json", "--sensor", "sensor.json", "-o", "scan.csv"},
                "device_profile.json: profiles.pole.csv: /dev/zero: is a character device, not a regular file");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "/dev/zero", "--rays", "r.csv", "--out", "h.csv"},
                "/dev/zero: is a character device");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "p.csv", "--rays", "pipe", "--out", "h.csv"},
                "pipe: is a FIFO");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "p.csv", "--rays", "folder", "--out", "h.csv"},
                "folder: is a directory, not a regular file");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "p.csv", "--rays", "huge.csv", "--out", "h.csv"},
                "huge.csv: its 268 MB is too large: a CSV file is read up to 256 MiB");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "long_line.csv", "--rays", "r.csv", "--out", "h.csv"},
                "long_line.csv:1: the line is 8192 bytes long; a line of these files holds at most 4096");
  expectRefusal(kClearance, "revolve-clearance", dir,
                {"scene.json", "--robot", "0.3,0,1", "--poses", "/dev/zero", "-o", "c.csv"},
                "/dev/zero: is a character device");
}

// ---------------------------------------------------------------------------------------------
// Sizes checked before allocating.

TEST(Sizes, AScanBeyondWhatAFileHoldsIsRefusedBeforeTracing) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  // 16,384 x 1,024 = 2^24 beams a pose (the most a sensor may have), 200 poses: 3.4e9 beams.
  dir.write("sensor.json", R"({"pose": {"position": [0, 0, 0.5]},
    "horizontal": {"samples": 16384, "min_angle": -3, "max_angle": 3},
    "vertical": {"samples": 1024, "min_angle": -1, "max_angle": 1}, "range": {"min": 0.1, "max": 30}})");
  dir.write("poses.csv", testing::manyPoses(200));
  expectRefusal(
      kLidar, "revolve-lidar", dir, {"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o", "scan.pcd"},
      "poses.csv: 200 poses x 16777216 points (sensor.json) = 3355443200 points; a scan holds at most 2^31 - 1");
}

TEST(Sizes, AMeshBeyondTheMachinesMemoryIsRefusedBeforeBuilding) {
  const ScratchDirectory dir;
  std::string profile = "r,z\n";
  for (int i = 0; i <= 1000; ++i) profile += "1," + std::to_string(i) + "\n";
  dir.write("p.csv", profile);
  dir.write("r.csv", "-5,0,0.5,1,0,0,0,inf\n");
  // 2 x 1,000 segments x 2^24 slices = 3.4e10 triangles, terabytes.
  expectRefusal(kTrace, "revolve-trace", dir,
                {"--profile", "p.csv", "--rays", "r.csv", "--out", "h.csv", "--method", "mesh", "--slices", "16777216"},
                "--method mesh with 16777216 slices needs about");
}

// ---------------------------------------------------------------------------------------------
// Options: an empty value is an error; every option error is one line and status 1.

TEST(Options, EmptyValuesAreErrorsNotDefaults) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kPlanarSensor);
  dir.write("poses.csv", kPoses);
  dir.write("p.csv", "r,z\n0,0\n1,0\n1,1\n0,1\n");
  dir.write("r.csv", "-5,0,0.5,1,0,0,0,inf\n");
  const std::vector<std::string> lidar{"scene.json", "--sensor", "sensor.json", "--poses",
                                       "poses.csv",  "-o",       "scan.csv"};
  const auto with = [](std::vector<std::string> args, const std::string& option, const std::string& value) {
    const auto at = std::find(args.begin(), args.end(), option);
    if (at != args.end()) {
      *(at + 1) = value;
    } else {
      args.insert(args.end(), {option, value});
    }
    return args;
  };
  expectRefusal(kLidar, "revolve-lidar", dir, with(lidar, "-o", ""),
                "--output: the value is empty; a file name is needed (see --help)");
  expectRefusal(kLidar, "revolve-lidar", dir, with(lidar, "--poses", ""), "--poses: the value is empty");
  expectRefusal(kLidar, "revolve-lidar", dir, with(lidar, "--plot", ""), "--plot: the value is empty");
  expectRefusal(kLidar, "revolve-lidar", dir, with(lidar, "--sensor", ""), "--sensor: the value is empty");
  const std::vector<std::string> clearance{"scene.json", "--robot", "0.3,0,1", "--poses", "poses.csv", "-o", "c.csv"};
  expectRefusal(kClearance, "revolve-clearance", dir, with(clearance, "-o", ""), "--output: the value is empty");
  expectRefusal(kClearance, "revolve-clearance", dir, with(clearance, "--poses", ""), "--poses: the value is empty");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "p.csv", "--rays", "r.csv", "--out", ""},
                "--out: the value is empty");
}

TEST(Options, ParserErrorsAreOneLineAndStatusOne) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kPlanarSensor);
  const std::vector<std::string> lidar{"scene.json", "--sensor", "sensor.json", "-o", "scan.csv"};
  std::vector<std::string> args = lidar;
  args.insert(args.end(), {"--slices", "2"});
  expectRefusal(kLidar, "revolve-lidar", dir, args,
                "--slices: 2 is out of range: it must lie in [3, 65536] (see --help)");
  args = lidar;
  args.insert(args.end(), {"--threads", "1.5"});
  expectRefusal(kLidar, "revolve-lidar", dir, args, "--threads: 1.5 is not a whole number (see --help)");
  args = lidar;
  args.insert(args.end(), {"--bogus"});
  expectRefusal(kLidar, "revolve-lidar", dir, args, "--bogus");
  expectRefusal(kLidar, "revolve-lidar", dir, {"scene.json", "-o", "scan.csv"}, "--sensor is required (see --help)");
  expectRefusal(kClearance, "revolve-clearance", dir,
                {"scene.json", "--robot", "0.3,0,1", "--poses", "p.csv", "-o", "c.csv", "--threads", "0"},
                "--threads: 0 is out of range: it must lie in [1, 1024]");
  args = lidar;
  args.insert(args.end(), {"--pcd-data", "binary"});
  expectRefusal(kLidar, "revolve-lidar", dir, args,
                "scan.csv: --pcd-data applies to .pcd outputs, and this one is a CSV table");
}

// ---------------------------------------------------------------------------------------------
// No output may be an input or another output: by identity where files exist (hard and symbolic
// links too), by normalised path otherwise.

TEST(Outputs, AnOutputThatIsAnInputOrAnotherOutputIsRefused) {
  const ScratchDirectory dir;
  dir.write("scene.json",
            replacedIn(kPoleScene, R"({"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]})", R"({"csv": "pole.csv"})"));
  dir.write("pole.csv", "r,z\n0,0\n0.25,0\n0.25,2\n0,2\n");
  dir.write("sensor.json", kPlanarSensor);
  dir.write("poses.csv", kPoses);
  dir.write("r.csv", "-5,0,0.5,1,0,0,0,inf\n");
  std::filesystem::create_symlink("poses.csv", dir / "poses_link.csv");
  std::filesystem::create_hard_link(dir / "poses.csv", dir / "poses_hard.csv");
  std::filesystem::create_directory(dir / "folder");
  const std::vector<std::string> lidar{"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o"};
  const auto lidarTo = [&](const std::string& output) {
    std::vector<std::string> args = lidar;
    args.push_back(output);
    return args;
  };
  expectRefusal(
      kLidar, "revolve-lidar", dir, lidarTo("poses.csv"),
      "poses.csv: -o names the same file as the poses file (--poses) (an input); an output may not overwrite an input");
  expectRefusal(kLidar, "revolve-lidar", dir, lidarTo("poses_link.csv"),
                "poses_link.csv: -o names the same file as the poses file");
  expectRefusal(kLidar, "revolve-lidar", dir, lidarTo("poses_hard.csv"),
                "poses_hard.csv: -o names the same file as the poses file");
  expectRefusal(kLidar, "revolve-lidar", dir, lidarTo("./pole.csv"),
                "./pole.csv: -o names the same file as a profile CSV of the scene");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "pole.csv", "--rays", "r.csv", "--out", "pole.csv"},
                "pole.csv: --out names the same file as the profile file (--profile)");
  expectRefusal(kTrace, "revolve-trace", dir, {"--profile", "pole.csv", "--rays", "r.csv", "--out", "folder/../r.csv"},
                "--out names the same file as the rays file (--rays)");
  expectRefusal(kClearance, "revolve-clearance", dir,
                {"scene.json", "--robot", "0.3,0,1", "--poses", "poses.csv", "-o", "poses_hard.csv"},
                "poses_hard.csv: -o names the same file as the poses file (--poses)");
  ASSERT_EQ(mkfifo((dir / "fifo.csv").c_str(), 0600), 0);
  expectRefusal(kLidar, "revolve-lidar", dir, lidarTo("fifo.csv"),
                "fifo.csv: -o names a FIFO (named pipe), not a regular file");
}

// revolve-render's refusals, in one test (each process loads OpenImageIO, half a second): the
// issue's far camera and tiny scale, option errors, empty values, outputs that are inputs.
TEST(Options, RevolveRenderRefusesInOneLineWithStatusOne) {
  const ScratchDirectory dir;
  const std::string scene =
      replacedIn(kPoleScene, R"({"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]})", R"({"csv": "pole.csv"})");
  dir.write("scene.json", scene);
  dir.write("pole.csv", "r,z\n0,0\n0.25,0\n0.25,2\n0,2\n");
  dir.write("far.json", replacedIn(scene, R"("from": [-3, 0, 1])", R"("from": [1e20, 0, 1])"));
  dir.write("tiny.json",
            replacedIn(scene, R"("translate": [2, 0, 0])", R"("translate": [2, 0, 0], "scale": [1e-20, 1, 1])"));
  dir.write("old.png", "an existing image");
  const auto refused = [&](const std::vector<std::string>& args, const std::string& expected) {
    SCOPED_TRACE(args.front() + " ...");
    expectRefusal(kRender, "revolve-render", dir, args, expected);
  };
  refused({"far.json", "-o", "old.png"},
          "far.json: camera.from[0]: 1e+20 is beyond the coordinate limit: positions lie within +-2^40 (1.1e12)");
  refused({"tiny.json", "-o", "old.png"},
          "tiny.json: objects[0].scale[0]: 1e-20 is out of range: scale factors lie in [2^-16, 2^40]");
  refused({"scene.json", "-o", "old.png", "--spp", "0"},
          "revolve-render: --spp: 0 is out of range: it must lie in [1, 1048576] (see --help)");
  refused({"scene.json", "-o", "old.png", "--width", "64.0000001"},
          "--width: 64.0000001 is not a whole number (see --help)");
  refused({"scene.json", "-o", ""}, "--output: the value is empty; a file name is needed (see --help)");
  refused({"scene.json", "-o", "old.png", "--stats", ""}, "--stats: the value is empty");
  refused({"scene.json", "--pick", ""}, "--pick: the value is empty");
  refused({"scene.json", "-o", "old.png", "--stats", "scene.json"},
          "scene.json: --stats names the same file as the scene file (an input); an output may not overwrite an input");
  refused({"scene.json", "-o", "old.png", "--stats", "./pole.csv"},
          "./pole.csv: --stats names the same file as a profile CSV of the scene");
  refused({"scene.json", "-o", "old.png", "--stats", "old.png"},
          "old.png: --stats names the same file as -o (old.png); each output needs a file of its own");
}

// ---------------------------------------------------------------------------------------------
// Degenerate scenes: valid, but an object shows nothing; one warning per object, and the run goes on.

TEST(DegenerateScenes, EachObjectThatShowsNothingIsWarnedOfOnce) {
  const ScratchDirectory dir;
  dir.write("scene.json", R"({
    "camera": {"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40, "width": 8, "height": 6, "spp": 1},
    "profiles": {"pole": {"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]},
                 "line": {"points": [[0, 0], [0, 1]]},
                 "room": {"points": [[0, -1], [10, -1], [10, 5], [0, 5]]}},
    "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
    "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0], "name": "pole"},
                {"profile": "line", "material": "grey", "name": "thread"},
                {"profile": "pole", "material": "grey", "translate": [1e6, 0, 0], "scale": 1.52587890625e-05, "name": "speck"},
                {"profile": "room", "material": "grey", "name": "room"},
                {"profile": "pole", "material": "grey", "translate": [-1, 5, 0], "name": "beside"}]
  })");
  dir.write("sensor.json", kPlanarSensor);
  const ProcessResult render = runIn(dir, kRender, {"scene.json", "-o", "image.png"});
  ASSERT_EQ(render.status, 0) << render.err;
  const std::string prefix = "revolve-render: warning: scene.json: objects[";
  EXPECT_EQ(render.err,
            prefix +
                "1] \"thread\": every point of profile \"line\" lies on the axis (r = 0): the surface has no area and "
                "nothing can hit it\n" +
                prefix +
                "2] \"speck\": placed, it spans 3.05e-05, less than one float step at its distance 1e+06 from the "
                "origin: Embree cannot place it, and its hits are lost to rounding\n" +
                prefix +
                "3] \"room\": the camera (camera.from) lies inside it: the view shows its inside, or nothing\n");
  EXPECT_TRUE(std::filesystem::exists(dir / "image.png"));
  // The lidar has no camera: the other two, once each.
  const ProcessResult lidar = runIn(dir, kLidar, {"scene.json", "--sensor", "sensor.json", "-o", "scan.csv"});
  ASSERT_EQ(lidar.status, 0) << lidar.err;
  EXPECT_EQ(lineCount(lidar.err), 2u) << lidar.err;
  EXPECT_THAT(lidar.err, HasSubstr("objects[1] \"thread\""));
  EXPECT_THAT(lidar.err, HasSubstr("objects[2] \"speck\""));
}

}  // namespace
}  // namespace revolve
