#include "io/scan_files.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace revolve::io {
namespace {

static_assert(std::endian::native == std::endian::little,
              "binary PCD is written in the byte order PCL reads on x86-64");

// x y z range ring return object intensity time, packed
constexpr std::size_t kBinaryPointBytes = 4 + 4 + 4 + 4 + 2 + 1 + 4 + 4 + 4;

// A float as its shortest round-trip text ("nan" for NaN), appended at `at`.
char* appendFloat(char* at, float value) {
  if (std::isnan(value)) return std::copy_n("nan", 3, at);
  return std::to_chars(at, at + 32, value).ptr;
}

}  // namespace

ScanLayout scanLayout(const SensorDescription& sensor, std::size_t poses) {
  ScanLayout layout;
  if (sensor.pattern.empty()) {
    layout.azimuths = fanAngles(sensor.horizontal);
    layout.elevations = sensor.elevations;
  } else {
    for (const PatternBeam& beam : sensor.pattern) {
      layout.azimuths.push_back(beam.azimuth);
      layout.elevations.push_back(beam.elevation);
    }
    layout.pattern = true;
  }
  layout.layers = std::size_t(sensor.layers());
  layout.poses = poses;
  return layout;
}

ScanFormat scanFormatFor(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".csv") return ScanFormat::csv;
  if (extension == ".pcd") return ScanFormat::pcd;
  throw std::runtime_error(path + ": unsupported scan extension \"" + extension +
                           "\"; use .csv (a LaserScan-shaped table) or .pcd (a PCD v0.7 point cloud)");
}

ScanWriter::ScanWriter(OutputStream& out, ScanFormat format, PcdData data, const ScanLayout& layout)
    : out_(out), format_(format), data_(data), layout_(layout) {
  if (format_ == ScanFormat::csv) {
    out_.write("pose,ring,return,azimuth,elevation,range,x,y,z,object,intensity,time\n");
    return;
  }
  const std::size_t points = std::size_t(layout_.pointCount());
  const std::size_t width = layout_.pattern ? points : layout_.columns(), height = layout_.pattern ? 1 : points / width;
  out_.print(
      "# .PCD v0.7 - Point Cloud Data file format\n"
      "VERSION 0.7\n"
      "FIELDS x y z range ring return object intensity time\n"
      "SIZE 4 4 4 4 2 1 4 4 4\n"
      "TYPE F F F F U U I F F\n"
      "COUNT 1 1 1 1 1 1 1 1 1\n"
      "WIDTH %zu\n"
      "HEIGHT %zu\n"
      "VIEWPOINT 0 0 0 1 0 0 0\n"
      "POINTS %zu\n"
      "DATA %s\n",
      width, height, width * height, data_ == PcdData::binary ? "binary" : "ascii");
}

void ScanWriter::write(std::uint64_t first, std::span<const BeamReturn> beams) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  if (format_ == ScanFormat::csv) {
    for (std::size_t i = 0; i < beams.size(); ++i) {
      const ScanLayout::Place at = layout_.place(first + i);
      const BeamReturn& b = beams[i];
      const double azimuth = layout_.azimuths[at.column], elevation = layout_.elevation(at.ring, at.column);
      if (std::isinf(b.range)) {
        if (at.layer > 0) continue;  // a further return the beam does not have
        out_.print("%zu,%zu,0,%.9g,%.9g,inf,,,,,,%.9g\n", at.pose, at.ring, azimuth, elevation, b.time);
      } else {
        out_.print("%zu,%zu,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.9g,%.9g\n", at.pose, at.ring, at.layer, azimuth,
                   elevation, b.range, b.x, b.y, b.z, int(b.object), b.intensity, b.time);
      }
    }
    return;
  }
  if (data_ == PcdData::binary) {
    buffer_.resize(beams.size() * kBinaryPointBytes);
    char* at = buffer_.data();
    for (std::size_t i = 0; i < beams.size(); ++i) {
      const ScanLayout::Place place = layout_.place(first + i);
      const BeamReturn& b = beams[i];
      const bool hit = !std::isinf(b.range);
      const float fields[4] = {hit ? b.x : nan, hit ? b.y : nan, hit ? b.z : nan, hit ? b.range : nan};
      const auto ring = std::uint16_t(place.ring);
      const auto layer = std::uint8_t(place.layer);
      const std::int32_t object = hit ? b.object : -1;
      const float intensity = hit ? b.intensity : nan;
      std::memcpy(at, fields, sizeof fields);
      std::memcpy(at + 16, &ring, 2);
      std::memcpy(at + 18, &layer, 1);
      std::memcpy(at + 19, &object, 4);
      std::memcpy(at + 23, &intensity, 4);
      std::memcpy(at + 27, &b.time, 4);
      at += kBinaryPointBytes;
    }
    out_.write(buffer_.data(), buffer_.size());
    return;
  }
  // ASCII: the longest line is 6 floats of at most 15 characters, a ring, a return and an object index.
  buffer_.resize(beams.size() * 128);
  char* at = buffer_.data();
  for (std::size_t i = 0; i < beams.size(); ++i) {
    const ScanLayout::Place place = layout_.place(first + i);
    const BeamReturn& b = beams[i];
    const bool hit = !std::isinf(b.range);
    for (const float value : {hit ? b.x : nan, hit ? b.y : nan, hit ? b.z : nan, hit ? b.range : nan}) {
      at = appendFloat(at, value);
      *at++ = ' ';
    }
    at = std::to_chars(at, at + 16, place.ring).ptr;
    *at++ = ' ';
    at = std::to_chars(at, at + 16, place.layer).ptr;
    *at++ = ' ';
    at = std::to_chars(at, at + 16, hit ? b.object : -1).ptr;
    *at++ = ' ';
    at = appendFloat(at, hit ? b.intensity : nan);
    *at++ = ' ';
    at = appendFloat(at, b.time);
    *at++ = '\n';
  }
  out_.write(buffer_.data(), std::size_t(at - buffer_.data()));
}

void writeScan(const std::string& path, const ScanTable& scan, PcdData data) {
  const ScanFormat format = scanFormatFor(path);
  OutputSet outputs;
  outputs.add("", path);
  ScanWriter writer(outputs.stream(path), format, data, scan);
  writer.write(0, scan.points);
  outputs.commit();
}

}  // namespace revolve::io
