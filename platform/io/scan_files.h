// Range scans as files other tools read: a LaserScan-shaped CSV table and an organised PCD v0.7
// point cloud (PCL, Open3D, CloudCompare), ASCII or binary, chosen by the output's extension and
// an option. A scan is written as it is traced, block by block in point order, so memory does not
// grow with the number of poses; the file goes to a temporary renamed into place (output_set.h),
// so it is whole or absent.
#pragma once

#include "io/output_set.h"
#include "io/sensor_file.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace revolve::io {

struct BeamReturn {
  float range;          // +inf: no return (nothing hit, or the measurement outside [min, max])
  float x, y, z;        // the return in the world frame (meaningless without one)
  std::int32_t object;  // the scene's object index (quads: objects + quad index); -1 without a return
  float intensity = 0;  // reflectivity |cos theta| / range^2, in 1/m^2 (robot/lidar.h); without a return, unused
  float time = 0;       // seconds from the sweep's start to the beam's firing (every beam, returned or not)
};

// The shape of a scan: poses, each a grid of rings (channels) x columns (azimuths), one layer of
// that grid per return a beam reports (io::SensorDescription::layers; 1 unless returns "all").
// Points are numbered in pose, layer, ring, column order:
// ((pose * layers + layer) * rings + ring) * columns + column; a beam (pose, ring, column) has
// one point in each layer, its returns in range order (empty where it has fewer).
// A pattern sensor's scan is one ring whose columns are the pattern's beams, each with its own
// elevation, and its files are unorganised clouds.
struct ScanLayout {
  std::vector<double> azimuths;    // radians, in the sensor's frame, one per column
  std::vector<double> elevations;  // radians, one per ring; with a pattern, one per column
  bool pattern = false;
  std::size_t layers = 1;
  std::size_t poses = 0;

  std::size_t columns() const { return azimuths.size(); }
  std::size_t rings() const { return pattern ? 1 : elevations.size(); }
  double elevation(std::size_t ring, std::size_t column) const { return elevations[pattern ? column : ring]; }
  std::size_t beamsPerPose() const { return rings() * columns(); }
  std::size_t pointsPerPose() const { return beamsPerPose() * layers; }
  std::uint64_t pointCount() const { return std::uint64_t(poses) * pointsPerPose(); }

  // Where point `point` is: its pose, layer (return index), ring and column.
  struct Place {
    std::size_t pose, layer, ring, column;
  };
  Place place(std::uint64_t point) const {
    const std::uint64_t row = point / columns();
    return {std::size_t(row / rings() / layers), std::size_t(row / rings() % layers), std::size_t(row % rings()),
            std::size_t(point % columns())};
  }
};

// The layout of `poses` sweeps of `sensor`: the one place a scan's shape comes from.
ScanLayout scanLayout(const SensorDescription& sensor, std::size_t poses);

// The most points one scan file holds: 2^31 - 1, PCD's point count as PCL indexes it (a signed
// 32-bit index), and at 31 to 75 bytes a point already 66 to 160 GB of output.
inline constexpr std::uint64_t kMaxScanPoints = (std::uint64_t{1} << 31) - 1;

// A whole scan in memory, for tests and the benchmark (the tools stream).
struct ScanTable : ScanLayout {
  std::vector<BeamReturn> points;  // in point order

  const BeamReturn& at(std::size_t pose, std::size_t ring, std::size_t column, std::size_t layer = 0) const {
    return points[((pose * layers + layer) * rings() + ring) * columns() + column];
  }
};

enum class ScanFormat { csv, pcd };
enum class PcdData { ascii, binary };

// The format for `path`'s extension (.csv or .pcd, case-insensitive), or std::runtime_error
// naming the file and the extensions supported.
ScanFormat scanFormatFor(const std::string& path);

// Writes one scan in point order (ScanLayout): the header when made, then each block of points as
// it comes.
//
// CSV: header `pose,ring,return,azimuth,elevation,range,x,y,z,object,intensity,time`, one row per
// point of layer 0 (every beam: `range` is `inf` and x, y, z, object and intensity empty for no
// return) and per return of the further layers (their empty points have no row); %.9g numbers;
// every row has its beam's firing time.
//
// PCD v0.7: fields `x y z range ring return object intensity time` (F F F F U U I F F, sizes
// 4 4 4 4 2 1 4 4 4); x, y, z, range and intensity are nan for no return, object -1, time the
// beam's firing time either way; points in the world frame, so VIEWPOINT is the identity.
// Organised for fans: WIDTH = columns, HEIGHT = rows, row = (pose * layers + layer) * rings + ring,
// i.e. each pose one rings x columns image per return. A pattern's scan is unorganised: WIDTH =
// points, HEIGHT = 1, in point order. `DATA ascii`: one point a line, floats in their shortest
// round-trip text. `DATA binary`: PCL's layout, each point its fields packed in order (31 bytes,
// little-endian as PCL writes on x86-64), no padding.
class ScanWriter {
 public:
  ScanWriter(OutputStream& out, ScanFormat format, PcdData data, const ScanLayout& layout);
  // Points `first`, `first` + 1, ... (their numbers in point order).
  void write(std::uint64_t first, std::span<const BeamReturn> beams);

 private:
  OutputStream& out_;
  ScanFormat format_;
  PcdData data_;
  const ScanLayout& layout_;
  std::vector<char> buffer_;
};

// A whole table to `path`, alone (by its extension).
void writeScan(const std::string& path, const ScanTable& scan, PcdData data = PcdData::ascii);

}  // namespace revolve::io
