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

// Two poses of 2 rings x 3 azimuths, with returns and beams without one; `layers` returns a beam.
ScanTable sampleScan(std::size_t layers = 1) {
  ScanTable scan;
  scan.azimuths = {-0.5, 0.0, 0.5};
  scan.elevations = {-0.1, 0.2};
  scan.poses = 2;
  scan.layers = layers;
  for (int i = 0; i < int(12 * layers); ++i) {
    const float time = 0.001f * float(i % 3) / 3;  // every beam fired, returned or not
    if (i % 4 == 3) {
      scan.points.push_back({INFINITY, 0, 0, 0, -1, 0, time});
    } else {
      scan.points.push_back({1.25f + 0.1f * i, 0.1f * i - 0.3f, 1.0f / (i + 3), -0.015625f * i, std::int32_t(i % 5),
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

// Rows in point order (pose, return layer, ring, column); a further layer's empty points have no row.
TEST(ScanFilesTest, CsvReadsBackBeamForBeam) {
  for (const std::size_t layers : {1u, 2u}) {
    SCOPED_TRACE("layers " + std::to_string(layers));
    const ScratchDirectory dir;
    const ScanTable scan = sampleScan(layers);
    writeScan(dir / "scan.csv", scan);
    const std::vector<std::string> rows = lines(readWholeFile(dir / "scan.csv"));
    EXPECT_EQ(rows[0], "pose,ring,return,azimuth,elevation,range,x,y,z,object,intensity,time");
    std::size_t row = 1;
    for (std::size_t pose = 0; pose < 2; ++pose) {
      for (std::size_t layer = 0; layer < layers; ++layer) {
        for (std::size_t ring = 0; ring < 2; ++ring) {
          for (std::size_t column = 0; column < 3; ++column) {
            const BeamReturn& beam = scan.at(pose, ring, column, layer);
            if (layer > 0 && std::isinf(beam.range)) continue;
            ASSERT_LT(row, rows.size());
            const std::vector<std::string> f = split(rows[row++], ',');
            ASSERT_EQ(f.size(), 12u) << rows[row - 1];
            EXPECT_EQ(std::stoul(f[0]), pose);
            EXPECT_EQ(std::stoul(f[1]), ring);
            EXPECT_EQ(std::stoul(f[2]), layer);
            EXPECT_EQ(std::stod(f[3]), scan.azimuths[column]);
            EXPECT_EQ(std::stod(f[4]), scan.elevations[ring]);
            EXPECT_EQ(std::stof(f[11]), beam.time);
            if (std::isinf(beam.range)) {
              EXPECT_EQ(f[5], "inf");
              EXPECT_EQ(f[6] + f[7] + f[8] + f[9] + f[10], "");  // empty for no return
              continue;
            }
            // %.9g round-trips a float exactly.
            EXPECT_EQ(std::stof(f[5]), beam.range);
            EXPECT_EQ(std::stof(f[6]), beam.x);
            EXPECT_EQ(std::stof(f[7]), beam.y);
            EXPECT_EQ(std::stof(f[8]), beam.z);
            EXPECT_EQ(std::stoi(f[9]), beam.object);
            EXPECT_EQ(std::stof(f[10]), beam.intensity);
          }
        }
      }
    }
    EXPECT_EQ(row, rows.size());
  }
}

TEST(ScanFilesTest, PcdIsAnOrganisedCloudThatReadsBack) {
  for (const std::size_t layers : {1u, 2u}) {
    SCOPED_TRACE("layers " + std::to_string(layers));
    const ScratchDirectory dir;
    const ScanTable scan = sampleScan(layers);
    const std::size_t points = 12 * layers;
    writeScan(dir / "scan.pcd", scan);
    const std::vector<std::string> text = lines(readWholeFile(dir / "scan.pcd"));
    // The header: its keys in the order PCD v0.7 requires, after optional # comments.
    std::size_t at = 0;
    while (at < text.size() && text[at].rfind('#', 0) == 0) ++at;
    std::map<std::string, std::string> header;
    const char* keys[] = {"VERSION", "FIELDS", "SIZE",      "TYPE",   "COUNT",
                          "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
    for (const char* key : keys) {
      ASSERT_LT(at, text.size());
      const std::size_t space = text[at].find(' ');
      ASSERT_EQ(text[at].substr(0, space), key) << "header line " << at;
      header[key] = text[at].substr(space + 1);
      ++at;
    }
    EXPECT_EQ(header["VERSION"], "0.7");
    EXPECT_EQ(header["FIELDS"], "x y z range ring return object intensity time");
    EXPECT_EQ(header["SIZE"], "4 4 4 4 2 1 4 4 4");
    EXPECT_EQ(header["TYPE"], "F F F F U U I F F");
    EXPECT_EQ(header["COUNT"], "1 1 1 1 1 1 1 1 1");
    EXPECT_EQ(std::stoul(header["WIDTH"]), 3u);                // azimuths
    EXPECT_EQ(std::stoul(header["HEIGHT"]), 2u * 2 * layers);  // rings x layers x poses
    EXPECT_EQ(std::stoul(header["POINTS"]), points);
    EXPECT_EQ(header["DATA"], "ascii");
    ASSERT_EQ(text.size() - at, points);
    // Row r = (pose * layers + layer) * rings + ring, column = azimuth: point r * WIDTH + column.
    for (std::size_t point = 0; point < points; ++point) {
      const std::vector<std::string> f = split(text[at + point], ' ');
      ASSERT_EQ(f.size(), 9u) << text[at + point];
      const std::size_t row = point / 3, column = point % 3;
      const std::size_t ring = row % 2, layer = row / 2 % layers, pose = row / 2 / layers;
      const BeamReturn& beam = scan.at(pose, ring, column, layer);
      EXPECT_EQ(std::stoul(f[4]), ring);
      EXPECT_EQ(std::stoul(f[5]), layer);  // return
      EXPECT_EQ(std::stof(f[8]), beam.time);
      if (std::isinf(beam.range)) {
        for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isnan(std::stof(f[k]))) << f[k];  // PCL's invalid point
        EXPECT_EQ(std::stoi(f[6]), -1);
        EXPECT_TRUE(std::isnan(std::stof(f[7])));
        continue;
      }
      EXPECT_EQ(std::stof(f[7]), beam.intensity);
      EXPECT_EQ(std::stof(f[0]), beam.x);
      EXPECT_EQ(std::stof(f[1]), beam.y);
      EXPECT_EQ(std::stof(f[2]), beam.z);
      EXPECT_EQ(std::stof(f[3]), beam.range);
      EXPECT_EQ(std::stoi(f[6]), beam.object);
    }
  }
}

// DATA binary as PCL reads it (pcl::PCDReader, readBodyBinary): after the header's DATA line, the
// points back to back, each its fields in FIELDS order at their SIZEs, no padding (point_step = 4 +
// 4 + 4 + 4 + 2 + 1 + 4 + 4 + 4 = 31), in the machine's byte order.
TEST(ScanFilesTest, BinaryPcdHoldsEveryPointInPclsPackedLayout) {
  const ScratchDirectory dir;
  const ScanTable scan = sampleScan(2);
  writeScan(dir / "scan.pcd", scan, PcdData::binary);
  const std::string cloud = readWholeFile(dir / "scan.pcd");
  const std::size_t data = cloud.find("DATA binary\n");
  ASSERT_NE(data, std::string::npos);
  EXPECT_NE(cloud.find("\nSIZE 4 4 4 4 2 1 4 4 4\nTYPE F F F F U U I F F\n"), std::string::npos);
  EXPECT_NE(cloud.find("\nWIDTH 3\nHEIGHT 8\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 24\n"), std::string::npos);
  const std::string points = cloud.substr(data + 12);
  ASSERT_EQ(points.size(), 24u * 31);
  for (std::size_t point = 0; point < 24; ++point) {
    const char* at = points.data() + 31 * point;
    float x, y, z, range, intensity, time;
    std::uint16_t ring;
    std::uint8_t layer;
    std::int32_t object;
    std::memcpy(&x, at, 4);
    std::memcpy(&y, at + 4, 4);
    std::memcpy(&z, at + 8, 4);
    std::memcpy(&range, at + 12, 4);
    std::memcpy(&ring, at + 16, 2);
    std::memcpy(&layer, at + 18, 1);
    std::memcpy(&object, at + 19, 4);
    std::memcpy(&intensity, at + 23, 4);
    std::memcpy(&time, at + 27, 4);
    const std::size_t row = point / 3, column = point % 3;
    const BeamReturn& beam = scan.at(row / 4, row % 2, column, row / 2 % 2);
    EXPECT_EQ(ring, row % 2);
    EXPECT_EQ(layer, row / 2 % 2);
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
    const std::span<const BeamReturn> beams(scan.points);
    writer.write(0, beams.subspan(0, 5));
    writer.write(5, beams.subspan(5, 1));
    writer.write(6, beams.subspan(6));
    outputs.commit();
    EXPECT_EQ(readWholeFile(blocks), readWholeFile(dir / name));
  }
}

// A beam pattern's scan: one ring whose columns are the pattern's beams, each with its own
// elevation; the PCD is unorganised (HEIGHT 1), its points in pose, layer, beam order.
TEST(ScanFilesTest, PatternScanIsAnUnorganisedCloud) {
  const ScratchDirectory dir;
  ScanTable scan = sampleScan(2);  // 24 points: 2 poses x 2 layers x 6 beams
  scan.azimuths = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  scan.elevations = {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2};  // one per beam
  scan.pattern = true;
  writeScan(dir / "pattern.pcd", scan);
  const std::string cloud = readWholeFile(dir / "pattern.pcd");
  EXPECT_NE(cloud.find("\nWIDTH 24\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 24\n"), std::string::npos);
  const std::vector<std::string> text = lines(cloud);
  ASSERT_GE(text.size(), 24u);
  for (std::size_t point = 0; point < 24; ++point) {
    const std::vector<std::string> f = split(text[text.size() - 24 + point], ' ');
    ASSERT_EQ(f.size(), 9u);
    EXPECT_EQ(f[4], "0");                                 // one ring
    EXPECT_EQ(std::stoul(f[5]), point / 6 % 2);           // return layer
    EXPECT_EQ(std::stof(f[8]), scan.points[point].time);  // in point order
  }
  writeScan(dir / "pattern.csv", scan);
  const std::vector<std::string> rows = lines(readWholeFile(dir / "pattern.csv"));
  ASSERT_GE(rows.size(), 2u);
  const std::vector<std::string> f = split(rows[4], ',');  // pose 0, layer 0, beam 3
  EXPECT_EQ(std::stod(f[3]), 0.4);
  EXPECT_EQ(std::stod(f[4]), 0.0);
  const std::vector<std::string> g = split(rows[6], ',');  // beam 5
  EXPECT_EQ(std::stod(g[4]), 0.2);
}

TEST(ScanFilesTest, UnknownExtensionIsRefused) {
  EXPECT_EQ(scanFormatFor("a/b.CSV"), ScanFormat::csv);
  EXPECT_EQ(scanFormatFor("b.Pcd"), ScanFormat::pcd);
  EXPECT_THROW(scanFormatFor("b.ply"), std::runtime_error);
  EXPECT_THROW(scanFormatFor("b"), std::runtime_error);
}

}  // namespace
}  // namespace revolve::io
