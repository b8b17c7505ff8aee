#include "io/sensor_file.h"

#include "io/beam_pattern_file.h"
#include "io/json_reader.h"
#include "io/text_files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace revolve::io {
namespace {

using json::child;
using json::element;
using json::Json;
using json::numberText;
using Reader = json::Reader<SensorError>;

// Angles are radians: a value beyond a full turn either way is most likely degrees.
constexpr double kTurn = 2 * std::numbers::pi;
constexpr double kRightAngle = std::numbers::pi / 2;

double angle(const Reader& in, const Json& value, const std::string& path) {
  return in.numberIn(value, path, -kTurn, kTurn, "angles are in radians, within [-2 pi, 2 pi] (degrees?)");
}

double elevation(const Reader& in, const Json& value, const std::string& path) {
  return in.numberIn(value, path, -kRightAngle, kRightAngle, "an elevation lies in [-pi/2, pi/2] radians");
}

SensorPose readPose(const Reader& in, const Json& json, const std::string& path = "pose") {
  in.object(json, path, {"position", "yaw", "pitch", "roll"});
  SensorPose pose;
  pose.position = in.position(in.required(json, path, "position"), child(path, "position"));
  if (const Json* v = in.optional(json, "yaw")) pose.yaw = angle(in, *v, child(path, "yaw"));
  if (const Json* v = in.optional(json, "pitch")) pose.pitch = angle(in, *v, child(path, "pitch"));
  if (const Json* v = in.optional(json, "roll")) pose.roll = angle(in, *v, child(path, "roll"));
  return pose;
}

// Gaussian noise: {"mean": m, "stddev": s, "seed": k}, stddev required.
void readNoise(const Reader& in, const Json& noise, const std::string& path, double& mean, double& stddev,
               std::uint64_t& seed) {
  in.object(noise, path, {"mean", "stddev", "seed"});
  stddev = in.number(in.required(noise, path, "stddev"), child(path, "stddev"));
  if (!(stddev >= 0)) in.fail(child(path, "stddev"), numberText(stddev) + " is negative");
  if (const Json* v = in.optional(noise, "mean")) mean = in.number(*v, child(path, "mean"));
  if (const Json* v = in.optional(noise, "seed")) seed = in.unsignedInteger(*v, child(path, "seed"));
}

std::string readText(const std::string& path) {
  try {
    return readTextFile(path, kMaxJsonFileBytes, "a JSON file");
  } catch (const InputError& error) {
    throw SensorError(error.what());
  }
}

// A fan of beams; `limit` reads one angle (azimuths may span a turn, elevations half of one).
template <class ReadAngle>
BeamFan readFan(const Reader& in, const Json& json, const std::string& path, int maxSamples, ReadAngle limit) {
  in.object(json, path, {"samples", "min_angle", "max_angle"});
  BeamFan fan;
  fan.samples = in.integerIn(in.required(json, path, "samples"), child(path, "samples"), 1, maxSamples);
  fan.minAngle = limit(in.required(json, path, "min_angle"), child(path, "min_angle"));
  fan.maxAngle = limit(in.required(json, path, "max_angle"), child(path, "max_angle"));
  if (!(fan.minAngle <= fan.maxAngle)) {
    in.fail(child(path, "max_angle"), numberText(fan.maxAngle) + " is below min_angle = " + numberText(fan.minAngle) +
                                          ": beams run from min_angle up to max_angle");
  }
  if (fan.maxAngle - fan.minAngle > kTurn) {
    in.fail(child(path, "max_angle"),
            "the fan spans " + numberText(fan.maxAngle - fan.minAngle) + " radians, more than a full turn (2 pi)");
  }
  if (fan.samples == 1 && fan.minAngle != fan.maxAngle) {
    in.fail(child(path, "max_angle"), numberText(fan.maxAngle) +
                                          " differs from min_angle = " + numberText(fan.minAngle) +
                                          ": with 1 sample the one beam is at min_angle = max_angle");
  }
  return fan;
}

// The footprint and return keys (divergence, subrays, returns, max_returns, return_separation).
void readReturns(const Reader& in, const Json& root, SensorDescription& sensor) {
  if (const Json* v = in.optional(root, "divergence")) {
    sensor.divergence = in.numberIn(*v, "divergence", 0, kMaxDivergence,
                                    "a beam's full divergence angle lies in [0, 0.1] radians (degrees?)");
  }
  if (const Json* v = in.optional(root, "subrays")) sensor.subrays = in.integerIn(*v, "subrays", 1, kMaxSubrays);
  if (const Json* v = in.optional(root, "returns")) {
    const std::string mode = in.string(*v, "returns");
    bool known = false;
    for (const ReturnMode m : {ReturnMode::first, ReturnMode::last, ReturnMode::strongest, ReturnMode::all}) {
      if (mode == returnModeName(m)) {
        sensor.returns = m;
        known = true;
      }
    }
    if (!known) {
      in.fail("returns", json::quotedText(mode) +
                             " is not a return mode; expected one of: \"first\", \"last\", \"strongest\", \"all\"");
    }
  }
  if (const Json* v = in.optional(root, "max_returns")) {
    if (sensor.returns != ReturnMode::all) {
      in.fail("max_returns", std::string("applies to \"returns\": \"all\" only; returns is \"") +
                                 returnModeName(sensor.returns) + "\", one return a beam");
    }
    sensor.maxReturns = in.integerIn(*v, "max_returns", 1, kMaxReturns);
  }
  // A footprint needs both: a cone and more than one ray across it.
  if (sensor.divergence > 0 && sensor.subrays == 1) {
    in.fail("subrays", "1 with divergence = " + numberText(sensor.divergence) +
                           ": one sub-ray is the beam's axis alone, so the divergence would do nothing; sample the "
                           "cone with subrays > 1, or set divergence 0");
  }
  if (sensor.divergence == 0 && sensor.subrays > 1) {
    in.fail("subrays", std::to_string(sensor.subrays) +
                           " with divergence 0: every sub-ray would be the beam's axis; give the cone's divergence");
  }
  if (const Json* v = in.optional(root, "return_separation")) {
    sensor.returnSeparation = in.number(*v, "return_separation");
    if (!(sensor.returnSeparation > 0))
      in.fail("return_separation", numberText(sensor.returnSeparation) + " is not above 0: a distance between returns");
  }
}

}  // namespace

