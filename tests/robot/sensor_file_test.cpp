// The sensor file reader: every key and default as README documents them, the beams' angles as
// Gazebo and ROS define them (both ends included), and each rule's error naming the key path.
#include "io/sensor_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace revolve::io {
namespace {

using ::testing::HasSubstr;

const std::string kPlanar = R"({
  "pose": {"position": [0.1, -0.2, 0.3], "yaw": 0.5, "pitch": -0.25, "roll": 0.125},
  "horizontal": {"samples": 5, "min_angle": -1.0, "max_angle": 1.0},
  "range": {"min": 0.1, "max": 30, "resolution": 0.01},
  "noise": {"mean": 0.002, "stddev": 0.01, "seed": 18446744073709551615},
  "intensity_noise": {"stddev": 0.05, "seed": 9},
  "rotation_rate": 10
})";

TEST(SensorFileTest, ReadsEveryKey) {
  const SensorDescription s = parseSensor(kPlanar, "s.json");
  EXPECT_EQ(s.pose.position, (std::array<double, 3>{0.1, -0.2, 0.3}));
  EXPECT_EQ(s.pose.yaw, 0.5);
  EXPECT_EQ(s.pose.pitch, -0.25);
  EXPECT_EQ(s.pose.roll, 0.125);
  EXPECT_EQ(s.horizontal.samples, 5);
  EXPECT_TRUE(s.planar);
  EXPECT_EQ(s.elevations, std::vector<double>{0.0});  // a 2-D scanner: one channel in its plane
  EXPECT_EQ(s.rangeMin, 0.1);
  EXPECT_EQ(s.rangeMax, 30);
  EXPECT_EQ(s.resolution, 0.01);
  EXPECT_EQ(s.noiseMean, 0.002);
  EXPECT_EQ(s.noiseStddev, 0.01);
  EXPECT_EQ(s.noiseSeed, 18446744073709551615ull);  // the full 64-bit range, not through a double
  EXPECT_EQ(s.intensityNoiseStddev, 0.05);
  EXPECT_EQ(s.intensityNoiseSeed, 9u);
  EXPECT_EQ(s.rotationRate, 10);
  // Column k of 5 fires k / (5 x 10 Hz) after the sweep starts.
  EXPECT_EQ(s.columnTime(0), 0);
  EXPECT_EQ(s.columnTime(4), 4.0 / 50);
}

TEST(SensorFileTest, DefaultsAreNoRotationNoNoiseNoResolution) {
  const SensorDescription s =
      parseSensor(R"({"pose": {"position": [0, 0, 1]}, "horizontal": {"samples": 1, "min_angle": 0, "max_angle": 0},
                      "range": {"min": 0, "max": 5}})",
                  "s.json");
  EXPECT_EQ(s.pose.yaw, 0);
  EXPECT_EQ(s.pose.pitch, 0);
  EXPECT_EQ(s.pose.roll, 0);
  EXPECT_EQ(s.resolution, 0);
  EXPECT_EQ(s.noiseMean, 0);
  EXPECT_EQ(s.noiseStddev, 0);
  EXPECT_EQ(s.intensityNoiseStddev, 0);
  EXPECT_EQ(s.rotationRate, 0);
  EXPECT_EQ(s.columnTime(0), 0);  // every beam at the pose's instant
}

TEST(SensorFileTest, VerticalFanAndElevationList) {
  const SensorDescription fan = parseSensor(
      R"({"pose": {"position": [0, 0, 0]}, "horizontal": {"samples": 4, "min_angle": 0, "max_angle": 3},
          "vertical": {"samples": 3, "min_angle": -0.2, "max_angle": 0.2}, "range": {"min": 0, "max": 5}})",
      "s.json");
  EXPECT_FALSE(fan.planar);
  ASSERT_EQ(fan.elevations.size(), 3u);
  EXPECT_DOUBLE_EQ(fan.elevations[0], -0.2);  // ring 0 is min_angle, the lowest
  EXPECT_DOUBLE_EQ(fan.elevations[1], 0.0);
  EXPECT_DOUBLE_EQ(fan.elevations[2], 0.2);
  const SensorDescription list = parseSensor(
      R"({"pose": {"position": [0, 0, 0]}, "horizontal": {"samples": 4, "min_angle": 0, "max_angle": 3},
          "elevations": [0.1, -0.3, 0.05], "range": {"min": 0, "max": 5}})",
      "s.json");
  EXPECT_EQ(list.elevations, (std::vector<double>{0.1, -0.3, 0.05}));  // rings in the order listed
}

