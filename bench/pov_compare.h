// revolve-bench pov and pov-scaling: revolve beside POV-Ray 3.7, the one widely used ray tracer
// with surfaces of revolution (its `lathe`).
//
// pov: one scene exported to POV-Ray SDL (io/pov_scene.h) and rendered by both at the same size,
// one sample a pixel, the same reflection depth, point lights only, on one thread and on all;
// revolve's render time (in process, whitted) against POV-Ray's Trace Time statistic (its
// rendering alone, not its start-up, parsing or bounding), medians of interleaved repetitions
// (revolve's rendered several times a repetition, its renders being so much shorter); the
// images compared after matching exposure and written side by side.
//
// pov-scaling: one lathe (the benchmark's vase) at 16 to 32,767 profile points, the same camera
// and light, the trace time of both at each point count; then the vase as a spline of cubic Bézier
// pieces, traced exactly by revolve and by POV-Ray as a bezier_spline lathe of the same pieces.
#pragma once

#include "image_compare.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace revolve::bench {

struct PovCompareSettings {
  std::string scene = "scenes/patio_points.json";
  int width = 0, height = 0;  // 0: the scene's camera size, else 640 x 480
  int depth = 4;
  bool shadows = true;
  int threads = 0;  // the "all threads" count; 0: the machine's
  int repetitions = 5;
  std::string outDirectory = "out/pov";
  std::string figure;  // the side-by-side PNG; empty: <outDirectory>/<scene name>_side_by_side.png
};

struct TimedRun {
  int threads = 1;
  double revolveSeconds = 0, revolveLow = 0, revolveHigh = 0;  // median and range
  int revolveRenders = 0;                                      // renders the median is of
  double povraySeconds = 0, povrayLow = 0, povrayHigh = 0;     // Trace Time
  double povrayParseSeconds = 0, povrayBoundingSeconds = 0;    // medians
  double ratio() const { return povraySeconds / revolveSeconds; }
};

struct PovComparison {
  int width = 0, height = 0;
  std::vector<TimedRun> runs;  // one thread, then all threads
  double revolveBuildSeconds = 0;
  std::uint64_t revolveRays = 0, revolveShadowRays = 0, povrayRays = 0, povrayShadowRayTests = 0, povrayLatheTests = 0;
  ImageDifference difference;
  std::string povFile, figure, revolveImage, povrayImage;
};

PovComparison runPovComparison(const std::string& povray, const PovCompareSettings& settings);
void printPovComparison(std::FILE* out, const PovCompareSettings& settings, const PovComparison& comparison);
nlohmann::ordered_json povComparisonJson(const PovCompareSettings& settings, const PovComparison& comparison);

struct PovScalingSettings {
  std::vector<int> points = {16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384, 32767};
  int size = 300;   // image size x size
  int threads = 0;  // both renderers; 0: the machine's
  int repetitions = 3;
  std::string outDirectory = "out/pov/scaling";
};

struct PovScalingPoint {
  int points = 0;       // profile points; for the spline, its Bézier pieces
  bool spline = false;  // the vase as a spline traced exactly (POV-Ray: a bezier_spline lathe)
  TimedRun timing;
  ImageDifference difference;
};

std::vector<PovScalingPoint> runPovScaling(const std::string& povray, const PovScalingSettings& settings);
void printPovScaling(std::FILE* out, const PovScalingSettings& settings, const std::vector<PovScalingPoint>& points);
nlohmann::ordered_json povScalingJson(const PovScalingSettings& settings, const std::vector<PovScalingPoint>& points);

}  // namespace revolve::bench
