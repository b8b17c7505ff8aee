// The beam pattern file: a sensor's beams listed one a line, for sensors whose beams are not even
// fans (a spinning sensor's calibrated channel table with its firing times, a non-repetitive
// rosette). CSV with the header `azimuth,elevation,time`: radians counter-clockwise about the
// sensor's +Z from its +X, radians up from its XY plane, seconds from the sweep's start to the
// beam's firing. At most 2^24 beams; the scan keeps the file's order (io::ScanLayout).
//
// The reader is strict: a bad line is an InputError naming the file, the line, the column and the
// rule it breaks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

struct PatternBeam {
  double azimuth = 0, elevation = 0, time = 0;
};

inline constexpr std::size_t kMaxPatternBeams = std::size_t{1} << 24;
// The latest firing time a beam may have: an hour after its sweep starts.
inline constexpr double kMaxPatternTime = 3600;
// A pattern file's size limit: 2^24 lines of up to 64 characters.
inline constexpr std::uint64_t kMaxPatternFileBytes = std::uint64_t{1} << 30;

// Parses pattern CSV `text`; `file` names it in messages. Throws InputError (text_files.h).
std::vector<PatternBeam> parseBeamPattern(std::string_view text, std::string_view file);
std::vector<PatternBeam> readBeamPattern(const std::string& path);

}  // namespace revolve::io