TEST(SensorFileTest, FanAnglesIncludeBothEnds) {
  // ROS LaserScan / Gazebo: angle_increment = (max - min) / (samples - 1).
  const std::vector<double> a = fanAngles({5, -1.0, 1.0});
  ASSERT_EQ(a.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(a[i], -1.0 + 0.5 * i);
  EXPECT_EQ(a.back(), 1.0);
  const std::vector<double> full = fanAngles({1081, -0.75 * std::numbers::pi, 0.75 * std::numbers::pi});
  EXPECT_DOUBLE_EQ(full[540], 0.0);  // the middle beam of an odd fan looks straight ahead
  EXPECT_EQ(fanAngles({1, 0.25, 0.25}), std::vector<double>{0.25});
}

struct BadSensor {
  const char* name;
  std::string text;
  std::string expected;  // a substring of the message
};

std::string replacedIn(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// kPlanar with `from` replaced by `to`.
std::string with(const std::string& from, const std::string& to) { return replacedIn(kPlanar, from, to); }

// Every rule, one case each (in one test: a process per case costs seconds under the sanitizers).
TEST(SensorFileTest, EachRuleNamesTheKeyAndTheRule) {
  const std::vector<BadSensor> cases{
      BadSensor{"NotJson", "{", "s.json: not valid JSON"},
      BadSensor{"MissingHorizontal", with(R"("horizontal": {"samples": 5, "min_angle": -1.0, "max_angle": 1.0},)", ""),
                R"(missing key "horizontal")"},
      BadSensor{"MissingPose",
                with(R"("pose": {"position": [0.1, -0.2, 0.3], "yaw": 0.5, "pitch": -0.25, "roll": 0.125},)", ""),
                R"(missing key "pose")"},
      BadSensor{"MissingPosition", with(R"("position": [0.1, -0.2, 0.3], )", ""), R"(pose: missing key "position")"},
      BadSensor{"UnknownTopKey", with(R"("range")", R"("rnage")"),
                "rnage: unknown key; expected one of: pose, horizontal"},
      BadSensor{"UnknownNestedKey", with(R"("seed")", R"("sead")"),
                "noise.sead: unknown key; expected one of: mean, stddev, seed"},
      BadSensor{"RepeatedKey", with(R"("yaw": 0.5)", R"("yaw": 0.5, "yaw": 0.6)"),
                "s.json: pose.yaw: the key appears twice in its object"},
      BadSensor{"SamplesNotANumber", with(R"("samples": 5)", R"("samples": "many")"),
                "horizontal.samples: expected a number, found string"},
      BadSensor{"SamplesZero", with(R"("samples": 5)", R"("samples": 0)"),
                "horizontal.samples: 0 is out of range: must lie in [1, 1048576]"},
      BadSensor{"SamplesFractional", with(R"("samples": 5)", R"("samples": 5.5)"),
                "horizontal.samples: 5.5 is not a whole number"},
      BadSensor{"AngleInDegrees", with(R"("min_angle": -1.0)", R"("min_angle": -135)"),
                "horizontal.min_angle: -135 is out of range: angles are in radians, within [-2 pi, 2 pi] (degrees?)"},
      BadSensor{"MaxBelowMin", with(R"("max_angle": 1.0)", R"("max_angle": -2.0)"),
                "horizontal.max_angle: -2 is below min_angle = -1"},
      BadSensor{"MoreThanATurn", with(R"("min_angle": -1.0, "max_angle": 1.0)", R"("min_angle": -4, "max_angle": 4)"),
                "horizontal.max_angle: the fan spans 8 radians, more than a full turn"},
      BadSensor{"OneSampleTwoAngles", with(R"("samples": 5)", R"("samples": 1)"),
                "horizontal.max_angle: 1 differs from min_angle = -1"},
      BadSensor{"ElevationBeyondVertical", with(R"("range")", R"("elevations": [0.1, 2.0], "range")"),
                "elevations[1]: 2 is out of range: an elevation lies in [-pi/2, pi/2]"},
      BadSensor{"ElevationsEmpty", with(R"("range")", R"("elevations": [], "range")"), "elevations: the list is empty"},
      BadSensor{"VerticalAndElevations",
                with(R"("range")",
                     R"("elevations": [0.1], "vertical": {"samples": 2, "min_angle": 0, "max_angle": 0.1}, "range")"),
                "give either \"vertical\" (an even fan) or \"elevations\" (a list), not both"},
      BadSensor{"VerticalMissingSamples",
                with(R"("range")", R"("vertical": {"min_angle": 0, "max_angle": 0.1}, "range")"),
                R"(vertical: missing key "samples")"},
      BadSensor{"NegativeMin", with(R"("min": 0.1)", R"("min": -1)"), "range.min: -1 is negative"},
      BadSensor{"MaxNotAboveMin", with(R"("max": 30)", R"("max": 0.1)"), "range.max: 0.1 is not above range.min = 0.1"},
      BadSensor{"MaxInfinite", with(R"("max": 30)", R"("max": 1e999)"),
                "not valid JSON: number overflow parsing '1e999'"},
      BadSensor{"NegativeResolution", with(R"("resolution": 0.01)", R"("resolution": -0.01)"),
                "range.resolution: -0.01 is negative"},
      BadSensor{"NegativeStddev", with(R"("stddev": 0.01)", R"("stddev": -1)"), "noise.stddev: -1 is negative"},
      BadSensor{"MissingStddev", with(R"("stddev": 0.01, )", ""), R"(noise: missing key "stddev")"},
      BadSensor{"NegativeSeed", with(R"("seed": 18446744073709551615)", R"("seed": -3)"), "noise.seed: -3 is negative"},
      BadSensor{"FractionalSeed", with(R"("seed": 18446744073709551615)", R"("seed": 1.5)"),
                "noise.seed: 1.5 is not a whole number"},
      BadSensor{"IntensityNoiseAboveOne", with(R"("stddev": 0.05)", R"("stddev": 1.5)"),
                "intensity_noise.stddev: 1.5 is out of range: a relative standard deviation lies in [0, 1]"},
      BadSensor{"IntensityNoiseUnknownKey", with(R"("stddev": 0.05, "seed": 9)", R"("stddev": 0.05, "mean": 9)"),
                "intensity_noise.mean: unknown key; expected one of: stddev, seed"},
      BadSensor{"NegativeRotationRate", with(R"("rotation_rate": 10)", R"("rotation_rate": -10)"),
                "rotation_rate: -10 is out of range: a rotation rate lies in [0, 1e6] revolutions per second"},
      BadSensor{"RotationRateTooHigh", with(R"("rotation_rate": 10)", R"("rotation_rate": 2e6)"),
                "is out of range: a rotation rate lies in [0, 1e6]"},
      BadSensor{"RotationRateNotANumber", with(R"("rotation_rate": 10)", R"("rotation_rate": "10 Hz")"),
                "rotation_rate: expected a number, found string"},
      BadSensor{"PositionNotThree", with(R"([0.1, -0.2, 0.3])", "[0.1, -0.2]"),
                "pose.position: expected an array of 3 numbers"},
      BadSensor{"NegativeDivergence", with(R"("rotation_rate": 10)", R"("divergence": -0.001)"),
                "divergence: -0.001 is out of range: a beam's full divergence angle lies in [0, 0.1] radians"},
      BadSensor{"DivergenceInDegrees", with(R"("rotation_rate": 10)", R"("divergence": 0.2)"),
                "divergence: 0.2 is out of range"},
      BadSensor{"DivergenceNaN", with(R"("rotation_rate": 10)", R"("divergence": NaN)"), "not valid JSON"},
      BadSensor{"SubraysZero", with(R"("rotation_rate": 10)", R"("subrays": 0)"),
                "subrays: 0 is out of range: must lie in [1, 256]"},
      BadSensor{"SubraysTooMany", with(R"("rotation_rate": 10)", R"("subrays": 257)"),
                "subrays: 257 is out of range: must lie in [1, 256]"},
      BadSensor{"UnknownReturns", with(R"("rotation_rate": 10)", R"("returns": "dual")"),
                R"(returns: "dual" is not a return mode; expected one of: "first", "last", "strongest", "all")"},
      BadSensor{"MaxReturnsZero", with(R"("rotation_rate": 10)", R"("returns": "all", "max_returns": 0)"),
                "max_returns: 0 is out of range: must lie in [1, 255]"},
      BadSensor{"MaxReturnsWithoutAll", with(R"("rotation_rate": 10)", R"("returns": "last", "max_returns": 2)"),
                R"(max_returns: applies to "returns": "all" only; returns is "last")"},
      BadSensor{"SeparationZero", with(R"("rotation_rate": 10)", R"("return_separation": 0)"),
                "return_separation: 0 is not above 0"},
      BadSensor{"MaxReturnsTooMany", with(R"("rotation_rate": 10)", R"("returns": "all", "max_returns": 256)"),
                "max_returns: 256 is out of range: must lie in [1, 255]"},
      BadSensor{"ReturnsNotAString", with(R"("rotation_rate": 10)", R"("returns": 2)"),
                "returns: expected a string, found number"},
      BadSensor{"DivergenceWithOneSubray", with(R"("rotation_rate": 10)", R"("divergence": 0.003)"),
                "subrays: 1 with divergence = 0.003: one sub-ray is the beam's axis alone"},
      BadSensor{"SubraysWithoutDivergence", with(R"("rotation_rate": 10)", R"("subrays": 8)"),
                "subrays: 8 with divergence 0: every sub-ray would be the beam's axis"},
      // 2^20 beams x 17 returns (max_returns' default of 2 would fit): beyond 2^24 points a pose.
      BadSensor{"TooManyPointsAPose",
                replacedIn(with(R"("samples": 5)", R"("samples": 1048576)"), R"("rotation_rate": 10)",
                           R"("returns": "all", "max_returns": 17)"),
                "max_returns: 1048576 beams x 17 returns = 17825792 points a pose; at most 16777216"},
      BadSensor{"PatternPathEmpty",
                R"({"pose": {"position": [0, 0, 0]}, "pattern": "", "range": {"min": 0, "max": 5}})",
                "pattern: the path is empty"},
      BadSensor{"PatternWithFans", with(R"("rotation_rate": 10)", R"("pattern": "beams.csv")"),
                R"(horizontal: give either "pattern" (a beam table) or the fans)"},
      BadSensor{
          "PatternMissing",
          R"({"pose": {"position": [0, 0, 0]}, "pattern": "/nonexistent/beams.csv", "range": {"min": 0, "max": 5}})",
          "pattern: /nonexistent/beams.csv"},
      BadSensor{
          "PatternAndRotationRate",
          R"({"pose": {"position": [0, 0, 0]}, "pattern": "b.csv", "rotation_rate": 10, "range": {"min": 0, "max": 5}})",
          "rotation_rate: a pattern's beams carry their own firing times"}};
  for (const BadSensor& bad : cases) {
    SCOPED_TRACE(bad.name);
    try {
      parseSensor(bad.text, "s.json");
      ADD_FAILURE() << "accepted";
    } catch (const SensorError& error) {
      EXPECT_THAT(error.what(), HasSubstr(bad.expected));
      EXPECT_THAT(error.what(), ::testing::StartsWith("s.json: "));
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    }
  }
}

TEST(SensorFileTest, FootprintAndReturnKeys) {
  const SensorDescription s = parseSensor(
      R"({"pose": {"position": [0, 0, 0]}, "horizontal": {"samples": 4, "min_angle": 0, "max_angle": 3},
          "range": {"min": 0, "max": 5}, "divergence": 0.003, "subrays": 16, "returns": "all", "max_returns": 3,
          "return_separation": 0.25})",
      "s.json");
  EXPECT_EQ(s.divergence, 0.003);
  EXPECT_EQ(s.subrays, 16);
  EXPECT_EQ(s.returns, ReturnMode::all);
  EXPECT_EQ(s.maxReturns, 3);
  EXPECT_EQ(s.layers(), 3);
  EXPECT_EQ(s.returnSeparation, 0.25);
  const SensorDescription d = parseSensor(
      R"({"pose": {"position": [0, 0, 0]}, "horizontal": {"samples": 4, "min_angle": 0, "max_angle": 3},
          "range": {"min": 0, "max": 5}, "returns": "strongest"})",
      "s.json");
  EXPECT_EQ(d.divergence, 0);  // a ray
  EXPECT_EQ(d.subrays, 1);
  EXPECT_EQ(d.returns, ReturnMode::strongest);
  EXPECT_EQ(d.layers(), 1);
  EXPECT_EQ(parseSensor(R"({"pose": {"position": [0, 0, 0]}, "horizontal": {"samples": 1, "min_angle": 0,
                            "max_angle": 0}, "range": {"min": 0, "max": 5}, "returns": "all"})",
                        "s.json")
                .maxReturns,
            2);  // the default
}

