// The scan writers, read back by readers written here from the formats' definitions: the
// LaserScan-shaped CSV (README) and ASCII PCD v0.7 (PCL's file format documentation: header lines
// VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA, then one point a line).
#include "io/scan_files.h"

#include "io/scratch_directory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
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
    const float time = 0.001f * float(i % 3) / 3;  // every beam fired, returned or not
    if (i % 4 == 3) {
      scan.beams.push_back({INFINITY, 0, 0, 0, -1, 0, time});
    } else {
      scan.beams.push_back({1.25f + 0.1f * i, 0.1f * i - 0.3f, 1.0f / (i + 3), -0.015625f * i, std::int32_t(i % 5),
                            0.7f / float(i + 1), time});
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
  EXPECT_EQ(rows[0], "pose,ring,azimuth,elevation,range,x,y,z,object,intensity,time");
  std::size_t row = 1;
  for (std::size_t pose = 0; pose < 2; ++pose) {
    for (std::size_t ring = 0; ring < 2; ++ring) {
      for (std::size_t column = 0; column < 3; ++column, ++row) {
        const std::vector<std::string> f = split(rows[row], ',');
        ASSERT_EQ(f.size(), 11u) << rows[row];
        EXPECT_EQ(std::stoul(f[0]), pose);
        EXPECT_EQ(std::stoul(f[1]), ring);
        EXPECT_EQ(std::stod(f[2]), scan.azimuths[column]);
        EXPECT_EQ(std::stod(f[3]), scan.elevations[ring]);
        const BeamReturn& beam = scan.at(pose, ring, column);
        EXPECT_EQ(std::stof(f[10]), beam.time);
        if (std::isinf(beam.range)) {
          EXPECT_EQ(f[4], "inf");
          EXPECT_EQ(f[5] + f[6] + f[7] + f[8] + f[9], "");  // empty for no return
          continue;
        }
        // %.9g round-trips a float exactly.
        EXPECT_EQ(std::stof(f[4]), beam.range);
        EXPECT_EQ(std::stof(f[5]), beam.x);
        EXPECT_EQ(std::stof(f[6]), beam.y);
        EXPECT_EQ(std::stof(f[7]), beam.z);
        EXPECT_EQ(std::stoi(f[8]), beam.object);
        EXPECT_EQ(std::stof(f[9]), beam.intensity);
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
  EXPECT_EQ(header["FIELDS"], "x y z range ring object intensity time");
  EXPECT_EQ(header["SIZE"], "4 4 4 4 2 4 4 4");
  EXPECT_EQ(header["TYPE"], "F F F F U I F F");
  EXPECT_EQ(header["COUNT"], "1 1 1 1 1 1 1 1");
  EXPECT_EQ(std::stoul(header["WIDTH"]), 3u);       // azimuths
  EXPECT_EQ(std::stoul(header["HEIGHT"]), 2u * 2);  // rings x poses
  EXPECT_EQ(std::stoul(header["POINTS"]), 12u);
  EXPECT_EQ(header["DATA"], "ascii");
  ASSERT_EQ(text.size() - at, 12u);
  // Row r = pose * rings + ring, column = azimuth: point r * WIDTH + column.
  for (std::size_t point = 0; point < 12; ++point) {
    const std::vector<std::string> f = split(text[at + point], ' ');
    ASSERT_EQ(f.size(), 8u) << text[at + point];
    const std::size_t row = point / 3, column = point % 3;
    const BeamReturn& beam = scan.at(row / 2, row % 2, column);
    EXPECT_EQ(std::stoul(f[4]), row % 2);  // ring
    EXPECT_EQ(std::stof(f[7]), beam.time);
    if (std::isinf(beam.range)) {
      for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isnan(std::stof(f[k]))) << f[k];  // PCL's invalid point
      EXPECT_EQ(std::stoi(f[5]), -1);
      EXPECT_TRUE(std::isnan(std::stof(f[6])));
      continue;
    }
    EXPECT_EQ(std::stof(f[6]), beam.intensity);
    EXPECT_EQ(std::stof(f[0]), beam.x);
    EXPECT_EQ(std::stof(f[1]), beam.y);
    EXPECT_EQ(std::stof(f[2]), beam.z);
    EXPECT_EQ(std::stof(f[3]), beam.range);
    EXPECT_EQ(std::stoi(f[5]), beam.object);
  }
}

// DATA binary as PCL reads it (pcl::PCDReader, readBodyBinary): after the header's DATA line, the
// points back to back, each its fields in FIELDS order at their SIZEs, no padding (point_step = 4 +
// 4 + 4 + 4 + 2 + 4 + 4 + 4 = 30), in the machine's byte order.
TEST(ScanFilesTest, BinaryPcdHoldsEveryPointInPclsPackedLayout) {
  const ScratchDirectory dir;
  const ScanTable scan = sampleScan();
  writeScan(dir / "scan.pcd", scan, PcdData::binary);
  const std::string cloud = readWholeFile(dir / "scan.pcd");
  const std::size_t data = cloud.find("DATA binary\n");
  ASSERT_NE(data, std::string::npos);
  EXPECT_NE(cloud.find("\nSIZE 4 4 4 4 2 4 4 4\nTYPE F F F F U I F F\n"), std::string::npos);
  EXPECT_NE(cloud.find("\nWIDTH 3\nHEIGHT 4\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 12\n"), std::string::npos);
  const std::string points = cloud.substr(data + 12);
  ASSERT_EQ(points.size(), 12u * 30);
  for (std::size_t point = 0; point < 12; ++point) {
    const char* at = points.data() + 30 * point;
    float x, y, z, range, intensity, time;
    std::uint16_t ring;
    std::int32_t object;
    std::memcpy(&x, at, 4);
    std::memcpy(&y, at + 4, 4);
    std::memcpy(&z, at + 8, 4);
    std::memcpy(&range, at + 12, 4);
    std::memcpy(&ring, at + 16, 2);
    std::memcpy(&object, at + 18, 4);
    std::memcpy(&intensity, at + 22, 4);
    std::memcpy(&time, at + 26, 4);
    const std::size_t row = point / 3, column = point % 3;
    const BeamReturn& beam = scan.at(row / 2, row % 2, column);
    EXPECT_EQ(ring, row % 2);
    EXPECT_EQ(time, beam.time);
    if (std::isinf(beam.range)) {
      EXPECT_TRUE(std::isnan(x) && std::isnan(y) && std::isnan(z) && std::isnan(range));
      EXPECT_EQ(object, -1);
      EXPECT_TRUE(std::isnan(intensity));
      continue;
    }
    EXPECT_EQ(intensity, beam.intensity);
    EXPECT_EQ(x, beam.x);
    EXPECT_EQ(y, beam.y);
    EXPECT_EQ(z, beam.z);
    EXPECT_EQ(range, beam.range);
    EXPECT_EQ(object, beam.object);
  }
}

// A scan written block by block, split anywhere (inside a row, across poses), is the same file as
// the whole table written at once.
TEST(ScanFilesTest, WritingInBlocksGivesTheSameFile) {
  const ScratchDirectory dir;
  const ScanTable scan = sampleScan();
  for (const auto& [name, format, data] : {std::tuple{"scan.csv", ScanFormat::csv, PcdData::ascii},
                                           std::tuple{"scan.pcd", ScanFormat::pcd, PcdData::ascii},
                                           std::tuple{"binary.pcd", ScanFormat::pcd, PcdData::binary}}) {
    SCOPED_TRACE(name);
    writeScan(dir / name, scan, data);
    const std::string blocks = dir / (std::string("blocks-") + name);
    OutputSet outputs;
    outputs.add("", blocks);
    ScanWriter writer(outputs.stream(blocks), format, data, scan);
    const std::span<const BeamReturn> beams(scan.beams);
    writer.write(0, beams.subspan(0, 5));
    writer.write(5, beams.subspan(5, 1));
    writer.write(6, beams.subspan(6));
    outputs.commit();
    EXPECT_EQ(readWholeFile(blocks), readWholeFile(dir / name));
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
