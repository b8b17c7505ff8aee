#include "io/text_files.h"

#include "io/csv_fields.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <type_traits>

namespace revolve::io {
namespace {

using csv::parseNumber;
using csv::quote;

// Calls row(fields, line) for every row (csv::Rows).
template <class Row>
void forEachRow(std::string_view text, std::string_view file, std::string_view header, std::size_t columns, Row&& row) {
  csv::Lines lines(text, file);
  csv::Rows rows(lines, file, header, columns);
  while (const std::vector<std::string_view>* fields = rows.next()) row(*fields, rows.line());
}

template <class T>
T numberAt(const std::vector<std::string_view>& fields, std::size_t i, std::string_view file, std::size_t line,
           std::string_view name) {
  const std::optional<T> value = parseNumber<T>(fields[i]);
  if (!value) throw InputError(file, line, std::string(name) + " = " + quote(fields[i]) + " is not a number");
  return *value;
}

}  // namespace

ProfileFile parseProfileCsv(std::string_view text, std::string_view file) {
  ProfileFile profile;
  forEachRow(text, file, "r,z", 2, [&](const std::vector<std::string_view>& fields, std::size_t line) {
    profile.points.push_back(
        {numberAt<double>(fields, 0, file, line, "r"), numberAt<double>(fields, 1, file, line, "z")});
    profile.lines.push_back(line);
  });
  if (profile.points.empty()) throw InputError(file, 0, "no profile points");
  return profile;
}

ProfileFile readProfileCsv(const std::string& path) {
  return parseProfileCsv(readTextFile(path, kMaxCsvFileBytes, "a CSV file"), path);
}

std::vector<Ray> parseRaysCsv(std::string_view text, std::string_view file) {
  static constexpr std::array<std::string_view, 8> kNames{"ox", "oy", "oz", "dx", "dy", "dz", "tnear", "tfar"};
  std::vector<Ray> rays;
  forEachRow(text, file, "ox,oy,oz,dx,dy,dz,tnear,tfar", 8,
             [&](const std::vector<std::string_view>& fields, std::size_t line) {
               float v[8];
               for (std::size_t i = 0; i < 8; ++i) {
                 v[i] = numberAt<float>(fields, i, file, line, kNames[i]);
                 const bool allowedInfinity = i == 7 && v[i] == INFINITY;
                 if (!std::isfinite(v[i]) && !allowedInfinity) {
                   throw InputError(file, line,
                                    std::string(kNames[i]) + " = " + quote(fields[i]) + " is not finite" +
                                        (i == 7 ? " (tfar may be inf)" : ""));
                 }
               }
               for (std::size_t i = 0; i < 6; ++i) {
                 if (std::abs(double(v[i])) > Profile::kMaxCoordinate) {
                   throw InputError(
                       file, line,
                       std::string(kNames[i]) + " = " + quote(fields[i]) +
                           " is beyond +-2^60 (1.15e18), the largest coordinate revolve traces and Embree accepts");
                 }
               }
               if (v[3] == 0.0f && v[4] == 0.0f && v[5] == 0.0f)
                 throw InputError(file, line, "direction (0, 0, 0) is zero");
               if (!(v[6] >= 0.0f))
                 throw InputError(file, line, "tnear = " + quote(fields[6]) + " is negative; need tnear >= 0");
               if (!(v[6] <= v[7])) {
                 throw InputError(file, line, "tnear = " + quote(fields[6]) + " exceeds tfar = " + quote(fields[7]));
               }
               rays.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], v[7]});
             });
  return rays;
}

std::vector<Ray> readRaysCsv(const std::string& path) {
  return parseRaysCsv(readTextFile(path, kMaxCsvFileBytes, "a CSV file"), path);
}

void writeHitsCsv(OutputStream& out, const std::vector<std::optional<Hit>>& hits) {
  out.write("hit,t,nx,ny,nz,u,v\n");
  for (const std::optional<Hit>& hit : hits) {
    if (!hit) {
      out.write("0,inf,0,0,0,0,0\n");
      continue;
    }
    out.print("1,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", hit->t, hit->normal.x, hit->normal.y, hit->normal.z, hit->u, hit->v);
  }
}

void writeHitsCsv(const std::string& path, const std::vector<std::optional<Hit>>& hits) {
  OutputSet outputs;
  outputs.add("", path);
  writeHitsCsv(outputs.stream(path), hits);
  outputs.commit();
}

}  // namespace revolve::io
