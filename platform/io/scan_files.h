// Range scans as files other tools read: a LaserScan-shaped CSV table and an organised PCD v0.7
// point cloud (PCL, Open3D, CloudCompare), ASCII or binary, chosen by the output's extension and
// an option. A scan is written as it is traced, block by block in beam order, so memory does not
// grow with the number of poses; the file goes to a temporary renamed into place (output_set.h),
// so it is whole or absent.
#pragma once

#include "io/output_set.h"

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

// The shape of a scan: poses, each a grid of rings (channels) x azimuths. Beams are numbered in
// pose, ring, azimuth order: (pose * rings + ring) * azimuths + column.
struct ScanLayout {
  std::vector<double> azimuths;    // radians, in the sensor's frame, one per column
  std::vector<double> elevations;  // radians, one per ring
  std::size_t poses = 0;

  std::size_t rings() const { return elevations.size(); }
  std::size_t beamsPerPose() const { return rings() * azimuths.size(); }
  std::uint64_t beamCount() const { return std::uint64_t(poses) * beamsPerPose(); }
};

// The most beams one scan file holds: 2^31 - 1, PCD's point count as PCL indexes it (a signed
// 32-bit index), and at 30 to 70 bytes a beam already 64 to 150 GB of output.
inline constexpr std::uint64_t kMaxScanBeams = (std::uint64_t{1} << 31) - 1;

// A whole scan in memory, for tests and the benchmark (the tools stream).
struct ScanTable : ScanLayout {
  std::vector<BeamReturn> beams;

  const BeamReturn& at(std::size_t pose, std::size_t ring, std::size_t column) const {
    return beams[(pose * rings() + ring) * azimuths.size() + column];
  }
};

enum class ScanFormat { csv, pcd };
enum class PcdData { ascii, binary };

// The format for `path`'s extension (.csv or .pcd, case-insensitive), or std::runtime_error
// naming the file and the extensions supported.
ScanFormat scanFormatFor(const std::string& path);

// Writes one scan in beam order: the header when made, then each block of beams as it comes.
//
// CSV: header `pose,ring,azimuth,elevation,range,x,y,z,object,intensity,time`, one row per beam;
// `range` is `inf` and x, y, z, object and intensity are empty for no return (%.9g numbers); every
// beam has its time.
//
// PCD v0.7, organised: WIDTH = azimuths, HEIGHT = rings x poses (row = pose * rings + ring); fields
// `x y z range ring object intensity time` (F F F F U I F F, sizes 4 4 4 4 2 4 4 4); x, y, z, range
// and intensity are nan for no return, object -1, time the beam's firing time either way; points
// in the world frame, so VIEWPOINT is the identity. `DATA ascii`: one point a line, floats in their
// shortest round-trip text. `DATA binary`: PCL's layout, each point its fields packed in order (30
// bytes, little-endian as PCL writes on x86-64), no padding.
class ScanWriter {
 public:
  ScanWriter(OutputStream& out, ScanFormat format, PcdData data, const ScanLayout& layout);
  // Beams `first`, `first` + 1, ... (their numbers in beam order).
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
