// Range scans as files other tools read: a LaserScan-shaped CSV table and an organised ASCII PCD
// v0.7 point cloud (PCL, Open3D, CloudCompare), chosen by the output's extension. Both are written
// through a temporary file renamed into place (text_files.h), so an output is whole or absent.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace revolve::io {

struct BeamReturn {
  float range;        // +inf: no return (nothing hit, or the measurement outside [min, max])
  float x, y, z;      // the return in the world frame (meaningless without one)
  std::int32_t object;  // the scene's object index (quads: objects + quad index); -1 without a return
};

// Beams of several poses, each a grid of rings (channels) x azimuths.
struct ScanTable {
  std::vector<double> azimuths;    // radians, in the sensor's frame, one per column
  std::vector<double> elevations;  // radians, one per ring
  std::size_t poses = 0;
  std::vector<BeamReturn> beams;   // (pose * rings + ring) * azimuths + column

  std::size_t rings() const { return elevations.size(); }
  const BeamReturn& at(std::size_t pose, std::size_t ring, std::size_t column) const {
    return beams[(pose * rings() + ring) * azimuths.size() + column];
  }
};

enum class ScanFormat { csv, pcd };

// The format for `path`'s extension (.csv or .pcd, case-insensitive), or std::runtime_error
// naming the file and the extensions supported.
ScanFormat scanFormatFor(const std::string& path);

// CSV: header `pose,ring,azimuth,elevation,range,x,y,z,object`, one row per beam in pose, ring,
// azimuth order; `range` is `inf` and x, y, z and object are empty for no return (%.9g numbers).
void writeScanCsv(const std::string& path, const ScanTable& scan);

// ASCII PCD v0.7, organised: WIDTH = azimuths, HEIGHT = rings x poses (row = pose * rings + ring);
// fields `x y z range ring object` (F F F F U I); x, y, z and range are nan for no return, object
// -1. Points are in the world frame, so VIEWPOINT is the identity.
void writeScanPcd(const std::string& path, const ScanTable& scan);

// Writes by the extension of `path`.
void writeScan(const std::string& path, const ScanTable& scan);

}  // namespace revolve::io
