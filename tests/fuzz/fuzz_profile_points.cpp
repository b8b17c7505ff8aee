// Fuzz target: profile points straight from bytes, past the CSV reader, so that the validator and
// the exact self-intersection sweep see every double (NaN, inf, subnormals, 1e308) and the
// degenerate configurations that random doubles almost never produce.
//
// Byte 0 picks the decoding (low 2 bits); the rest of it, through the shared generator, picks
// build options. Decodings:
//   0 raw:         16 bytes a point, two native-endian doubles r, z.
//   1 scaled grid: bytes 1-2 two int8 exponent codes for eR, eZ (code c gives 2^c for |c| < 100,
//                  where profiles are valid, and 2^(8c), up to the double range, beyond); then 2
//                  bytes a point, r = u8 * 2^eR, z = i8 * 2^eZ. Exact, so collinear overlaps,
//                  touches and shared vertices survive at any scale, and an exact brute force over
//                  the integers is the oracle for the sweep (which Profile's range limits skip).
//   2 nudged grid: 4 bytes a point: r = u8 + i8 * 2^-30, z = i8 + i8 * 2^-30: near-degenerate.
//   3 floats:      8 bytes a point, two native-endian floats (what a rays-style file could hold).
// Expected: ProfileError with a one-line message, or a profile whose shapes keep every query
// promise (fuzz_checks.h).
#include "fuzz_checks.h"

#include "profile/self_intersection.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

using namespace revolve;

namespace {

template <class T>
T load(const std::uint8_t* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

// ---------------------------------------------------------------------------------------------
// Exact brute force on integer points: whether segments i < j share a point they must not
// (rules of self_intersection.h). Coordinates are below 2^8, so every product fits in int64.

struct IntPoint {
  std::int64_t r, z;
  bool operator==(const IntPoint&) const = default;
};

std::int64_t cross(IntPoint o, IntPoint a, IntPoint b) { return (a.r - o.r) * (b.z - o.z) - (a.z - o.z) * (b.r - o.r); }

bool forbidden(const std::vector<IntPoint>& p, std::size_t i, std::size_t j) {
  const IntPoint a = p[i], b = p[i + 1], c = p[j], d = p[j + 1];
  const bool closed = p.front() == p.back();
  const bool neighbours = j == i + 1;
  const bool closingPair = closed && i == 0 && j == p.size() - 2;
  // The one point each allowed pair may share: the common vertex, or the closing point.
  const auto allowed = [&](std::int64_t rNum, std::int64_t zNum, std::int64_t den) {
    const auto is = [&](IntPoint q) { return rNum == q.r * den && zNum == q.z * den; };
    return (neighbours && is(b)) || (closingPair && is(a));
  };
  const std::int64_t d1 = cross(a, b, c), d2 = cross(a, b, d);
  const IntPoint ab{b.r - a.r, b.z - a.z}, cd{d.r - c.r, d.z - c.z};
  std::int64_t den = ab.r * cd.z - ab.z * cd.r;
  if (den != 0) {  // lines cross in one point: a + t (b - a), t = tNum / den
    std::int64_t tNum = (c.r - a.r) * cd.z - (c.z - a.z) * cd.r;
    std::int64_t uNum = (c.r - a.r) * ab.z - (c.z - a.z) * ab.r;
    if (den < 0) den = -den, tNum = -tNum, uNum = -uNum;
    if (tNum < 0 || tNum > den || uNum < 0 || uNum > den) return false;
    return !allowed(a.r * den + tNum * ab.r, a.z * den + tNum * ab.z, den);
  }
  if (d1 != 0 || d2 != 0) return false;  // parallel, apart
  // Collinear: overlap of the projections on an axis along which the line is not constant.
  const bool useR = ab.r != 0;
  const auto x = [&](IntPoint q) { return useR ? q.r : q.z; };
  const std::int64_t lo = std::max(std::min(x(a), x(b)), std::min(x(c), x(d)));
  const std::int64_t hi = std::min(std::max(x(a), x(b)), std::max(x(c), x(d)));
  if (lo > hi) return false;
  if (lo < hi) return true;  // a stretch in common: never allowed
  for (const IntPoint q : {a, b, c, d}) {
    if (x(q) == lo) return !allowed(q.r, q.z, 1);
  }
  return false;
}

// Compares the sweep with the brute force on the scaled grid (exact: every value is u8 or i8 times
// a power of two within the double range).
void checkSweepAgainstBruteForce(const std::vector<IntPoint>& grid, const std::vector<Point2>& points) {
  // Profile drops exactly repeated consecutive points before the sweep; do the same.
  std::vector<IntPoint> p;
  std::vector<Point2> q;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!p.empty() && p.back() == grid[i]) continue;
    p.push_back(grid[i]);
    q.push_back(points[i]);
  }
  if (p.size() < 2 || p.size() > 96) return;  // O(n^2): keep it cheap
  bool expected = false;
  for (std::size_t i = 0; i + 1 < p.size() && !expected; ++i) {
    for (std::size_t j = i + 1; j + 1 < p.size() && !expected; ++j) expected = forbidden(p, i, j);
  }
  const std::optional<detail::SegmentPair> found = detail::findSelfIntersection(q);
  FUZZ_CHECK(found.has_value() == expected);
  if (found) {
    FUZZ_CHECK(found->first < found->second && found->second + 1 < p.size());
    FUZZ_CHECK(forbidden(p, found->first, found->second));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int mode = data[0] & 3;
  std::vector<Point2> points;
  std::vector<IntPoint> grid;
  std::size_t at = 1;
  switch (mode) {
    case 0:
      for (; at + 16 <= size; at += 16) points.push_back({load<double>(data + at), load<double>(data + at + 8)});
      break;
    case 1: {
      if (size < 3) return 0;
      // Within [-1074, 1015], u8 * 2^e and i8 * 2^e are exact finite doubles (subnormal at worst).
      const auto exponent = [](std::uint8_t byte) {
        const int code = static_cast<std::int8_t>(byte);
        return std::clamp(std::abs(code) < 100 ? code : 8 * code, -1074, 1015);
      };
      const int eR = exponent(data[1]), eZ = exponent(data[2]);
      for (at = 3; at + 2 <= size; at += 2) {
        const IntPoint p{data[at], static_cast<std::int8_t>(data[at + 1])};
        grid.push_back(p);
        points.push_back({std::ldexp(double(p.r), eR), std::ldexp(double(p.z), eZ)});
      }
      break;
    }
    case 2:
      for (; at + 4 <= size; at += 4) {
        const auto i8 = [&](std::size_t k) { return double(static_cast<std::int8_t>(data[at + k])); };
        points.push_back({data[at] + std::ldexp(i8(2), -30), i8(1) + std::ldexp(i8(3), -30)});
      }
      break;
    default:
      for (; at + 8 <= size; at += 8) points.push_back({load<float>(data + at), load<float>(data + at + 4)});
      break;
  }

  if (mode == 1) checkSweepAgainstBruteForce(grid, points);

  std::optional<Profile> profile;
  try {
    profile.emplace(points);
  } catch (const ProfileError& error) {
    FUZZ_CHECK(points.empty() ? error.index() == 0 : error.index() < points.size());
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  for (const ProfileWarning& warning : profile->warnings()) {
    FUZZ_CHECK(warning.index < points.size());
    fuzz::checkOneLineMessage(warning.message);
  }
  std::mt19937_64 random = fuzz::generatorFor({data, size});
  fuzz::exerciseShapes(*profile, random);
  return 0;
}
