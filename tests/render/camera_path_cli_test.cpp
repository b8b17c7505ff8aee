// revolve-render --camera --poses: a robot's camera rendered at every pose of a path. Checked
// against what is independent of it: the same view written into a scene file's camera renders the
// same image byte for byte; the depth image of a pole and a floor against the closed-form
// intersections of each pixel's ray, written here from the scene camera's conventions; the
// CameraInfo's K against the pinhole's definition; and bad inputs refused in one line with
// nothing written.
#include "../io/scratch_directory.h"
#include "support/process.h"

#include <OpenImageIO/imagebuf.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <vector>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using testing::readWholeFile;
using testing::ScratchDirectory;

testing::ProcessResult runRender(const std::string& directory, const std::vector<std::string>& args) {
  return testing::runProcess(REVOLVE_RENDER_PATH, args, directory);
}

// A pole of radius 0.25 at (2, 0), 2 high, on a floor quad at z = 0.
std::string poleScene(const std::string& camera) {
  return R"({"camera": )" + camera + R"(,
    "profiles": {"pole": {"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]}},
    "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
    "lights": [{"type": "sun", "direction": [0.3, 0.5, -0.8], "irradiance": [2, 2, 2]}],
    "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0]}],
    "quads": [{"corners": [[-10, -10, 0], [10, -10, 0], [10, 10, 0], [-10, 10, 0]], "material": "grey"}]})";
}

const char* kCamera = R"({"type": "camera", "pose": {"position": [0.1, 0, 0.6], "pitch": 0.2},
                          "width": 48, "height": 36, "fov": 50})";

