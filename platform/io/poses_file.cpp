#include "io/poses_file.h"

#include "geometry/ray_limits.h"
#include "io/csv_fields.h"
#include "io/text_files.h"

#include <cmath>
#include <optional>

namespace revolve::io {

namespace {

// The columns a poses file may have, in the order messages list them.
enum Column { kTime, kX, kY, kZ, kRoll, kPitch, kYaw, kColumns };
constexpr const char* kColumnNames[kColumns] = {"time", "x", "y", "z", "roll", "pitch", "yaw"};
constexpr const char* kHeaderRule =
    "the columns are x, y and yaw, with z, roll, pitch and time optional, each once (x,y,z,yaw)";

}  // namespace

std::vector<RobotPose> parsePosesCsv(std::string_view text, std::string_view file) {
  std::vector<RobotPose> poses;
  // Where each column is in a line (-1: absent), from the header, which is therefore required.
  int at[kColumns] = {-1, -1, -1, -1, -1, -1, -1};
  std::size_t columns = 0;
  bool headerSeen = false;
  std::size_t previousLine = 0;
  std::string previousTime;  // as written on previousLine
  csv::Lines lines(text, file);
  while (const std::optional<std::string_view> raw = lines.next()) {
    const std::size_t lineNumber = lines.number();
    const std::string_view line = csv::trim(*raw);
    if (line.empty()) continue;
    const std::vector<std::string_view> fields = csv::splitFields(line);
    if (!headerSeen) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        int column = kColumns;
        for (int c = 0; c < kColumns; ++c)
          if (fields[i] == kColumnNames[c]) column = c;
        if (column == kColumns || at[column] >= 0) {
          throw InputError(file, lineNumber,
                           "header " + csv::quote(line) + ": column " + std::to_string(i + 1) + " " +
                               csv::quote(fields[i]) + (column == kColumns ? " is not a pose column" : " is repeated") +
                               "; " + kHeaderRule);
        }
        at[column] = int(i);
      }
      if (at[kX] < 0 || at[kY] < 0 || at[kYaw] < 0)
        throw InputError(file, lineNumber, "header " + csv::quote(line) + " lacks x, y or yaw; " + kHeaderRule);
      columns = fields.size();
      headerSeen = true;
      continue;
    }
    if (fields.size() != columns) {
      throw InputError(file, lineNumber,
                       "expected " + std::to_string(columns) + " comma-separated values (as the header), found " +
                           std::to_string(fields.size()));
    }
    // `position`: a coordinate, within the limit every position keeps (geometry/ray_limits.h).
    const auto value = [&](Column column, bool emptyIsZero, bool position) {
      const std::string_view field = fields[std::size_t(at[column])];
      const std::string name = kColumnNames[column];
      if (emptyIsZero && field.empty()) return 0.0;
      const std::optional<double> x = csv::parseNumber<double>(field);
      if (!x) throw InputError(file, lineNumber, name + " = " + csv::quote(field) + " is not a number");
      if (!std::isfinite(*x)) throw InputError(file, lineNumber, name + " = " + csv::quote(field) + " is not finite");
      if (position && std::abs(*x) > app::kMaxWorldCoordinate) {
        throw InputError(
            file, lineNumber,
            name + " = " + csv::quote(field) + " is beyond the coordinate limit: " + app::kCoordinateLimitRule);
      }
      return *x;
    };
    RobotPose pose;
    pose.x = value(kX, false, true);
    pose.y = value(kY, false, true);
    pose.z = at[kZ] >= 0 ? value(kZ, true, true) : 0.0;
    pose.yaw = value(kYaw, false, false);
    if (at[kRoll] >= 0) pose.roll = value(kRoll, false, false);
    if (at[kPitch] >= 0) pose.pitch = value(kPitch, false, false);
    if (at[kTime] >= 0) {
      pose.time = value(kTime, false, false);
      if (const char* problem = poseTimeProblem(pose.time, poses.empty() ? std::nan("") : poses.back().time)) {
        std::string message = "time = " + csv::quote(fields[std::size_t(at[kTime])]) + " " + problem;
        if (!poses.empty())
          message += " (the pose on line " + std::to_string(previousLine) + " is at " + previousTime + ")";
        throw InputError(file, lineNumber, message);
      }
      previousTime = std::string(fields[std::size_t(at[kTime])]);
    }
    poses.push_back(pose);
    previousLine = lineNumber;
  }
  if (!headerSeen)
    throw InputError(file, 0, "empty: expected the header \"x,y,z,yaw\" (or \"x,y,yaw\") and at least one pose");
  if (poses.empty()) throw InputError(file, 0, "no poses after the header");
  return poses;
}

std::vector<RobotPose> readPosesCsv(const std::string& path) {
  return parsePosesCsv(readTextFile(path, kMaxCsvFileBytes, "a CSV file"), path);
}

}  // namespace revolve::io