TEST(SensorFileTest, ACameraFileHasItsOwnType) {
  const CameraDescription c = parseCamera(
      R"({"type": "camera", "pose": {"position": [0.1, 0, 0.9], "pitch": 0.2}, "width": 64, "height": 48,
          "fov": 50})",
      "c.json");
  EXPECT_EQ(c.pose.position, (std::array<double, 3>{0.1, 0, 0.9}));
  EXPECT_EQ(c.pose.pitch, 0.2);
  EXPECT_EQ(c.width, 64);
  EXPECT_EQ(c.height, 48);
  EXPECT_EQ(c.fovDegrees, 50);
  // A lidar's reader refuses a camera's file and an unknown type; "lidar" is the default type.
  const auto refusal = [](const std::string& text) {
    try {
      parseSensor(text, "s.json");
    } catch (const SensorError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(refusal(R"({"type": "camera", "pose": {"position": [0, 0, 0]}})"),
              HasSubstr("s.json: type: \"camera\": a camera's file; revolve-render renders it"));
  EXPECT_THAT(refusal(R"({"type": "sonar"})"), HasSubstr(R"(s.json: type: "sonar" is not a sensor type)"));
  EXPECT_EQ(parseSensor(std::string(kPlanar).insert(1, R"("type": "lidar", )"), "s.json").horizontal.samples, 5);
  for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
           {R"({"pose": {"position": [0, 0, 0]}, "width": 4, "height": 4, "fov": 50})", R"(missing key "type")"},
           {R"({"type": "camera", "pose": {"position": [0, 0, 0]}, "width": 4, "height": 4, "fov": 0})",
            "fov: 0 is out of range: the vertical field of view lies in (0, 180) degrees"},
           {R"({"type": "camera", "pose": {"position": [0, 0, 0]}, "width": 16385, "height": 4, "fov": 50})",
            "width: 16385 is out of range"},
           {R"({"type": "camera", "pose": {"position": [0, 0, 0]}, "height": 4, "fov": 50})", R"(missing key "width")"},
           {R"({"type": "camera", "pose": {"position": [0, 0, 0]}, "width": 4, "height": 4, "fov": 50, "spp": 4})",
            "spp: unknown key"}}) {
    try {
      parseCamera(text, "c.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const SensorError& error) {
      EXPECT_THAT(error.what(), HasSubstr(expected));
      EXPECT_THAT(error.what(), ::testing::StartsWith("c.json: "));
    }
  }
}

