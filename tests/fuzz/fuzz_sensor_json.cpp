// Fuzz target: a sensor file (SENSOR.json) as revolve-lidar reads it. Expected: a SensorError with
// a one-line message, or a description that keeps the reader's promises (sample and channel counts
// within their limits, the position within the coordinate limit, angles finite and within their
// ranges, min <= max and a fan spanning at
// most a turn, range 0 <= min < max, resolution and stddev >= 0, the footprint and return keys
// within theirs, points a pose within the limit), whose beam angles (fanAngles) run from min_angle
// to max_angle without going back. Anything else, or a sanitizer report, is a finding. (A
// "pattern" names a file, which the fuzzer can only rarely name: patterns are tested apart.) The same
// text goes to the range sensors' reader ("type": "range"), whose sensors keep theirs: a count
// within the limit, unique names, field_of_view in (0, pi], 0 <= min_range < max_range finite,
// noise finite with stddev >= 0, positions and angles as the lidar's.
#include "fuzz_checks.h"
#include "geometry/ray_limits.h"
#include "io/sensor_file.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string_view>

using namespace revolve;

namespace {

void checkRangeSensors(std::string_view text) {
  io::RangeSensorsDescription ring;
  try {
    ring = io::parseRangeSensors(text, "fuzz.json");
  } catch (const io::SensorError& error) {
    fuzz::checkOneLineMessage(error.what());
    return;
  }
  FUZZ_CHECK(!ring.sensors.empty() && ring.sensors.size() <= io::kMaxRangeSensors);
  for (std::size_t i = 0; i < ring.sensors.size(); ++i) {
    const io::RangeSensorDescription& s = ring.sensors[i];
    FUZZ_CHECK(!s.name.empty());
    for (std::size_t j = 0; j < i; ++j) FUZZ_CHECK(ring.sensors[j].name != s.name);
    FUZZ_CHECK(s.fieldOfView > 0 && s.fieldOfView <= std::numbers::pi);
    FUZZ_CHECK(s.minRange >= 0 && s.minRange < s.maxRange && std::isfinite(s.maxRange));
    FUZZ_CHECK(s.noiseStddev >= 0 && std::isfinite(s.noiseStddev) && std::isfinite(s.noiseMean));
    for (const double p : s.pose.position) FUZZ_CHECK(std::abs(p) <= app::kMaxWorldCoordinate);
    for (const double a : {s.pose.yaw, s.pose.pitch, s.pose.roll}) FUZZ_CHECK(std::abs(a) <= 2 * std::numbers::pi);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  checkRangeSensors(text);
  io::SensorDescription sensor;
  try {
    sensor = io::parseSensor(text, "fuzz.json");
  } catch (const io::SensorError& error) {
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  const double turn = 2 * std::numbers::pi;
  for (const double a : {sensor.pose.yaw, sensor.pose.pitch, sensor.pose.roll}) FUZZ_CHECK(std::abs(a) <= turn);
  for (const double p : sensor.pose.position) FUZZ_CHECK(std::abs(p) <= app::kMaxWorldCoordinate);
  const io::BeamFan& fan = sensor.horizontal;
  FUZZ_CHECK(fan.samples >= 1 && fan.samples <= io::kMaxHorizontalSamples);
  FUZZ_CHECK(fan.minAngle <= fan.maxAngle && fan.maxAngle - fan.minAngle <= turn);
  FUZZ_CHECK(std::abs(fan.minAngle) <= turn && std::abs(fan.maxAngle) <= turn);
  FUZZ_CHECK(!sensor.elevations.empty() && sensor.elevations.size() <= std::size_t(io::kMaxChannels));
  FUZZ_CHECK(long(fan.samples) * long(sensor.elevations.size()) <= io::kMaxBeamsPerPose);
  if (sensor.planar) FUZZ_CHECK(sensor.elevations.size() == 1 && sensor.elevations[0] == 0);
  for (const double e : sensor.elevations) FUZZ_CHECK(std::abs(e) <= std::numbers::pi / 2);
  FUZZ_CHECK(sensor.rangeMin >= 0 && sensor.rangeMin < sensor.rangeMax && std::isfinite(sensor.rangeMax));
  FUZZ_CHECK(sensor.resolution >= 0 && std::isfinite(sensor.resolution));
  FUZZ_CHECK(sensor.noiseStddev >= 0 && std::isfinite(sensor.noiseStddev) && std::isfinite(sensor.noiseMean));
  FUZZ_CHECK(sensor.divergence >= 0 && sensor.divergence <= io::kMaxDivergence);
  FUZZ_CHECK(sensor.subrays >= 1 && sensor.subrays <= io::kMaxSubrays);
  FUZZ_CHECK(sensor.layers() >= 1 && sensor.layers() <= io::kMaxReturns);
  FUZZ_CHECK(sensor.returns == io::ReturnMode::all || sensor.layers() == 1);
  FUZZ_CHECK(sensor.returnSeparation > 0 && std::isfinite(sensor.returnSeparation));
  const long beams =
      sensor.pattern.empty() ? long(fan.samples) * long(sensor.elevations.size()) : long(sensor.pattern.size());
  FUZZ_CHECK(beams * sensor.layers() <= io::kMaxBeamsPerPose);
  if (fan.samples <= 4096) {  // the angles themselves, where that stays quick
    const std::vector<double> angles = io::fanAngles(fan);
    FUZZ_CHECK(angles.size() == std::size_t(fan.samples));
    FUZZ_CHECK(angles.front() == fan.minAngle && angles.back() == fan.maxAngle);
    for (std::size_t i = 1; i < angles.size(); ++i) FUZZ_CHECK(angles[i] >= angles[i - 1]);
  }
  return 0;
}