std::string number(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

TEST(RevolveRenderCameraCliTest, EachFrameIsTheSceneCameraAtThatPose) {
  const ScratchDirectory dir;
  dir.write("scene.json", poleScene(R"({"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40})"));
  // Level poses (yaw only) and a camera mounted level: its view is from (x + 0.1 cos yaw, y + 0.1
  // sin yaw, 0.6) along (cos yaw, sin yaw, 0), up +Z.
  dir.write("camera.json", R"({"type": "camera", "pose": {"position": [0.1, 0, 0.6]}, "width": 48, "height": 36,
                               "fov": 50})");
  dir.write("poses.csv", "x,y,yaw\n-1,0.2,0.1\n0,0,0\n");
  std::filesystem::create_directories(dir.path() / "frames");
  const testing::ProcessResult run = runRender(dir.path(), {"scene.json", "--camera", "camera.json", "--poses",
                                                            "poses.csv", "-o", "frames/f.png", "--spp", "2"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("frame 2 of 2: frames/f_0001.png"));
  const double yaw = 0.1;
  const double x = -1 + 0.1 * std::cos(yaw), y = 0.2 + 0.1 * std::sin(yaw);
  const std::string camera = R"({"from": [)" + number(x) + ", " + number(y) + R"(, 0.6], "to": [)" +
                             number(x + std::cos(yaw)) + ", " + number(y + std::sin(yaw)) +
                             R"(, 0.6], "up": [0, 0, 1], "fov": 50})";
  dir.write("view.json", poleScene(camera));
  const testing::ProcessResult view =
      runRender(dir.path(), {"view.json", "-o", "view.png", "--width", "48", "--height", "36", "--spp", "2"});
  ASSERT_EQ(view.status, 0) << view.err;
  EXPECT_EQ(readWholeFile(dir / "frames/f_0000.png"), readWholeFile(dir / "view.png"));
  EXPECT_NE(readWholeFile(dir / "frames/f_0001.png"), readWholeFile(dir / "view.png"));
  // CameraInfo: K of the pinhole, fy = (height / 2) / tan(fov / 2), principal point at the centre
  // in ROS's pixel coordinates (integers at pixel centres).
  const nlohmann::json info = nlohmann::json::parse(readWholeFile(dir / "frames/f_0000.json"));
  const double f = 18 / std::tan(25 * std::numbers::pi / 180);
  EXPECT_EQ(info["width"], 48);
  EXPECT_EQ(info["height"], 36);
  EXPECT_EQ(info["distortion_model"], "none");
  EXPECT_NEAR(info["k"][0].get<double>(), f, 1e-12 * f);
  EXPECT_NEAR(info["k"][4].get<double>(), f, 1e-12 * f);
  EXPECT_EQ(info["k"][2].get<double>(), 23.5);
  EXPECT_EQ(info["k"][5].get<double>(), 17.5);
  EXPECT_NEAR(info["position"][0].get<double>(), x, 1e-15);
  // The optical frame's z (forward) is the rotation's third column.
  EXPECT_NEAR(info["rotation"][2].get<double>(), std::cos(yaw), 1e-15);
  EXPECT_NEAR(info["rotation"][5].get<double>(), std::sin(yaw), 1e-15);
  EXPECT_EQ(info["image"], "f_0000.png");
}

// The depth of every pixel: its ray through the pixel's centre (the scene camera's pinhole, written
// here from its definition), intersected in closed form with the pole's side and top and with the
// floor, the nearest hit's distance along the optical axis.
TEST(RevolveRenderCameraCliTest, TheDepthImageIsTheClosedFormDistanceAlongTheOpticalAxis) {
  const ScratchDirectory dir;
  dir.write("scene.json", poleScene(R"({"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40})"));
  dir.write("camera.json", kCamera);
  dir.write("poses.csv", "x,y,yaw\n0,0.05,0\n");
  const testing::ProcessResult run =
      runRender(dir.path(), {"scene.json", "--camera", "camera.json", "--poses", "poses.csv", "-o", "f.png", "--spp",
                             "1", "--depth-image", "d.exr"});
  ASSERT_EQ(run.status, 0) << run.err;
  OIIO::ImageBuf depth(dir / "d_0000.exr");
  ASSERT_TRUE(depth.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << depth.geterror();
  ASSERT_EQ(depth.spec().nchannels, 1);
  EXPECT_EQ(depth.spec().channelnames[0], "Z");
  EXPECT_EQ(depth.spec().format, OIIO::TypeDesc::FLOAT);
  ASSERT_EQ(depth.spec().width, 48);
  ASSERT_EQ(depth.spec().height, 36);
  // The camera: at (0.1, 0.05, 0.6), pitched down by 0.2 (ROS: +pitch turns +X down).
  const double p = 0.2;
  const double o[3] = {0.1, 0.05, 0.6};
  const double forward[3] = {std::cos(p), 0, -std::sin(p)}, up[3] = {std::sin(p), 0, std::cos(p)};
  const double right[3] = {0, -1, 0};  // forward x up
  const double half = std::tan(25 * std::numbers::pi / 180), aspect = 48.0 / 36.0;
  int onPole = 0, onFloor = 0;
  for (int py = 0; py < 36; ++py) {
    for (int px = 0; px < 48; ++px) {
      const double sx = 2 * (px + 0.5) / 48 - 1, sy = 1 - 2 * (py + 0.5) / 36;
      double d[3];
      for (int i = 0; i < 3; ++i) d[i] = forward[i] + sx * half * aspect * right[i] + sy * half * up[i];
      double best = INFINITY;
      // The pole's side: |(o + t d - (2, 0))_xy| = 0.25, z in [0, 2]; its top: z = 2, r <= 0.25.
      const double a = d[0] * d[0] + d[1] * d[1], b = (o[0] - 2) * d[0] + o[1] * d[1];
      const double c = (o[0] - 2) * (o[0] - 2) + o[1] * o[1] - 0.0625;
      bool pole = false;
      if (b * b - a * c >= 0) {
        const double t = (-b - std::sqrt(b * b - a * c)) / a;
        const double z = o[2] + t * d[2];
        if (t > 0 && z >= 0 && z <= 2) best = t, pole = true;
      }
      if (d[2] < 0) {  // the floor quad, [-10, 10] x [-10, 10]
        const double t = -o[2] / d[2];
        if (t < best && std::abs(o[0] + t * d[0]) <= 10 && std::abs(o[1] + t * d[1]) <= 10) best = t, pole = false;
      }
      float got = 0;
      depth.getpixel(px, py, &got, 1);
      if (std::isinf(best)) {
        EXPECT_TRUE(std::isinf(got)) << px << ", " << py;
        continue;
      }
      (pole ? onPole : onFloor) += 1;
      const double z = best * (d[0] * forward[0] + d[1] * forward[1] + d[2] * forward[2]);
      // Float rays (origin and direction rounded) and a float result: 2^-20 of the distance.
      EXPECT_NEAR(got, z, 0x1p-20 * (best + 1) * 4) << px << ", " << py;
    }
  }
  EXPECT_GT(onPole, 20);
  EXPECT_GT(onFloor, 200);
}

TEST(RevolveRenderCameraCliTest, BadInputsAreOneLineAndWriteNothing) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {"zero.json: width: 0 is out of range", {"--camera", "zero.json", "--poses", "poses.csv", "-o", "f.png"}},
      {"wide.json: fov: 180 is out of range", {"--camera", "wide.json", "--poses", "poses.csv", "-o", "f.png"}},
      {"empty.csv: no poses after the header", {"--camera", "camera.json", "--poses", "empty.csv", "-o", "f.png"}},
      {"--camera and --poses go together", {"--camera", "camera.json", "-o", "f.png"}},
      {"d.png: a depth image is written as EXR",
       {"--camera", "camera.json", "--poses", "poses.csv", "-o", "f.png", "--depth-image", "d.png"}},
      {"the camera file gives the image's width and height",
       {"--camera", "camera.json", "--poses", "poses.csv", "-o", "f.png", "--width", "10"}},
      {"sensor.json: type: \"lidar\": expected \"camera\"",
       {"--camera", "sensor.json", "--poses", "poses.csv", "-o", "f.png"}},
  };
  for (const auto& [expected, args] : cases) {
    SCOPED_TRACE(expected);
    const ScratchDirectory dir;
    dir.write("scene.json", poleScene(R"({"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40})"));
    dir.write("camera.json", kCamera);
    dir.write("zero.json",
              R"({"type": "camera", "pose": {"position": [0, 0, 1]}, "width": 0, "height": 4, "fov": 50})");
    dir.write("wide.json",
              R"({"type": "camera", "pose": {"position": [0, 0, 1]}, "width": 4, "height": 4, "fov": 180})");
    dir.write("sensor.json", R"({"type": "lidar", "pose": {"position": [0, 0, 1]}})");
    dir.write("poses.csv", "x,y,yaw\n0,0,0\n");
    dir.write("empty.csv", "x,y,yaw\n");
    const std::set<std::string> before = dir.entries();
    std::vector<std::string> full{"scene.json"};
    full.insert(full.end(), args.begin(), args.end());
    const testing::ProcessResult run = runRender(dir.path(), full);
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_THAT(run.err, HasSubstr(expected));
    EXPECT_EQ(dir.entries(), before);
  }
}

}  // namespace
}  // namespace revolve
