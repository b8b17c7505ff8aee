#include "io/scan_files.h"

#include "io/text_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace revolve::io {

ScanFormat scanFormatFor(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".csv") return ScanFormat::csv;
  if (extension == ".pcd") return ScanFormat::pcd;
  throw std::runtime_error(path + ": unsupported scan extension \"" + extension +
                           "\"; use .csv (a LaserScan-shaped table) or .pcd (an ASCII PCD v0.7 point cloud)");
}

void writeScanCsv(const std::string& path, const ScanTable& scan) {
  writeFileAtomically(path, [&](std::FILE* out) {
    std::fputs("pose,ring,azimuth,elevation,range,x,y,z,object\n", out);
    for (std::size_t pose = 0; pose < scan.poses; ++pose) {
      for (std::size_t ring = 0; ring < scan.rings(); ++ring) {
        for (std::size_t column = 0; column < scan.azimuths.size(); ++column) {
          const BeamReturn& beam = scan.at(pose, ring, column);
          std::fprintf(out, "%zu,%zu,%.9g,%.9g,", pose, ring, scan.azimuths[column], scan.elevations[ring]);
          if (std::isinf(beam.range)) {
            std::fputs("inf,,,,\n", out);
          } else {
            std::fprintf(out, "%.9g,%.9g,%.9g,%.9g,%d\n", beam.range, beam.x, beam.y, beam.z, int(beam.object));
          }
        }
      }
    }
  });
}

void writeScanPcd(const std::string& path, const ScanTable& scan) {
  writeFileAtomically(path, [&](std::FILE* out) {
    const std::size_t width = scan.azimuths.size(), height = scan.rings() * scan.poses;
    std::fprintf(out,
                 "# .PCD v0.7 - Point Cloud Data file format\n"
                 "VERSION 0.7\n"
                 "FIELDS x y z range ring object\n"
                 "SIZE 4 4 4 4 2 4\n"
                 "TYPE F F F F U I\n"
                 "COUNT 1 1 1 1 1 1\n"
                 "WIDTH %zu\n"
                 "HEIGHT %zu\n"
                 "VIEWPOINT 0 0 0 1 0 0 0\n"
                 "POINTS %zu\n"
                 "DATA ascii\n",
                 width, height, width * height);
    for (std::size_t pose = 0; pose < scan.poses; ++pose) {
      for (std::size_t ring = 0; ring < scan.rings(); ++ring) {
        for (std::size_t column = 0; column < width; ++column) {
          const BeamReturn& beam = scan.at(pose, ring, column);
          if (std::isinf(beam.range)) {
            std::fprintf(out, "nan nan nan nan %zu -1\n", ring);
          } else {
            std::fprintf(out, "%.9g %.9g %.9g %.9g %zu %d\n", beam.x, beam.y, beam.z, beam.range, ring, int(beam.object));
          }
        }
      }
    }
  });
}

void writeScan(const std::string& path, const ScanTable& scan) {
  if (scanFormatFor(path) == ScanFormat::csv) {
    writeScanCsv(path, scan);
  } else {
    writeScanPcd(path, scan);
  }
}

}  // namespace revolve::io