const char* returnModeName(ReturnMode mode) {
  switch (mode) {
    case ReturnMode::first:
      return "first";
    case ReturnMode::last:
      return "last";
    case ReturnMode::strongest:
      return "strongest";
    case ReturnMode::all:
      return "all";
  }
  return "?";
}

double SensorDescription::sweepDuration() const {
  double last = 0;
  if (!pattern.empty()) {
    for (const PatternBeam& beam : pattern) last = std::max(last, beam.time);
    return last;
  }
  return columnTime(std::size_t(horizontal.samples - 1));
}

std::vector<double> fanAngles(const BeamFan& fan) {
  std::vector<double> angles(std::size_t(fan.samples));
  for (int i = 0; i < fan.samples; ++i) {
    angles[i] = fan.samples == 1 ? fan.minAngle : fan.minAngle + i * (fan.maxAngle - fan.minAngle) / (fan.samples - 1);
  }
  angles.back() = fan.maxAngle;  // exactly, whatever the rounding of the step
  return angles;
}

namespace {

// parseSensor, the beam pattern's text from `patterns` when given.
SensorDescription parseSensorWith(std::string_view text, const std::string& file, FileTexts* patterns) {
  const Reader in(file);
  const Json root = json::parse(text, in);
  if (root.is_object() && root.contains("type")) {
    const std::string type = in.string(root["type"], "type");
    if (type == "camera")
      in.fail("type", "\"camera\": a camera's file; revolve-render renders it along a path (--camera)");
    if (type == "range")
      in.fail("type",
              "\"range\": a range sensor's file (sonar or infrared cones), read as one by revolve-lidar and "
              "revolve.RangeSensors, not as a lidar");
    if (type != "lidar")
      in.fail("type", json::quotedText(type) +
                          " is not a sensor type; expected \"lidar\" (the default), \"range\" "
                          "or \"camera\"");
  }
  in.object(root, "",
            {"pose", "horizontal", "vertical", "elevations", "pattern", "range", "noise", "intensity_noise",
             "rotation_rate", "divergence", "subrays", "returns", "max_returns", "return_separation", "type"});
  SensorDescription sensor;
  sensor.file = file;
  sensor.pose = readPose(in, in.required(root, "", "pose"));
  const auto azimuth = [&](const Json& value, const std::string& path) { return angle(in, value, path); };
  const auto upward = [&](const Json& value, const std::string& path) { return elevation(in, value, path); };

  const Json* vertical = in.optional(root, "vertical");
  const Json* elevations = in.optional(root, "elevations");
  if (const Json* pattern = in.optional(root, "pattern")) {
    for (const char* fan : {"horizontal", "vertical", "elevations"}) {
      if (in.optional(root, fan) != nullptr)
        in.fail(fan,
                "give either \"pattern\" (a beam table) or the fans (horizontal, vertical or elevations), not both");
    }
    if (in.optional(root, "rotation_rate") != nullptr)
      in.fail("rotation_rate",
              "a pattern's beams carry their own firing times (its time column); rotation_rate is for fans");
    const std::string name = in.string(*pattern, "pattern");
    if (name.empty()) in.fail("pattern", "the path is empty");
    // Relative to the sensor file, so that a sensor and its pattern travel together.
    const std::filesystem::path path(name);
    sensor.patternFile =
        path.is_absolute() ? name : (std::filesystem::path(file).parent_path() / path).lexically_normal().string();
    try {
      sensor.pattern =
          patterns != nullptr
              ? parseBeamPattern(patterns->text(sensor.patternFile, kMaxPatternFileBytes, "a beam pattern file"),
                                 sensor.patternFile)
              : readBeamPattern(sensor.patternFile);
    } catch (const InputError& error) {
      in.fail("pattern", error.what());
    }
    sensor.elevations = {0.0};
    sensor.planar = false;
  } else {
    sensor.horizontal = readFan(in, in.required(root, "", "horizontal"), "horizontal", kMaxHorizontalSamples, azimuth);
    if (vertical != nullptr && elevations != nullptr) {
      in.fail("elevations", "give either \"vertical\" (an even fan) or \"elevations\" (a list), not both");
    } else if (vertical != nullptr) {
      sensor.elevations = fanAngles(readFan(in, *vertical, "vertical", kMaxChannels, upward));
      sensor.planar = false;
    } else if (elevations != nullptr) {
      in.array(*elevations, "elevations");
      if (elevations->empty()) in.fail("elevations", "the list is empty; a sensor needs at least one channel");
      if (elevations->size() > std::size_t(kMaxChannels)) {
        in.fail("elevations",
                std::to_string(elevations->size()) + " channels; at most " + std::to_string(kMaxChannels));
      }
      for (std::size_t i = 0; i < elevations->size(); ++i)
        sensor.elevations.push_back(upward((*elevations)[i], element("elevations", i)));
      sensor.planar = false;
    } else {
      sensor.elevations = {0.0};
    }
  }
  const long beams = sensor.pattern.empty() ? long(sensor.horizontal.samples) * long(sensor.elevations.size())
                                            : long(sensor.pattern.size());
  if (sensor.pattern.empty() && beams > kMaxBeamsPerPose) {
    in.fail("horizontal.samples",
            std::to_string(sensor.horizontal.samples) + " samples x " + std::to_string(sensor.elevations.size()) +
                " channels = " + std::to_string(beams) + " beams a pose; at most " + std::to_string(kMaxBeamsPerPose));
  }

  const Json& range = in.object(in.required(root, "", "range"), "range", {"min", "max", "resolution"});
  sensor.rangeMin = in.number(in.required(range, "range", "min"), "range.min");
  if (!(sensor.rangeMin >= 0)) in.fail("range.min", numberText(sensor.rangeMin) + " is negative; a range is >= 0");
  sensor.rangeMax = in.number(in.required(range, "range", "max"), "range.max");
  if (!(sensor.rangeMax > sensor.rangeMin)) {
    in.fail("range.max", numberText(sensor.rangeMax) + " is not above range.min = " + numberText(sensor.rangeMin));
  }
  if (const Json* resolution = in.optional(range, "resolution")) {
    sensor.resolution = in.number(*resolution, "range.resolution");
    if (!(sensor.resolution >= 0))
      in.fail("range.resolution", numberText(sensor.resolution) + " is negative; 0 means none");
  }

  if (const Json* noise = in.optional(root, "noise"))
    readNoise(in, *noise, "noise", sensor.noiseMean, sensor.noiseStddev, sensor.noiseSeed);
  if (const Json* noise = in.optional(root, "intensity_noise")) {
    in.object(*noise, "intensity_noise", {"stddev", "seed"});
    sensor.intensityNoiseStddev =
        in.numberIn(in.required(*noise, "intensity_noise", "stddev"), "intensity_noise.stddev", 0, 1,
                    "a relative standard deviation lies in [0, 1]");
    if (const Json* seed = in.optional(*noise, "seed"))
      sensor.intensityNoiseSeed = in.unsignedInteger(*seed, "intensity_noise.seed");
  }
  if (const Json* rate = in.optional(root, "rotation_rate")) {
    sensor.rotationRate = in.numberIn(*rate, "rotation_rate", 0, kMaxRotationRate,
                                      "a rotation rate lies in [0, 1e6] revolutions per second (0: every beam "
                                      "of a sweep at the pose's instant)");
  }
  readReturns(in, root, sensor);
  // Every beam gives `layers` points, one a return (empty or not): the points of a pose.
  if (beams * sensor.layers() > kMaxBeamsPerPose) {
    in.fail("max_returns", std::to_string(beams) + " beams x " + std::to_string(sensor.layers()) +
                               " returns = " + std::to_string(beams * sensor.layers()) + " points a pose; at most " +
                               std::to_string(kMaxBeamsPerPose));
  }
  return sensor;
}

}  // namespace