const std::string kSonarRing = R"({
  "type": "range", "radiation_type": "ultrasound", "field_of_view": 0.5, "min_range": 0.1, "max_range": 5,
  "noise": {"stddev": 0.01, "seed": 3},
  "sensors": [{"name": "front", "pose": {"position": [0.2, 0, 0.3]}},
              {"pose": {"position": [0, 0.2, 0.3], "yaw": 1.5707963267948966}, "field_of_view": 0.25,
               "radiation_type": "infrared", "max_range": 1.5, "noise": {"stddev": 0.002}}]
})";

TEST(SensorFileTest, RangeSensorsTakeTheFileDefaultsOrTheirOwn) {
  const RangeSensorsDescription ring = parseRangeSensors(kSonarRing, "r.json");
  ASSERT_EQ(ring.sensors.size(), 2u);
  const RangeSensorDescription &front = ring.sensors[0], &side = ring.sensors[1];
  EXPECT_EQ(front.name, "front");
  EXPECT_EQ(front.pose.position, (std::array<double, 3>{0.2, 0, 0.3}));
  EXPECT_EQ(front.fieldOfView, 0.5);
  EXPECT_EQ(front.minRange, 0.1);
  EXPECT_EQ(front.maxRange, 5);
  EXPECT_EQ(front.radiation, RadiationType::ultrasound);
  EXPECT_EQ(front.noiseStddev, 0.01);
  EXPECT_EQ(front.noiseSeed, 3u);
  EXPECT_EQ(side.name, "range_1");  // unnamed: its place in the ring
  EXPECT_EQ(side.pose.yaw, 1.5707963267948966);
  EXPECT_EQ(side.fieldOfView, 0.25);
  EXPECT_EQ(side.minRange, 0.1);
  EXPECT_EQ(side.maxRange, 1.5);
  EXPECT_EQ(side.radiation, RadiationType::infrared);
  EXPECT_EQ(side.noiseStddev, 0.002);  // its own noise, whole: no seed of the file's
  EXPECT_EQ(side.noiseSeed, 0u);
  const RangeSensorsDescription one = parseRangeSensors(
      R"({"type": "range", "pose": {"position": [0, 0, 0]}, "field_of_view": 3.141592653589793, "min_range": 0,
          "max_range": 2, "radiation_type": "infrared"})",
      "r.json");
  ASSERT_EQ(one.sensors.size(), 1u);
  EXPECT_EQ(one.sensors[0].name, "range");
  EXPECT_EQ(one.sensors[0].fieldOfView, std::numbers::pi);  // a half-space: allowed
  EXPECT_EQ(parseSensorType(kSonarRing, "r.json"), SensorType::range);
  EXPECT_EQ(parseSensorType(kPlanar, "s.json"), SensorType::lidar);
}

