// The text files the applications read and write: profiles, rays and hits as CSV.
//
// Readers are strict: a bad line is an InputError naming the file, the line and the problem, never a
// guess. Writers go through a temporary file renamed into place, so an output is whole or absent.
#pragma once

#include "io/input_file.h"
#include "io/output_set.h"

#include <revolve/revolve.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

struct ProfileFile {
  std::vector<Point2> points;
  std::vector<std::size_t> lines;  // line of each point, for messages about points
};

// Profile CSV: an optional header `r,z`, then one point `r,z` per line (doubles). Blank lines are
// skipped. Only the syntax is checked here: the Profile constructor checks the geometry.
ProfileFile parseProfileCsv(std::string_view text, std::string_view file);
ProfileFile readProfileCsv(const std::string& path);

// Rays CSV: an optional header `ox,oy,oz,dx,dy,dz,tnear,tfar`, then one ray per line, read as
// 32-bit floats (each field rounded once, from its decimal text; beyond float's range that gives
// +-inf or, gradually, zero). Every value must be finite
// except tfar, which may be inf; the direction must be non-zero, and 0 <= tnear <= tfar. Origin
// and direction components lie within +-Profile::kMaxCoordinate (2^60, about 1.15e18), the range
// revolve traces and Embree accepts (its FLT_LARGE, 1.844e18, is the bound it asserts).
std::vector<Ray> parseRaysCsv(std::string_view text, std::string_view file);
std::vector<Ray> readRaysCsv(const std::string& path);

// Hits CSV: header `hit,t,nx,ny,nz,u,v`, one line per ray in order: `1,t,nx,ny,nz,u,v` (%.9g)
// or `0,inf,0,0,0,0,0` for a miss. Written into `out` (an output's stream), or alone to `path`.
void writeHitsCsv(OutputStream& out, const std::vector<std::optional<Hit>>& hits);
void writeHitsCsv(const std::string& path, const std::vector<std::optional<Hit>>& hits);

}  // namespace revolve::io
