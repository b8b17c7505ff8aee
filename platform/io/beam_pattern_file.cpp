#include "io/beam_pattern_file.h"

#include "io/csv_fields.h"
#include "io/input_file.h"

#include <cmath>
#include <numbers>
#include <optional>

namespace revolve::io {

namespace {

constexpr const char* kHeader = "azimuth,elevation,time";

}  // namespace

std::vector<PatternBeam> parseBeamPattern(std::string_view text, std::string_view file) {
  std::vector<PatternBeam> beams;
  bool headerSeen = false;
  csv::Lines lines(text, file);
  while (const std::optional<std::string_view> raw = lines.next()) {
    const std::size_t lineNumber = lines.number();
    const std::string_view line = csv::trim(*raw);
    if (line.empty()) continue;
    if (!headerSeen) {
      if (line != kHeader) {
        throw InputError(file, lineNumber,
                         "header " + csv::quote(line) + ": a beam pattern's header is \"" + kHeader + "\"");
      }
      headerSeen = true;
      continue;
    }
    const std::vector<std::string_view> fields = csv::splitFields(line);
    if (fields.size() != 3) {
      throw InputError(
          file, lineNumber,
          "expected 3 comma-separated values (azimuth,elevation,time), found " + std::to_string(fields.size()));
    }
    if (beams.size() == kMaxPatternBeams) {
      throw InputError(file, lineNumber, "more than 2^24 = " + std::to_string(kMaxPatternBeams) + " beams");
    }
    // Column `column` (1-based, named `name`) within [lo, hi].
    const auto value = [&](std::size_t column, const char* name, double lo, double hi, const char* rule) {
      const std::string_view field = fields[column - 1];
      const std::string where = "column " + std::to_string(column) + " (" + name + ") = " + csv::quote(field);
      const std::optional<double> x = csv::parseNumber<double>(field);
      if (!x) throw InputError(file, lineNumber, where + " is not a number");
      if (!(*x >= lo && *x <= hi)) throw InputError(file, lineNumber, where + " is out of range: " + rule);
      return *x;
    };
    constexpr double kTurn = 2 * std::numbers::pi, kRightAngle = std::numbers::pi / 2;
    PatternBeam beam;
    beam.azimuth = value(1, "azimuth", -kTurn, kTurn, "angles are in radians, within [-2 pi, 2 pi] (degrees?)");
    beam.elevation =
        value(2, "elevation", -kRightAngle, kRightAngle, "an elevation lies in [-pi/2, pi/2] radians (degrees?)");
    beam.time = value(3, "time", 0, kMaxPatternTime,
                      "a firing time is a number of seconds from the sweep's start, within [0, 3600]");
    beams.push_back(beam);
  }
  if (!headerSeen) throw InputError(file, 0, std::string("empty: expected the header \"") + kHeader + "\" and beams");
  if (beams.empty()) throw InputError(file, 0, "no beams after the header");
  return beams;
}

std::vector<PatternBeam> readBeamPattern(const std::string& path) {
  return parseBeamPattern(readTextFile(path, kMaxPatternFileBytes, "a beam pattern file"), path);
}

}  // namespace revolve::io