TEST(SensorFileTest, EachRangeSensorRuleNamesTheKeyAndTheRule) {
  const auto refusal = [](const std::string& text) {
    try {
      parseRangeSensors(text, "r.json");
    } catch (const SensorError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  const auto ring = [](const std::string& from, const std::string& to) {
    std::string text = kSonarRing;
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("no " + from);
    return text.replace(at, from.size(), to);
  };
  for (
      const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
          {ring(R"("field_of_view": 0.5)", R"("field_of_view": 0)"),
           "r.json: field_of_view: 0 is out of range: the cone's full angle lies in (0, pi] radians"},
          {ring(R"("field_of_view": 0.5)", R"("field_of_view": -0.2)"), "field_of_view: -0.2 is out of range"},
          {ring(R"("field_of_view": 0.25)", R"("field_of_view": 3.2)"),
           "r.json: sensors[1].field_of_view: 3.2 is out of range"},
          {ring(R"("max_range": 1.5)", R"("max_range": 0.05)"),
           "r.json: sensors[1].max_range: 0.05 is not above min_range = 0.1 (min_range)"},
          {ring(R"("min_range": 0.1)", R"("min_range": -1)"), "r.json: min_range: -1 is negative"},
          {ring(R"("radiation_type": "infrared")", R"("radiation_type": "radar")"),
           R"(r.json: sensors[1].radiation_type: "radar" is not a radiation type; expected "ultrasound" or "infrared")"},
          {ring(R"("name": "front", )", R"("name": "range_1", )"), R"(sensors[1].name: "range_1" names two sensors)"},
          {ring(R"("field_of_view": 0.5, )", ""), R"(r.json: sensors[0]: missing key "field_of_view" (in the entry)"},
          {ring(R"("name": "front", )", R"("name": "front", "fov": 1, )"), "r.json: sensors[0].fov: unknown key"},
          {ring(R"("type": "range", )", R"("type": "range", "pose": {"position": [0, 0, 0]}, )"),
           "r.json: pose: with \"sensors\", each sensor gives its own pose in its entry"},
          {ring(R"("sensors": [)", R"("sensors": [], "unused": [)"), "unknown key"},
          {R"({"type": "range", "sensors": []})", "r.json: sensors: the list is empty"},
          {R"({"type": "lidar"})", R"(r.json: type: "lidar": expected "range")"},
      }) {
    EXPECT_THAT(refusal(text), HasSubstr(expected)) << text;
  }
  // A lidar's reader refuses a range sensor's file, saying what it is.
  try {
    parseSensor(kSonarRing, "r.json");
    ADD_FAILURE() << "a lidar read a range sensor's file";
  } catch (const SensorError& error) {
    EXPECT_THAT(error.what(), HasSubstr(R"(r.json: type: "range": a range sensor's file)"));
  }
}

TEST(SensorFileTest, TooManyBeamsAPose) {
  const std::string text = with(R"("samples": 5)", R"("samples": 1048576)");
  const std::string withRings = text.substr(0, text.find(R"("range")")) +
                                R"("vertical": {"samples": 17, "min_angle": 0, "max_angle": 0.1}, )" +
                                text.substr(text.find(R"("range")"));
  try {
    parseSensor(withRings, "s.json");
    FAIL() << "accepted";
  } catch (const SensorError& error) {
    EXPECT_THAT(
        error.what(),
        HasSubstr("horizontal.samples: 1048576 samples x 17 channels = 17825792 beams a pose; at most 16777216"));
  }
}

TEST(SensorFileTest, MissingFileNamesIt) {
  try {
    readSensor("/nonexistent/sensor.json");
    FAIL() << "accepted";
  } catch (const SensorError& error) {
    EXPECT_THAT(error.what(), HasSubstr("/nonexistent/sensor.json: cannot open"));
  }
}

}  // namespace
}  // namespace revolve::io