SensorDescription parseSensor(std::string_view text, const std::string& file) {
  return parseSensorWith(text, file, nullptr);
}

SensorDescription parseSensor(std::string_view text, const std::string& file, FileTexts& patterns) {
  return parseSensorWith(text, file, &patterns);
}

CameraDescription parseCamera(std::string_view text, const std::string& file) {
  const Reader in(file);
  const Json root = json::parse(text, in);
  in.object(root, "", {"type", "pose", "width", "height", "fov"});
  const std::string type = in.string(in.required(root, "", "type"), "type");
  if (type != "camera") {
    in.fail("type", json::quotedText(type) + ": expected \"camera\" (a lidar's file is scanned by revolve-lidar)");
  }
  CameraDescription camera;
  camera.file = file;
  camera.pose = readPose(in, in.required(root, "", "pose"));
  camera.width = in.integerIn(in.required(root, "", "width"), "width", 1, 16384);
  camera.height = in.integerIn(in.required(root, "", "height"), "height", 1, 16384);
  const Json& fov = in.required(root, "", "fov");
  camera.fovDegrees = in.number(fov, "fov");
  if (!(camera.fovDegrees > 0 && camera.fovDegrees < 180))
    in.fail("fov", numberText(fov) + " is out of range: the vertical field of view lies in (0, 180) degrees");
  return camera;
}

