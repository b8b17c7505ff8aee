#include "io/poses_file.h"

#include "geometry/ray_limits.h"
#include "io/csv_fields.h"
#include "io/text_files.h"

#include <cmath>
#include <optional>

namespace revolve::io {

std::vector<RobotPose> parsePosesCsv(std::string_view text, std::string_view file) {
  std::vector<RobotPose> poses;
  bool withZ = false, headerSeen = false;
  csv::Lines lines(text, file);
  while (const std::optional<std::string_view> raw = lines.next()) {
    const std::size_t lineNumber = lines.number();
    const std::string_view line = csv::trim(*raw);
    if (line.empty()) continue;
    const std::vector<std::string_view> fields = csv::splitFields(line);
    if (!headerSeen) {
      // The header decides whether there is a z column, so it is required.
      std::string joined;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i > 0) joined += ',';
        joined += fields[i];
      }
      if (joined != "x,y,z,yaw" && joined != "x,y,yaw") {
        throw InputError(file, lineNumber, "header " + csv::quote(line) + " is not \"x,y,z,yaw\" or \"x,y,yaw\"");
      }
      withZ = joined == "x,y,z,yaw";
      headerSeen = true;
      continue;
    }
    const std::size_t columns = withZ ? 4 : 3;
    if (fields.size() != columns) {
      throw InputError(file, lineNumber,
                       "expected " + std::to_string(columns) + " comma-separated values (" +
                           (withZ ? "x,y,z,yaw" : "x,y,yaw") + "), found " + std::to_string(fields.size()));
    }
    // `position`: a coordinate, within the limit every position keeps (geometry/ray_limits.h).
    const auto value = [&](std::size_t i, const char* name, bool emptyIsZero, bool position) {
      if (emptyIsZero && fields[i].empty()) return 0.0;
      const std::optional<double> x = csv::parseNumber<double>(fields[i]);
      if (!x)
        throw InputError(file, lineNumber, std::string(name) + " = " + csv::quote(fields[i]) + " is not a number");
      if (!std::isfinite(*x))
        throw InputError(file, lineNumber, std::string(name) + " = " + csv::quote(fields[i]) + " is not finite");
      if (position && std::abs(*x) > app::kMaxWorldCoordinate) {
        throw InputError(file, lineNumber,
                         std::string(name) + " = " + csv::quote(fields[i]) +
                             " is beyond the coordinate limit: " + app::kCoordinateLimitRule);
      }
      return *x;
    };
    RobotPose pose;
    pose.x = value(0, "x", false, true);
    pose.y = value(1, "y", false, true);
    pose.z = withZ ? value(2, "z", true, true) : 0.0;
    pose.yaw = value(withZ ? 3 : 2, "yaw", false, false);
    poses.push_back(pose);
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
