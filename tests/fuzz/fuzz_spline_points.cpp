// Fuzz target: spline points straight from bytes, so that the spline validator (counts, ranges,
// the axis rule, the conservative self-intersection check of the curve's monotone parts), the
// conversions of every kind, the exact curve kernel and Profile::fromCurve see every double.
//
// Byte 0: the kind (its value mod 5: linear, quadratic, bezier, catmull-rom, natural) and, in
// bits 4-5, the decoding of the rest:
//   0 raw:   16 bytes a point, two native-endian doubles r, z.
//   1 grid:  2 bytes a point, r = u8 / 16, z = i8 / 16: exact, so repeated points, points on the
//            axis, collinear controls, touches and cusps come up often.
//   2 nudged grid: 4 bytes a point, r = u8 / 16 + i8 * 2^-40, z = i8 / 16 + i8 * 2^-40: nearly so.
// Expected: a ProfileError with a one-line message naming a point of the input, or a spline whose
// shapes keep every query promise (fuzz_checks.h) and whose polyline within 1e-3 of its extent is
// a valid profile (Profile::fromCurve refines chords that would cross; Spline refuses curves that
// come within rounding of themselves, where no refinement could part the chords).
#include "fuzz_checks.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

using namespace revolve;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const auto kind = static_cast<SplineKind>((data[0] & 15) % 5);
  const int mode = (data[0] >> 4) & 3;
  std::vector<Point2> points;
  std::size_t at = 1;
  switch (mode) {
    case 0:
      for (; at + 16 <= size; at += 16) {
        double r, z;
        std::memcpy(&r, data + at, 8);
        std::memcpy(&z, data + at + 8, 8);
        points.push_back({r, z});
      }
      break;
    case 1:
      for (; at + 2 <= size; at += 2)
        points.push_back({data[at] / 16.0, static_cast<std::int8_t>(data[at + 1]) / 16.0});
      break;
    default:
      for (; at + 4 <= size; at += 4) {
        const auto i8 = [&](std::size_t k) { return double(static_cast<std::int8_t>(data[at + k])); };
        points.push_back({data[at] / 16.0 + std::ldexp(i8(2), -40), i8(1) / 16.0 + std::ldexp(i8(3), -40)});
      }
      break;
  }
  std::optional<Spline> spline;
  try {
    spline.emplace(kind, points);
  } catch (const ProfileError& error) {
    FUZZ_CHECK(points.empty() ? error.index() == 0 : error.index() < points.size());
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  std::mt19937_64 random = fuzz::generatorFor({data, size});
  fuzz::exerciseSplineShapes(*spline, random);
  double extent = 0;
  for (const Point2& p : spline->bezier()) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  // Profile::fromCurve refines chords that would cross, so for a curve Spline accepted it returns
  // a valid polyline: any exception escapes and is a finding.
  const Profile polyline = Profile::fromCurve(*spline, 1e-3 * extent);
  FUZZ_CHECK(polyline.points().size() >= 2);
  FUZZ_CHECK(polyline.points().front().r == spline->bezier().front().r);
  FUZZ_CHECK(polyline.points().back().z == spline->bezier().back().z);
  FUZZ_CHECK(spline->kind() == SplineKind::linear || polyline.curveParameters().size() == polyline.points().size());
  return 0;
}
