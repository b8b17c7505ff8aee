// The sensor file (SENSOR.json): a laser range-finder as Gazebo's <lidar> sensor and ROS's
// LaserScan describe it, an interface other tools write, so its key names are kept as they are
// (README.md, "Robot range-finding"). Angles are in radians.
//
//   {"pose": {"position": [x, y, z], "yaw": a, "pitch": b, "roll": c},
//    "horizontal": {"samples": N, "min_angle": a0, "max_angle": a1},
//    "vertical": {"samples": M, "min_angle": e0, "max_angle": e1}   or   "elevations": [e, ...],
//    "range": {"min": r0, "max": r1, "resolution": q},
//    "noise": {"mean": m, "stddev": s, "seed": k},
//    "intensity_noise": {"stddev": s, "seed": k},
//    "rotation_rate": hz,
//    "divergence": d, "subrays": n, "returns": "first" | "last" | "strongest" | "all",
//    "max_returns": m, "return_separation": s,
//    "pattern": "beams.csv"}   (instead of horizontal and vertical/elevations)
//
// The reader is strict: a missing or unknown key, a wrong type or a value breaking a rule is a
// SensorError naming the file, the key path (`horizontal.samples`), the value and the rule.
#pragma once

#include "io/input_file.h"

#include "io/beam_pattern_file.h"

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

class SensorError : public std::runtime_error {
 public:
  explicit SensorError(const std::string& message) : std::runtime_error(message) {}
};

// The sensor's mounting on the robot: position, then ROS's fixed-axis roll (about X), pitch (about
// Y), yaw (about Z): R = Rz(yaw) Ry(pitch) Rx(roll).
struct SensorPose {
  std::array<double, 3> position{};
  double yaw = 0, pitch = 0, roll = 0;
};

// `samples` beams evenly spanning [minAngle, maxAngle], both ends included (Gazebo, ROS):
// beam i at minAngle + i (maxAngle - minAngle) / (samples - 1).
struct BeamFan {
  int samples = 1;
  double minAngle = 0, maxAngle = 0;
};

// Which of a beam's returns a scan reports (robot/beam_returns.h).
enum class ReturnMode { first, last, strongest, all };

struct SensorDescription {
  std::string file;  // as given to the reader
  SensorPose pose;
  BeamFan horizontal;  // azimuths, counter-clockwise about the sensor's +Z from its +X
  // One elevation per channel (ring), in ring order, up from the sensor's XY plane: from
  // `vertical` (ring 0 = min_angle), from `elevations` as listed, or {0} for a 2-D scanner.
  std::vector<double> elevations;
  bool planar = true;  // neither `vertical` nor `elevations` given: a 2-D scanner in its XY plane
  double rangeMin = 0, rangeMax = 0;
  double resolution = 0;                  // ranges rounded to a multiple of it; 0 = not rounded
  double noiseMean = 0, noiseStddev = 0;  // Gaussian, added to returns only; stddev 0 = none
  std::uint64_t noiseSeed = 0;
  // Gaussian intensity noise, relative: a return's intensity times 1 + stddev N(0, 1) (kept >= 0);
  // 0 = none. Its own seed, so that adding it changes no range.
  double intensityNoiseStddev = 0;
  std::uint64_t intensityNoiseSeed = 0;
  // Revolutions per second of a spinning sensor; 0: every beam of a sweep fires at the pose's
  // instant. With a rate, column k of a sweep fires k / (samples x rate) seconds after its start.
  double rotationRate = 0;
  // A beam's footprint: a cone of full angle `divergence` (radians) sampled by `subrays` rays
  // (robot/beam_footprint.h); 0 and 1: the beam is its axis.
  double divergence = 0;
  int subrays = 1;
  ReturnMode returns = ReturnMode::first;
  // Returns reported per beam with ReturnMode::all (the scan's layers, io::ScanLayout); else 1.
  int maxReturns = 2;
  // Sub-ray hits nearer each other than this (or than the range resolution) are one return.
  double returnSeparation = kDefaultReturnSeparation;
  // The beams of a pattern file, in its order (`pattern`); empty: the fans above. With a pattern
  // the scan is unorganised: one ring whose columns are the pattern's beams.
  std::vector<PatternBeam> pattern;
  std::string patternFile;  // as resolved against the sensor file's folder

  static constexpr double kDefaultReturnSeparation = 0.1;

  // Seconds from the sweep's start to the firing of the beams of `column`: the one place a beam's
  // time offset comes from.
  double columnTime(std::size_t column) const {
    if (!pattern.empty()) return pattern[column].time;
    return rotationRate > 0 ? double(column) / (double(horizontal.samples) * rotationRate) : 0.0;
  }
  // Whether the beams of a sweep fire at different times.
  bool fansOutInTime() const {
    if (!pattern.empty()) {
      for (const PatternBeam& beam : pattern)
        if (beam.time != 0) return true;
      return false;
    }
    return rotationRate > 0;
  }
  // Seconds from a sweep's start to its last beam's firing.
  double sweepDuration() const;
  // Returns reported per beam: the layers of the scan.
  int layers() const { return returns == ReturnMode::all ? maxReturns : 1; }
};