CameraDescription readCamera(const std::string& path) { return parseCamera(readText(path), path); }

SensorDescription readSensor(const std::string& path) { return parseSensor(readText(path), path); }

SensorDescription readSensor(const std::string& path, std::string& text, FileTexts& patterns) {
  text = readText(path);
  return parseSensor(text, path, patterns);
}

const char* radiationTypeName(RadiationType type) {
  return type == RadiationType::infrared ? "infrared" : "ultrasound";
}

SensorType parseSensorType(std::string_view text, const std::string& file) {
  const Reader in(file);
  const Json root = json::parse(text, in);
  if (!root.is_object() || !root.contains("type")) return SensorType::lidar;
  const std::string type = in.string(root["type"], "type");
  if (type == "lidar") return SensorType::lidar;
  if (type == "camera") return SensorType::camera;
  if (type == "range") return SensorType::range;
  in.fail("type", json::quotedText(type) +
                      " is not a sensor type; expected \"lidar\" (the default), \"range\" or "
                      "\"camera\"");
}

SensorType readSensorType(const std::string& path) { return parseSensorType(readText(path), path); }

RangeSensorsDescription parseRangeSensors(std::string_view text, const std::string& file) {
  const Reader in(file);
  const Json root = json::parse(text, in);
  in.object(root, "",
            {"type", "name", "pose", "field_of_view", "min_range", "max_range", "radiation_type", "noise", "sensors"});
  const std::string type = in.string(in.required(root, "", "type"), "type");
  if (type != "range") {
    in.fail("type", json::quotedText(type) + ": expected \"range\" (a lidar's file has \"lidar\" or no type)");
  }
  const Json* ring = in.optional(root, "sensors");
  if (ring != nullptr) {
    for (const char* own : {"pose", "name"}) {
      if (in.optional(root, own) != nullptr)
        in.fail(own, "with \"sensors\", each sensor gives its own " + std::string(own) + " in its entry");
    }
    in.array(*ring, "sensors");
    if (ring->empty()) in.fail("sensors", "the list is empty; give at least one sensor");
    if (ring->size() > kMaxRangeSensors)
      in.fail("sensors", std::to_string(ring->size()) + " sensors; at most " + std::to_string(kMaxRangeSensors));
  }
  RangeSensorsDescription result;
  result.file = file;
  const std::size_t count = ring != nullptr ? ring->size() : 1;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string at = ring != nullptr ? element("sensors", i) : "";
    const Json& entry = ring != nullptr ? (*ring)[i] : root;
    if (ring != nullptr) {
      in.object(entry, at, {"name", "pose", "field_of_view", "min_range", "max_range", "radiation_type", "noise"});
    }
    // A key of the entry, else the file's default for every sensor; `path` names where it was found.
    std::string path;
    const auto find = [&](const char* key) -> const Json* {
      if (ring != nullptr) {
        if (const Json* own = in.optional(entry, key)) {
          path = child(at, key);
          return own;
        }
      }
      path = key;
      return in.optional(root, key);
    };
    const auto require = [&](const char* key) -> const Json& {
      if (const Json* v = find(key)) return *v;
      in.fail(at, std::string("missing key \"") + key + "\"" +
                      (ring != nullptr ? " (in the entry, or beside \"sensors\" for every sensor)" : ""));
    };
    RangeSensorDescription sensor;
    if (const Json* name = find("name")) {
      sensor.name = in.string(*name, path);
      if (sensor.name.empty() || sensor.name.size() > 256)
        in.fail(path, "a name has 1 to 256 characters (it becomes the sensor's frame id)");
      for (const unsigned char c : sensor.name) {
        if (c < 0x20 || c == 0x7f) in.fail(path, "a name holds no control characters");
      }
    } else {
      sensor.name = ring != nullptr ? "range_" + std::to_string(i) : "range";
    }
    const Json& pose = require("pose");
    sensor.pose = readPose(in, pose, path);
    const Json& fov = require("field_of_view");
    sensor.fieldOfView = in.number(fov, path);
    if (!(sensor.fieldOfView > 0 && sensor.fieldOfView <= std::numbers::pi)) {
      in.fail(path,
              numberText(fov) +
                  " is out of range: the cone's full angle lies in (0, pi] radians (pi: the half-space in front)");
    }
    const Json& low = require("min_range");
    const std::string lowPath = path;
    sensor.minRange = in.number(low, lowPath);
    if (!(sensor.minRange >= 0)) in.fail(lowPath, numberText(low) + " is negative; a range is >= 0");
    const Json& high = require("max_range");
    sensor.maxRange = in.number(high, path);
    if (!(sensor.maxRange > sensor.minRange)) {
      in.fail(path,
              numberText(high) + " is not above min_range = " + numberText(sensor.minRange) + " (" + lowPath + ")");
    }
    const Json& radiation = require("radiation_type");
    const std::string kind = in.string(radiation, path);
    if (kind == "ultrasound") {
      sensor.radiation = RadiationType::ultrasound;
    } else if (kind == "infrared") {
      sensor.radiation = RadiationType::infrared;
    } else {
      in.fail(path, json::quotedText(kind) +
                        " is not a radiation type; expected \"ultrasound\" or \"infrared\" (ROS's Range constants)");
    }
    if (const Json* noise = find("noise"))
      readNoise(in, *noise, path, sensor.noiseMean, sensor.noiseStddev, sensor.noiseSeed);
    for (const RangeSensorDescription& other : result.sensors) {
      if (other.name == sensor.name)
        in.fail(ring != nullptr ? child(at, "name") : "name", json::quotedText(sensor.name) + " names two sensors");
    }
    result.sensors.push_back(std::move(sensor));
  }
  return result;
}

RangeSensorsDescription readRangeSensors(const std::string& path) { return parseRangeSensors(readText(path), path); }

}  // namespace revolve::io
