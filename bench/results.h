// What a benchmark run measured, kept whole for the tables, the JSON and the CSV.
#pragma once

#include "error_metrics.h"
#include "timing.h"
#include "traced_scene.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace revolve::bench {

// Timing modes: which rays, and how they are handed to Embree.
inline constexpr const char* kIncoherent1 = "incoherent_1";      // rtcIntersect1, one thread
inline constexpr const char* kCamera1 = "camera_1";              // rtcIntersect1, one thread
inline constexpr const char* kCamera8 = "camera_8";              // rtcIntersect8, one thread
inline constexpr const char* kIncoherentAll = "incoherent_all";  // rtcIntersect1, all threads
inline constexpr const char* kOccluded1 = "occluded_1";          // incoherent rays, rtcOccluded1, one thread
inline constexpr const char* kOccluded8 = "occluded_8";          // camera rays, rtcOccluded8, one thread
// Every mode, in the order the tables print them.
inline constexpr const char* kModes[] = {kIncoherent1, kCamera8, kCamera1, kIncoherentAll, kOccluded1, kOccluded8};

struct ConfigResult {
  MethodConfig config;
  std::string limitation;  // why the method cannot trace this shape (then nothing else is measured)
  double buildSeconds = 0;
  std::size_t revolveBytes = 0;
  std::int64_t embreeBytes = 0;
  std::uint64_t triangles = 0;
  std::optional<ErrorSummary> incoherent, camera;  // absent for the analytic sphere on other shapes
  std::map<std::string, Throughput> speed;         // by timing mode
  double totalBytes() const { return double(revolveBytes) + double(embreeBytes); }
};

// The fastest MIBIT (cylinder shells) and the fastest mesh whose largest error is within `level`,
// for one shape and timing mode, and the smallest memory of each within it; and the fastest of
// Embree's cone curves and round curves within it.
struct MatchedRow {
  std::string shape, mode;
  double level;
  std::optional<std::size_t> mibit, mesh;  // indices into the shape's configs
  std::optional<std::size_t> leanestMibit, leanestMesh;
  std::optional<std::size_t> embreeCone, embreeRoundCurve;
};

// Points a polyline needs for one max error (relative to the size): `samplePoints` of
// SmoothProfile::sample (one sagitta for every arc's chords), and the fewest of Profile::fromCurve
// and of even spacing within the same error, all from closed forms.
struct PointsRow {
  int samplePoints = 0;
  double error = 0;
  int adaptivePoints = 0, uniformPoints = 0;
};

struct ShapeResult {
  std::string name;
  double size = 0;
  double splineError = 0;        // the spline's own distance from the profile, relative to the size
  std::size_t splinePieces = 0;  // its cubic pieces
  std::vector<PointsRow> points;
  std::size_t incoherentRays = 0, cameraRays = 0, incoherentGrazing = 0, cameraGrazing = 0;
  std::vector<ConfigResult> configs;
  std::vector<MatchedRow> matched;
};

struct RunSettings {
  bool quick = false;
  std::size_t incoherentRays = 200000;
  int cameraWidth = 512, cameraHeight = 512;
  int repetitions = 5;
  double minSeconds = 0.05;
  std::uint64_t seed = 20011;
};

struct RunResults {
  RunSettings settings;
  std::vector<ShapeResult> speedError;  // the speed-error subcommand
  std::vector<ShapeResult> scaling;     // the scaling subcommand (one shape)
};

// Fills ShapeResult::matched for the given error levels.
void matchErrorLevels(ShapeResult& shape, const std::vector<double>& levels);
// Fills ShapeResult::points.
class SmoothProfile;
void comparePolylinePoints(ShapeResult& shape, const SmoothProfile& profile);

}  // namespace revolve::bench
