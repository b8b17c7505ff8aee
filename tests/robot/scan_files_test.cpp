// The scan writers, read back by readers written here from the formats' definitions: the
// LaserScan-shaped CSV (README) and ASCII PCD v0.7 (PCL's file format documentation: header lines
// VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA, then one point a line).
#include "io/scan_files.h"

#include "io/scratch_directory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace revolve::io {
namespace {

using revolve::testing::readWholeFile;
using revolve::testing::ScratchDirectory;

// Two poses of 2 rings x 3 azimuths, with returns and beams without one.
ScanTable sampleScan() {
  ScanTable scan;
  scan.azimuths = {-0.5, 0.0, 0.5};
  scan.elevations = {-0.1, 0.2};
  scan.poses = 2;
  for (int i = 0; i < 12; ++i) {
    if (i % 4 == 3) {
      scan.beams.push_back({INFINITY, 0, 0, 0, -1});
    } else {
      scan.beams.push_back({1.25f + 0.1f * i, 0.1f * i - 0.3f, 1.0f / (i + 3), -0.015625f * i, std::int32_t(i % 5)});
    }
  }
  return scan;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, separator)) out.push_back(field);
  if (!line.empty() && line.back() == separator) out.push_back("");
  return out;
}

TEST(ScanFilesTest, CsvReadsBackBeamForBeam) {
  const ScratchDirectory dir;
  const ScanTable scan = sampleScan();
  writeScan(dir / "scan.csv", scan);
  const std::vector<std::string> rows = lines(readWholeFile(dir / "scan.csv"));
  ASSERT_EQ(rows.size(), 13u);
  EXPECT_EQ(rows[0], "pose,ring,azimuth,elevation,range,x,y,z,object");
  std::size_t row = 1;
  for (std::size_t pose = 0; pose < 2; ++pose) {
    for (std::size_t ring = 0; ring < 2; ++ring) {
      for (std::size_t column = 0; column < 3; ++column, ++row) {
        const std::vector<std::string> f = split(rows[row], ',');
        ASSERT_EQ(f.size(), 9u) << rows[row];
        EXPECT_EQ(std::stoul(f[0]), pose);
        EXPECT_EQ(std::stoul(f[1]), ring);
        EXPECT_EQ(std::stod(f[2]), scan.azimuths[column]);
        EXPECT_EQ(std::stod(f[3]), scan.elevations[ring]);
        const BeamReturn& beam = scan.at(pose, ring, column);
        if (std::isinf(beam.range)) {
          EXPECT_EQ(f[4], "inf");
          EXPECT_EQ(f[5] + f[6] + f[7] + f[8], "");  // empty for no return
          continue;
        }
        // %.9g round-trips a float exactly.
        EXPECT_EQ(std::stof(f[4]), beam.range);
        EXPECT_EQ(std::stof(f[5]), beam.x);
        EXPECT_EQ(std::stof(f[6]), beam.y);
        EXPECT_EQ(std::stof(f[7]), beam.z);
        EXPECT_EQ(std::stoi(f[8]), beam.object);
      }
    }
  }
}

TEST(ScanFilesTest, PcdIsAnOrganisedCloudThatReadsBack) {
  const ScratchDirectory dir;
  const ScanTable scan = sampleScan();
  writeScan(dir / "scan.pcd", scan);
  const std::vector<std::string> text = lines(readWholeFile(dir / "scan.pcd"));
  // The header: its keys in the order PCD v0.7 requires, after optional # comments.
  std::size_t at = 0;
  while (at < text.size() && text[at].rfind('#', 0) == 0) ++at;
  std::map<std::string, std::string> header;
  const char* keys[] = {"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
  for (const char* key : keys) {
    ASSERT_LT(at, text.size());
    const std::size_t space = text[at].find(' ');
    ASSERT_EQ(text[at].substr(0, space), key) << "header line " << at;
    header[key] = text[at].substr(space + 1);
    ++at;
  }
  EXPECT_EQ(header["VERSION"], "0.7");
  EXPECT_EQ(header["FIELDS"], "x y z range ring object");
  EXPECT_EQ(header["SIZE"], "4 4 4 4 2 4");
  EXPECT_EQ(header["TYPE"], "F F F F U I");
  EXPECT_EQ(header["COUNT"], "1 1 1 1 1 1");
  EXPECT_EQ(std::stoul(header["WIDTH"]), 3u);      // azimuths
  EXPECT_EQ(std::stoul(header["HEIGHT"]), 2u * 2);  // rings x poses
  EXPECT_EQ(std::stoul(header["POINTS"]), 12u);
  EXPECT_EQ(header["DATA"], "ascii");
  ASSERT_EQ(text.size() - at, 12u);
  // Row r = pose * rings + ring, column = azimuth: point r * WIDTH + column.
  for (std::size_t point = 0; point < 12; ++point) {
    const std::vector<std::string> f = split(text[at + point], ' ');
    ASSERT_EQ(f.size(), 6u) << text[at + point];
    const std::size_t row = point / 3, column = point % 3;
    const BeamReturn& beam = scan.at(row / 2, row % 2, column);
    EXPECT_EQ(std::stoul(f[4]), row % 2);  // ring
    if (std::isinf(beam.range)) {
      for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isnan(std::stof(f[k]))) << f[k];  // PCL's invalid point
      EXPECT_EQ(std::stoi(f[5]), -1);
      continue;
    }
    EXPECT_EQ(std::stof(f[0]), beam.x);
    EXPECT_EQ(std::stof(f[1]), beam.y);
    EXPECT_EQ(std::stof(f[2]), beam.z);
    EXPECT_EQ(std::stof(f[3]), beam.range);
    EXPECT_EQ(std::stoi(f[5]), beam.object);
  }
}

TEST(ScanFilesTest, UnknownExtensionIsRefused) {
  EXPECT_EQ(scanFormatFor("a/b.CSV"), ScanFormat::csv);
  EXPECT_EQ(scanFormatFor("b.Pcd"), ScanFormat::pcd);
  EXPECT_THROW(scanFormatFor("b.ply"), std::runtime_error);
  EXPECT_THROW(scanFormatFor("b"), std::runtime_error);
}

}  // namespace
}  // namespace revolve::io
