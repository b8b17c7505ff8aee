// What the hostile-input tests share: small scenes, sensors and poses, and the check every refusal
// must pass (status 1, one stderr line starting with the tool's name and naming the input, no
// output and no temporary left, inputs untouched).
#pragma once

#include "support/process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace revolve::testing {

// A pole of radius 0.25 at (2, 0), 2 m tall, and a floor; the camera looks at the pole.
inline const std::string kPoleScene = R"({
  "camera": {"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40, "width": 8, "height": 6, "spp": 1},
  "profiles": {"pole": {"points": [[0, 0], [0.25, 0], [0.25, 2], [0, 2]]}},
  "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
  "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0], "name": "pole 1"}],
  "quads": [{"corners": [[-10, -10, 0], [10, -10, 0], [10, 10, 0], [-10, 10, 0]], "material": "grey"}],
  "lights": [{"type": "sun", "direction": [0.3, 0.2, -1], "irradiance": [2, 2, 2]}],
  "environment": {"color": [0.2, 0.2, 0.2]}
})";

// Three beams at -pi/2, 0, pi/2 in the plane 0.5 above the floor.
inline const std::string kPlanarSensor = R"({
  "pose": {"position": [0, 0, 0.5], "yaw": 0},
  "horizontal": {"samples": 3, "min_angle": -1.5707963267948966, "max_angle": 1.5707963267948966},
  "range": {"min": 0.1, "max": 30}
})";

// A spinning 3-D sensor of 16 x 1,800 beams (a Velodyne VLP-16's layout).
inline const std::string kSpinningSensor = R"({
  "pose": {"position": [0, 0, 0.7]},
  "horizontal": {"samples": 1800, "min_angle": -3.141592653589793, "max_angle": 3.138101798010019},
  "vertical": {"samples": 16, "min_angle": -0.2617993877991494, "max_angle": 0.2617993877991494},
  "range": {"min": 0.4, "max": 100}
})";

inline const std::string kPoses = "x,y,yaw\n0,0,0\n0.5,0,0\n";

// `count` poses along x (header x,y,yaw).
inline std::string manyPoses(int count) {
  std::string text = "x,y,yaw\n";
  for (int i = 0; i < count; ++i) text += std::to_string(0.001 * i) + ",0," + std::to_string(0.01 * i) + "\n";
  return text;
}

inline std::size_t lineCount(const std::string& text) {
  return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

inline std::string replacedIn(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The contents of every regular file in `dir` (the size alone of those over 1 MiB), to see that a
// refusal changed nothing.
inline std::map<std::string, std::string> snapshot(const ScratchDirectory& dir) {
  std::map<std::string, std::string> files;
  for (const std::string& name : dir.entries()) {
    const std::string path = dir / name;
    if (!std::filesystem::is_symlink(path) && std::filesystem::is_regular_file(path)) {
      const auto size = std::filesystem::file_size(path);
      files[name] = size > (1u << 20) ? "size " + std::to_string(size) : readWholeFile(path);
    }
  }
  return files;
}

// Runs `tool` (in `dir`) and checks the refusal: status 1, one stderr line "<name>: ...",
// containing `expected`; every file in `dir` as it was and nothing added.
inline void expectRefusal(const std::string& tool, const std::string& name, const ScratchDirectory& dir,
                          const std::vector<std::string>& args, const std::string& expected) {
  const auto before = snapshot(dir);
  const std::set<std::string> entries = dir.entries();
  const ProcessResult run = runProcess(tool, args, ProcessOptions{.directory = dir.path().string()}, 30);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_EQ(lineCount(run.err), 1u) << run.err;
  EXPECT_THAT(run.err, ::testing::StartsWith(name + ": "));
  EXPECT_THAT(run.err, ::testing::HasSubstr(expected));
  EXPECT_EQ(dir.entries(), entries) << "no output, no temporary file";
  EXPECT_EQ(snapshot(dir), before) << "a file was changed";
}

}  // namespace revolve::testing
