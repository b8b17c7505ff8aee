// revolve-lidar's --plot: a top-down PNG of a scan over the scene's footprint. Floors and other
// non-vertical quads are filled (higher ones on top), walls drawn as thick lines, each object of
// revolution as its outline seen from above with, for upright ones, its section at the first
// pose's sensor height (what a 2-D scanner at that height sees); then the returns' beams (at most
// kMaxPlottedBeams of them), the returns, and each pose's sensor with its heading; axes in the
// scene's units (metres). A 3-D scan can be plotted whole or one ring at a time. This file
// projects the scene; matplotlib draws it (demo/lidar/revolve_lidar_plot.py, run as a child process).
#pragma once

#include "io/poses_file.h"
#include "io/scan_files.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>

namespace revolve::robot {

struct ScanPlotInput {
  const io::SceneDescription& scene;
  const io::SensorDescription& sensor;
  std::span<const io::RobotPose> poses;
  const io::ScanTable& scan;
  std::optional<std::size_t> ring;  // only this ring's beams and returns; all rings if none
};

// Beams drawn at most: beyond it every k-th return's beam is drawn (the title says which), or the
// 230,000 beams of a 3-D scan's eight poses would paint the whole footprint red.
inline constexpr std::size_t kMaxPlottedBeams = 2000;

// Throws std::runtime_error naming the file unless it ends in .png (any case), its folder takes a
// new file and the plotter is beside this program. Call before scanning so that a typo costs nothing.
void checkPlotPath(const std::string& path);

// Draws and writes the plot (through a temporary file renamed into place); std::runtime_error with
// the plotter's last words when it fails (matplotlib missing, say).
void writeScanPlot(const std::string& path, const ScanPlotInput& input);

}  // namespace revolve::robot
