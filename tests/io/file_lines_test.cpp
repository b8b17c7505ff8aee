// FileLines (io/input_file.h): a file read a block at a time gives the lines it was written with,
// numbered from 1, across the reader's 1 MiB blocks; refuses an overlong line by its number as
// csv::Lines does; and refuses what is not a regular file before reading.
#include "io/input_file.h"

#include "scratch_directory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {
namespace {

using revolve::testing::ScratchDirectory;
using ::testing::HasSubstr;

// Lines of lengths 0 to 4096 (the longest allowed), about 5 MB: many straddle a block's end.
std::vector<std::string> writtenLines() {
  std::vector<std::string> lines;
  std::size_t bytes = 0;
  for (std::size_t i = 0; bytes < 5000000; ++i) {
    const std::size_t length = (i * 7919) % (kMaxCsvLineBytes + 1);
    std::string line(length, char('a' + i % 26));
    if (length > 0) line[0] = '#';
    bytes += length + 1;
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<std::string> readBack(const std::string& path) {
  FileLines lines(path, std::uint64_t{1} << 30, "a test file");
  std::vector<std::string> read;
  while (const std::optional<std::string_view> line = lines.next()) {
    read.emplace_back(*line);
    EXPECT_EQ(lines.number(), read.size());
  }
  return read;
}

TEST(FileLinesTest, GivesTheLinesWrittenAcrossBlocks) {
  const ScratchDirectory dir;
  const std::vector<std::string> lines = writtenLines();
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  EXPECT_EQ(readBack(dir.write("ended.txt", text)), lines);
  // Without the last '\n', the last line is still a line.
  text.pop_back();
  EXPECT_EQ(readBack(dir.write("unended.txt", text)), lines);
  EXPECT_TRUE(readBack(dir.write("empty.txt", "")).empty());
}

TEST(FileLinesTest, RefusesAnOverlongLineByItsNumber) {
  const ScratchDirectory dir;
  std::string text;
  for (int i = 0; i < 1000; ++i) text += std::string(1000, 'x') + "\n";  // line 1001 starts near 1 MB
  text += std::string(kMaxCsvLineBytes + 1, 'y') + "\n";
  const std::string path = dir.write("long.txt", text);
  FileLines lines(path, std::uint64_t{1} << 30, "a test file");
  try {
    while (lines.next()) {}
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("long.txt:1001: the line is more than 4096 bytes long"));
  }
}

TEST(FileLinesTest, RefusesADirectoryAndAFileBeyondItsLimit) {
  const ScratchDirectory dir;
  EXPECT_THROW(FileLines(dir.path().string(), 100, "a test file"), InputError);
  const std::string path = dir.write("big.txt", std::string(200, 'z'));
  try {
    FileLines lines(path, 100, "a test file");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("is too large: a test file is read up to 100 bytes"));
  }
}

}  // namespace
}  // namespace revolve::io
