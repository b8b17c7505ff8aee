#include "io/text_files.h"

#include "io/csv_fields.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <sys/stat.h>
#include <unistd.h>

namespace revolve::io {
namespace {

using csv::parseNumber;
using csv::quote;
using csv::splitFields;
using csv::trim;

// Calls row(fields, line) for every non-blank line; a first line equal to `header` is skipped,
// and a first line that starts with a non-number is reported as a wrong header.
template <class Row>
void forEachRow(std::string_view text, std::string_view file, std::string_view header, std::size_t columns, Row&& row) {
  std::size_t lineNumber = 0;
  bool first = true;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    const std::string_view raw = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    ++lineNumber;
    const std::string_view line = trim(raw);
    if (line.empty()) continue;
    const std::vector<std::string_view> fields = splitFields(line);
    if (first) {
      first = false;
      if (!parseNumber<double>(fields[0])) {
        std::string joined;
        for (std::size_t i = 0; i < fields.size(); ++i) {
          if (i > 0) joined += ',';
          joined += fields[i];
        }
        if (joined == header) continue;
        throw InputError(file, lineNumber,
                         "header " + quote(line) + " is not the expected \"" + std::string(header) + "\"");
      }
    }
    if (fields.size() != columns) {
      throw InputError(file, lineNumber,
                       "expected " + std::to_string(columns) + " comma-separated values (" + std::string(header) +
                           "), found " + std::to_string(fields.size()));
    }
    row(fields, lineNumber);
  }
}

template <class T>
T numberAt(const std::vector<std::string_view>& fields, std::size_t i, std::string_view file, std::size_t line,
           std::string_view name) {
  const std::optional<T> value = parseNumber<T>(fields[i]);
  if (!value) throw InputError(file, line, std::string(name) + " = " + quote(fields[i]) + " is not a number");
  return *value;
}

}  // namespace

InputError::InputError(std::string_view file, std::size_t line, const std::string& problem)
    : std::runtime_error(std::string(file) + ":" + std::to_string(line) + ": " + problem) {}

std::string readTextFile(const std::string& path) {
  // A directory opens like a file and reads as empty; say what it is instead.
  std::error_code code;
  if (std::filesystem::is_directory(path, code)) throw InputError(path, 0, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream contents;
  contents << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "read error");
  return std::move(contents).str();
}

ProfileFile parseProfileCsv(std::string_view text, std::string_view file) {
  ProfileFile profile;
  forEachRow(text, file, "r,z", 2, [&](const std::vector<std::string_view>& fields, std::size_t line) {
    profile.points.push_back({numberAt<double>(fields, 0, file, line, "r"), numberAt<double>(fields, 1, file, line, "z")});
    profile.lines.push_back(line);
  });
  if (profile.points.empty()) throw InputError(file, 0, "no profile points");
  return profile;
}

ProfileFile readProfileCsv(const std::string& path) { return parseProfileCsv(readTextFile(path), path); }

std::vector<Ray> parseRaysCsv(std::string_view text, std::string_view file) {
  static constexpr std::array<std::string_view, 8> kNames{"ox", "oy", "oz", "dx", "dy", "dz", "tnear", "tfar"};
  std::vector<Ray> rays;
  forEachRow(text, file, "ox,oy,oz,dx,dy,dz,tnear,tfar", 8, [&](const std::vector<std::string_view>& fields,
                                                                 std::size_t line) {
    float v[8];
    for (std::size_t i = 0; i < 8; ++i) {
      v[i] = numberAt<float>(fields, i, file, line, kNames[i]);
      const bool allowedInfinity = i == 7 && v[i] == INFINITY;
      if (!std::isfinite(v[i]) && !allowedInfinity) {
        throw InputError(file, line, std::string(kNames[i]) + " = " + quote(fields[i]) +
                                         " is not finite" + (i == 7 ? " (tfar may be inf)" : ""));
      }
    }
    if (v[3] == 0.0f && v[4] == 0.0f && v[5] == 0.0f) throw InputError(file, line, "direction (0, 0, 0) is zero");
    if (!(v[6] >= 0.0f)) throw InputError(file, line, "tnear = " + quote(fields[6]) + " is negative; need tnear >= 0");
    if (!(v[6] <= v[7])) {
      throw InputError(file, line, "tnear = " + quote(fields[6]) + " exceeds tfar = " + quote(fields[7]));
    }
    rays.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], v[7]});
  });
  return rays;
}

std::vector<Ray> readRaysCsv(const std::string& path) { return parseRaysCsv(readTextFile(path), path); }

void writeFileAtomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
  std::string temporary = path + ".tmp-XXXXXX";
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) throw std::runtime_error(path + ": cannot create a temporary file: " + std::strerror(errno));
  // mkstemp makes the file private (0600); give the result the permissions a plain create would.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(descriptor, 0666 & ~mask);
  std::FILE* out = fdopen(descriptor, "w");
  if (out == nullptr) {
    const int error = errno;
    close(descriptor);
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": " + std::strerror(error));
  }
  try {
    write(out);
  } catch (...) {
    std::fclose(out);
    std::remove(temporary.c_str());
    throw;
  }
  const bool failed = std::ferror(out) != 0;
  const int error = errno;
  if (std::fclose(out) != 0 || failed) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": write failed: " + std::strerror(error));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int renameError = errno;
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot replace: " + std::strerror(renameError));
  }
}

void checkWritable(const std::string& path) {
  std::error_code code;
  if (std::filesystem::is_directory(path, code)) throw std::runtime_error(path + ": is a directory, not a file");
  std::string temporary = path + ".tmp-XXXXXX";
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) throw std::runtime_error(path + ": cannot create a file there: " + std::strerror(errno));
  close(descriptor);
  std::remove(temporary.c_str());
}

void writeHitsCsv(const std::string& path, const std::vector<std::optional<Hit>>& hits) {
  writeFileAtomically(path, [&](std::FILE* out) {
    std::fputs("hit,t,nx,ny,nz,u,v\n", out);
    for (const std::optional<Hit>& hit : hits) {
      if (!hit) {
        std::fputs("0,inf,0,0,0,0,0\n", out);
        continue;
      }
      std::fprintf(out, "1,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", hit->t, hit->normal.x, hit->normal.y, hit->normal.z,
                   hit->u, hit->v);
    }
  });
}

}  // namespace revolve::io
