// revolve-lidar's --plot: a top-down PNG of a scan over the scene's footprint. Floors and other
// non-vertical quads are filled (higher ones on top), walls drawn as thick lines, each object of
// revolution as its outline seen from above with, for upright ones, its section at the first
// pose's sensor height (what a 2-D scanner at that height sees); then the returns' beams (at most
// 2,000 of them: every k-th when there are more, as the title says), the returns, and each pose's
// sensor with its heading; axes in the scene's units (metres). A 3-D scan can be plotted whole or
// one ring at a time. This file projects the scene; matplotlib draws it
// (tools/lidar/revolve_lidar_plot.py, run as a child process, terminated if this process is
// interrupted).
#pragma once

#include "io/poses_file.h"
#include "io/scan_files.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include "io/output_set.h"

namespace revolve::robot {

// Throws std::runtime_error naming the file unless it ends in .png (any case) and the plotter is
// beside this program. Call before scanning so that a typo costs nothing.
void checkPlotPath(const std::string& path);

// A scan's plot, drawn as the scan is traced: the scene's footprint and then each pose's returns
// go to a data file in the temporary folder as they come, so memory does not grow with the scan;
// finish() runs the plotter on it.
class ScanPlot {
 public:
  // Keeps references to all four: they must outlive it. With `ring`, only that ring's returns (0 =
  // the lowest) are plotted.
  ScanPlot(const io::SceneDescription& scene, const io::SensorDescription& sensor, std::span<const io::RobotPose> poses,
           const io::ScanLayout& layout, std::optional<std::size_t> ring = std::nullopt);
  ~ScanPlot();
  ScanPlot(const ScanPlot&) = delete;
  ScanPlot& operator=(const ScanPlot&) = delete;

  // Beams `first`, `first` + 1, ... in beam order (io::ScanLayout).
  void add(std::uint64_t first, std::span<const io::BeamReturn> beams);
  // Runs the plotter, its PNG into `png` (the output `path`'s stream); std::runtime_error naming
  // `path` with the plotter's last words when it fails (matplotlib missing, a full disk).
  void finish(io::OutputStream& png, const std::string& path);

 private:
  struct Data;
  std::unique_ptr<Data> data_;
};

}  // namespace revolve::robot