// The name of a return mode as the sensor file writes it.
const char* returnModeName(ReturnMode mode);

// A camera on the robot: a sensor file with "type": "camera", whose view revolve-render renders at
// every pose of a path (docs/robot.md, "Cameras along a path"). A pinhole of square pixels looking
// along its mounting's +X with +Z up (a lidar's beam at azimuth 0, elevation 0):
//
//   {"type": "camera", "pose": {"position": [x, y, z], "yaw": a, "pitch": b, "roll": c},
//    "width": W, "height": H, "fov": degrees}
//
// `fov` is the vertical field of view, as the scene file's camera gives it; width and height are
// pixels, each 1 to 16384.
struct CameraDescription {
  std::string file;
  SensorPose pose;
  int width = 0, height = 0;
  double fovDegrees = 0;
};

// A range sensor (a sonar or an infrared ranger) as ROS's sensor_msgs/Range describes one: a cone
// of full angle `field_of_view` (radians) about the sensor's +X, reporting the distance to the
// nearest surface inside it (robot/range_sensors.h). A sensor file with "type": "range" holds one
// sensor, or a ring of them under "sensors" (the other keys, given beside "sensors", are every
// sensor's defaults, and each entry may set its own):
//
//   {"type": "range", "pose": {...}, "name": "sonar",
//    "field_of_view": f, "min_range": r0, "max_range": r1,
//    "radiation_type": "ultrasound" | "infrared", "noise": {"mean": m, "stddev": s, "seed": k}}
//   {"type": "range", "field_of_view": f, ..., "sensors": [{"name": "sonar_0", "pose": {...}}, ...]}
enum class RadiationType { ultrasound = 0, infrared = 1 };  // ROS's Range.ULTRASOUND, Range.INFRARED

struct RangeSensorDescription {
  std::string name;  // unique in its file; default "range" (one sensor) or "range_<index>"
  SensorPose pose;
  double fieldOfView = 0;             // full cone angle, radians, in (0, pi]
  double minRange = 0, maxRange = 0;  // 0 <= minRange < maxRange, finite
  RadiationType radiation = RadiationType::ultrasound;
  double noiseMean = 0, noiseStddev = 0;  // Gaussian, added to a reading; stddev 0 = none
  std::uint64_t noiseSeed = 0;
};

struct RangeSensorsDescription {
  std::string file;
  std::vector<RangeSensorDescription> sensors;
};

inline constexpr std::size_t kMaxRangeSensors = 1024;

// The name of a radiation type as the sensor file writes it (ROS's constant, in lower case).
const char* radiationTypeName(RadiationType type);

// What a sensor file describes: its "type" (a lidar without one).
enum class SensorType { lidar, camera, range };
SensorType parseSensorType(std::string_view text, const std::string& file);
SensorType readSensorType(const std::string& path);

inline constexpr double kMaxRotationRate = 1e6;

// Limits that keep a scan's output within reason (about 1 GB of CSV a pose at most).
inline constexpr int kMaxHorizontalSamples = 1 << 20;
inline constexpr int kMaxChannels = 4096;
inline constexpr long kMaxBeamsPerPose = 1L << 24;  // points: beams x layers
inline constexpr double kMaxDivergence = 0.1;
inline constexpr int kMaxSubrays = 256;
inline constexpr int kMaxReturns = 255;  // the PCD's `return` field is one byte

// The angles of a fan's beams (see BeamFan).
std::vector<double> fanAngles(const BeamFan& fan);

// Parses sensor JSON `text`; `file` names it in messages. Throws SensorError.
SensorDescription parseSensor(std::string_view text, const std::string& file);
// Reads and parses the file at `path`. Throws SensorError.
SensorDescription readSensor(const std::string& path);
// The same, a beam pattern's text taken from (or, as it is read, kept in) `patterns` by its path
// as resolved, and the sensor file's own in `text`: what rebuilds the sensor where the files are not.
SensorDescription parseSensor(std::string_view text, const std::string& file, FileTexts& patterns);
SensorDescription readSensor(const std::string& path, std::string& text, FileTexts& patterns);
// The same for a camera's file. Throws SensorError.
CameraDescription parseCamera(std::string_view text, const std::string& file);
CameraDescription readCamera(const std::string& path);
// The same for range sensors' files.
RangeSensorsDescription parseRangeSensors(std::string_view text, const std::string& file);
RangeSensorsDescription readRangeSensors(const std::string& path);

}  // namespace revolve::io
