// revolve-trace as its users see it: a process given files and options, judged by its exit
// status, its stderr and the files it leaves. Answers come from geometry worked out by hand (a
// capped cylinder) or from the long-double oracle of tests/support, never from an earlier run.
//
// The contract under test:
//   revolve-trace --profile P.csv --rays R.csv --out H.csv [--method mibit|linear|kajiya|mesh]
//                 [--shell cylinder|cone|hybrid] [--subdivisions N] [--slices K]
//                 [--spline linear|quadratic|bezier|catmull-rom|natural] [--tolerance T]
// H.csv: header `hit,t,nx,ny,nz,u,v`, one line per ray in input order, `1,t,nx,ny,nz,u,v` or
// `0,inf,0,0,0,0,0`. Bad input: non-zero exit, one line on stderr naming file, line and problem,
// and no output file (an existing one is left untouched).
#include "support/reference.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"
#include "support/test_seeds.h"

#include "scratch_directory.h"
#include "support/process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using namespace std::string_literals;
using testing::readWholeFile;
using testing::ScratchDirectory;

constexpr double kPi = std::numbers::pi;

using Result = testing::ProcessResult;

Result runTrace(const std::vector<std::string>& args) { return testing::runProcess(REVOLVE_TRACE_PATH, args); }

std::size_t lineCount(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// ---------------------------------------------------------------------------------------------
// The hits file, read back.

struct HitLine {
  bool hit = false;
  double t = 0, nx = 0, ny = 0, nz = 0, u = 0, v = 0;
};

double toDouble(const std::string& field) {
  double value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  EXPECT_TRUE(error == std::errc() && end == field.data() + field.size()) << "not a number: \"" << field << "\"";
  return value;
}

// Parses H.csv, checking its syntax: the exact header, then 7 fields a line, the miss line verbatim.
std::vector<HitLine> readHits(const std::string& path) {
  std::istringstream in(readWholeFile(path));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "hit,t,nx,ny,nz,u,v");
  std::vector<HitLine> hits;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::istringstream split(line);
    for (std::string field; std::getline(split, field, ',');) fields.push_back(field);
    EXPECT_EQ(fields.size(), 7u) << line;
    if (fields.size() != 7) break;
    HitLine hit;
    if (fields[0] == "0") {
      EXPECT_EQ(line, "0,inf,0,0,0,0,0");
    } else {
      EXPECT_EQ(fields[0], "1") << line;
      hit = {true,
             toDouble(fields[1]),
             toDouble(fields[2]),
             toDouble(fields[3]),
             toDouble(fields[4]),
             toDouble(fields[5]),
             toDouble(fields[6])};
    }
    hits.push_back(hit);
  }
  return hits;
}

// u lives on a circle: 0.9999999 and 0 are neighbours.
double uDistance(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, 1.0 - d);
}

std::string numberText(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}
std::string numberText(float value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string profileCsv(const std::vector<Point2>& points) {
  std::string text = "r,z\n";
  for (const Point2& p : points) text += numberText(p.r) + "," + numberText(p.z) + "\n";
  return text;
}

// Shortest round-trip text: the tool reads back exactly the floats written.
std::string raysCsv(const std::vector<Ray>& rays) {
  std::string text = "ox,oy,oz,dx,dy,dz,tnear,tfar\n";
  for (const Ray& r : rays) {
    const float fields[] = {r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z, r.tnear};
    for (const float value : fields) text += numberText(value) + ",";
    text += std::isinf(r.tfar) ? std::string("inf") : numberText(r.tfar);
    text += "\n";
  }
  return text;
}

// ---------------------------------------------------------------------------------------------
// The capped cylinder r = 1, 0 <= z <= 2, and rays whose answers follow from its geometry.

// Listed bottom to top: bottom disc (segment 0, axis to rim), wall (segment 1), top disc
// (segment 2, rim to axis). Arc lengths at the points: 0, 1, 3, 4; v = arc / 4.
// Normals point right of the direction of travel in (r, z): (dz, -dr) / length, so the bottom disc
// faces -z, the wall +r, the top disc +z: outwards everywhere.
constexpr const char* kCylinderCsv = "r,z\n0,0\n1,0\n1,2\n0,2\n";
constexpr double kCylinderRadius = 1.0;

struct Case {
  const char* ray;  // CSV line
  bool hit;
  double t, nx, ny, nz, u, v;
  bool tAtLimit = false;  // the exact t equals tnear or tfar: the mesh may fall either side
};

// u = atan2(y, x) / 2pi of the hit point, wrapped to [0, 1).
const std::vector<Case> kCylinderCases = {
    // From x = -5 along +x at z = 1: enters the wall at (-1, 0, 1), t = 4. Normal -x;
    // u = atan2(0, -1) / 2pi = 0.5; v = (1 + 1) / 4 (one unit of bottom disc, one up the wall).
    {"-5,0,1,1,0,0,0,inf", true, 4, -1, 0, 0, 0.5, 0.5},
    // The same with |d| = 2: t is in units of d, so 4 / 2.
    {"-5,0,1,2,0,0,0,inf", true, 2, -1, 0, 0, 0.5, 0.5},
    // Down onto the top disc at (0.5, 0, 2): t = 5 - 2 = 3, normal +z; u = 0; the top segment runs
    // from r = 1 (arc 3) to r = 0 (arc 4), so r = 0.5 is arc 3.5: v = 3.5 / 4.
    {"0.5,0,5,0,0,-1,0,inf", true, 3, 0, 0, 1, 0.0, 0.875},
    // Up onto the bottom disc at (0, 0.5, 0): t = 3, normal -z; u = atan2(0.5, 0) / 2pi = 0.25;
    // arc 0.5 along the bottom segment: v = 0.5 / 4.
    {"0,0.5,-3,0,0,1,0,inf", true, 3, 0, 0, -1, 0.25, 0.125},
    // Passes over the top (z = 3 > 2): a miss.
    {"-5,0,3,1,0,0,0,inf", false, 0, 0, 0, 0, 0, 0},
    // From inside the solid along +y: leaves through the wall at (0, 1, 1), t = 1. The normal is
    // the outward +y, not flipped towards the ray. u = 0.25, v = 0.5.
    {"0,0,1,0,1,0,0,inf", true, 1, 0, 1, 0, 0.25, 0.5},
    // Radially inwards from (3, 4, 1) along (-3, -4, 0): |o_xy| = 5, so the wall (radius 1) is
    // reached at t = 4 / 5 = 0.8, at (0.6, 0.8, 1) with normal (0.6, 0.8, 0);
    // u = atan2(4, 3) / 2pi = 0.9272952180 / 6.2831853072 = 0.1475836177.
    {"3,4,1,-3,-4,0,0,inf", true, 0.8, 0.6, 0.8, 0, 0.1475836177, 0.5},
    // Down the axis: the top disc's centre (0, 0, 2) at t = 8; on the axis phi = atan2(0, 0) = 0;
    // r = 0 is the top segment's end, arc 4: v = 1.
    {"0,0,10,0,0,-1,0,inf", true, 8, 0, 0, 1, 0.0, 1.0},
    // The first ray again with limits. Its hits are t = 4 (entry) and t = 6 (exit at (1, 0, 1),
    // normal +x, u = 0, v = 0.5).
    {"-5,0,1,1,0,0,0,3.9", false, 0, 0, 0, 0, 0, 0},          // both hits beyond tfar
    {"-5,0,1,1,0,0,0,4", true, 4, -1, 0, 0, 0.5, 0.5, true},  // tfar is inclusive
    {"-5,0,1,1,0,0,4,4", true, 4, -1, 0, 0, 0.5, 0.5, true},  // so is tnear: [4, 4] holds t = 4
    {"-5,0,1,1,0,0,4.5,inf", true, 6, 1, 0, 0, 0.0, 0.5},     // the entry is before tnear
    {"-5,0,1,1,0,0,4.5,5.9", false, 0, 0, 0, 0, 0, 0},        // neither hit inside [4.5, 5.9]
    {"-5,0,1,1,0,0,6.5,inf", false, 0, 0, 0, 0, 0, 0},        // both hits before tnear
};

std::string casesCsv() {
  std::string text = "ox,oy,oz,dx,dy,dz,tnear,tfar\n";
  for (const Case& c : kCylinderCases) text += std::string(c.ray) + "\n";
  return text;
}

class TraceCliTest : public ::testing::Test {
 protected:
  std::string profilePath() const { return directory / "p.csv"; }
  std::string raysPath() const { return directory / "r.csv"; }
  std::string outPath() const { return directory / "h.csv"; }

  // Traces the cylinder cases with `options`; expects success with no message.
  std::vector<HitLine> traceCylinder(const std::vector<std::string>& options) {
    directory.write("p.csv", kCylinderCsv);
    directory.write("r.csv", casesCsv());
    std::vector<std::string> args{"--profile", profilePath(), "--rays", raysPath(), "--out", outPath()};
    args.insert(args.end(), options.begin(), options.end());
    const Result result = runTrace(args);
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.err, "");
    const std::vector<HitLine> hits = readHits(outPath());
    EXPECT_EQ(hits.size(), kCylinderCases.size());  // one line per ray
    return hits;
  }

  ScratchDirectory directory;
};

// ---------------------------------------------------------------------------------------------
// Exact methods: the closed-form answers, to float precision, for every method and option.

class ExactMethodTest : public TraceCliTest, public ::testing::WithParamInterface<std::vector<std::string>> {};

TEST_P(ExactMethodTest, CylinderAnswersMatchTheGeometry) {
  const std::vector<HitLine> hits = traceCylinder(GetParam());
  for (std::size_t i = 0; i < std::min(hits.size(), kCylinderCases.size()); ++i) {
    const Case& expected = kCylinderCases[i];
    const HitLine& hit = hits[i];
    SCOPED_TRACE(std::string("ray ") + expected.ray);
    ASSERT_EQ(hit.hit, expected.hit);
    if (!hit.hit) continue;
    // Float output of double work: a few float ulps.
    constexpr double kTolerance = 1e-6;
    EXPECT_NEAR(hit.t, expected.t, kTolerance * expected.t);
    EXPECT_NEAR(hit.nx, expected.nx, kTolerance);
    EXPECT_NEAR(hit.ny, expected.ny, kTolerance);
    EXPECT_NEAR(hit.nz, expected.nz, kTolerance);
    EXPECT_LT(uDistance(hit.u, expected.u), kTolerance) << "u = " << hit.u;
    EXPECT_NEAR(hit.v, expected.v, kTolerance);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Options, ExactMethodTest,
    ::testing::Values(std::vector<std::string>{}, std::vector<std::string>{"--method", "mibit"},
                      std::vector<std::string>{"--method", "linear"}, std::vector<std::string>{"--method", "kajiya"},
                      std::vector<std::string>{"--method", "mibit", "--shell", "cylinder"},
                      std::vector<std::string>{"--shell", "cone"}, std::vector<std::string>{"--shell", "hybrid"},
                      std::vector<std::string>{"--subdivisions", "2"},
                      std::vector<std::string>{"--method", "mibit", "--shell", "cone", "--subdivisions", "1"}),
    [](const ::testing::TestParamInfo<std::vector<std::string>>& info) {
      std::string name = std::to_string(info.index);  // then the option values, e.g. 2_linear
      for (const std::string& arg : info.param) {
        if (!arg.starts_with("--")) name += "_" + arg;
      }
      return info.param.empty() ? name + "_defaults" : name;
    });

// ---------------------------------------------------------------------------------------------
// The tessellated mesh: same hits and misses, within the tessellation error.

// A mesh of K slices has its vertices on the exact circles at phi = 2 pi j / K; between two of them
// the chord's midpoint is nearest the axis, at r cos(pi / K): no point of the mesh is farther than
// r_max (1 - cos(pi / K)) from the surface. Facet normals lean by at most pi / K from the exact ones.
double meshError(double rMax, int slices) { return rMax * (1.0 - std::cos(kPi / slices)); }

class MeshMethodTest : public TraceCliTest, public ::testing::WithParamInterface<int> {};

TEST_P(MeshMethodTest, CylinderHitsLieWithinTheTessellationError) {
  const int slices = GetParam();
  std::vector<std::string> options{"--method", "mesh"};
  if (slices != 64) options.insert(options.end(), {"--slices", std::to_string(slices)});  // 64: the default
  const std::vector<HitLine> hits = traceCylinder(options);
  const double error = meshError(kCylinderRadius, slices);
  std::vector<Point2> cylinder = testing::cappedCylinder(kCylinderRadius, 0, 2);
  for (std::size_t i = 0; i < std::min(hits.size(), kCylinderCases.size()); ++i) {
    const Case& expected = kCylinderCases[i];
    if (expected.tAtLimit) continue;
    const HitLine& hit = hits[i];
    SCOPED_TRACE(std::string("ray ") + expected.ray);
    ASSERT_EQ(hit.hit, expected.hit);
    if (!hit.hit) continue;
    float o[3], d[3];
    std::sscanf(expected.ray, "%f,%f,%f,%f,%f,%f", &o[0], &o[1], &o[2], &d[0], &d[1], &d[2]);
    const long double x = o[0] + hit.t * d[0], y = o[1] + hit.t * d[1], z = o[2] + hit.t * d[2];
    // Small extra allowance for float vertices and a float t.
    EXPECT_LE(reference::meridianDistance(cylinder, x, y, z), error + 1e-5);
    const double cosine = hit.nx * expected.nx + hit.ny * expected.ny + hit.nz * expected.nz;
    EXPECT_GE(cosine, std::cos(kPi / slices) - 1e-6) << "normal (" << hit.nx << ", " << hit.ny << ", " << hit.nz << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(Slices, MeshMethodTest, ::testing::Values(8, 64));

TEST_F(TraceCliTest, SlicesSetTheMeshResolution) {
  // A radial ray at phi = 9 pi / 8 from distance 5. With 8 slices (vertices every pi / 4) it meets
  // the middle of the chord from pi to 5 pi / 4, at r = cos(pi / 8): t = 5 - cos(pi / 8) = 4.0761205.
  // With 16 slices phi = 9 pi / 8 is a vertex column (j = 9) on the exact circle: t = 4.
  const float c = float(std::cos(9 * kPi / 8)), s = float(std::sin(9 * kPi / 8));
  directory.write("p.csv", kCylinderCsv);
  directory.write("r.csv", raysCsv({Ray{{5 * c, 5 * s, 1}, {-c, -s, 0}}}));
  for (const auto& [slices, t] : {std::pair{8, 5 - std::cos(kPi / 8)}, std::pair{16, 4.0}}) {
    SCOPED_TRACE("slices " + std::to_string(slices));
    const Result result = runTrace({"--profile", profilePath(), "--rays", raysPath(), "--out", outPath(), "--method",
                                    "mesh", "--slices", std::to_string(slices)});
    ASSERT_EQ(result.status, 0) << result.err;
    // The summary line: counts, the profile and the method.
    EXPECT_THAT(result.out, ::testing::StartsWith("revolve-trace: 1 ray, 1 hit; "));
    EXPECT_THAT(result.out, ::testing::HasSubstr("(mesh, " + std::to_string(slices) + " slices)"));
    const std::vector<HitLine> hits = readHits(outPath());
    ASSERT_EQ(hits.size(), 1u);
    ASSERT_TRUE(hits[0].hit);
    EXPECT_NEAR(hits[0].t, t, 1e-5);  // float origin and direction
  }
}

// ---------------------------------------------------------------------------------------------
// Random rays against the long-double oracle: one line per ray, in input order, for each method.

// Whether the oracle's answer is stable: moving the ray sideways by `delta` keeps hit or miss and
// the segment, the hit is not grazing, and no hit lies within `delta` of tnear or tfar. Only then
// must a float implementation agree with it.
bool robust(std::span<const Point2> profile, const reference::RefRay& ray,
            const std::optional<reference::RefHit>& hit) {
  constexpr long double kDelta = 1e-4L;
  const long double length = std::sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
  // Two unit vectors perpendicular to the direction.
  long double ax = 0, ay = 0, az = 0;
  (std::abs(ray.dx) < std::abs(ray.dy) ? ax : ay) = 1;
  long double px = ay * ray.dz - az * ray.dy, py = az * ray.dx - ax * ray.dz, pz = ax * ray.dy - ay * ray.dx;
  const long double pn = std::sqrt(px * px + py * py + pz * pz);
  px /= pn, py /= pn, pz /= pn;
  const long double qx = (ray.dy * pz - ray.dz * py) / length, qy = (ray.dz * px - ray.dx * pz) / length,
                    qz = (ray.dx * py - ray.dy * px) / length;
  for (const auto& [sx, sy, sz] :
       {std::tuple{px, py, pz}, std::tuple{-px, -py, -pz}, std::tuple{qx, qy, qz}, std::tuple{-qx, -qy, -qz}}) {
    reference::RefRay moved = ray;
    moved.ox += kDelta * sx, moved.oy += kDelta * sy, moved.oz += kDelta * sz;
    const std::optional<reference::RefHit> other = reference::intersectProfile(profile, moved);
    if (other.has_value() != hit.has_value() || (hit && other->segment != hit->segment)) return false;
  }
  if (hit) {
    const long double cosine = (ray.dx * hit->nx + ray.dy * hit->ny + ray.dz * hit->nz) / length;
    if (std::abs(cosine) < 1e-2L) return false;
  }
  reference::RefRay unlimited = ray;
  unlimited.tnear = 0, unlimited.tfar = INFINITY;
  for (const reference::RefHit& h : reference::allHits(profile, unlimited)) {
    if (std::abs(h.t - ray.tnear) * length < kDelta || std::abs(h.t - ray.tfar) * length < kDelta) return false;
  }
  return true;
}

// The oracle's u and v for its hit, by the conventions of revolve.h.
std::pair<double, double> expectedUv(std::span<const Point2> profile, const reference::RefRay& ray,
                                     const reference::RefHit& hit) {
  const long double x = ray.ox + hit.t * ray.dx, y = ray.oy + hit.t * ray.dy, z = ray.oz + hit.t * ray.dz;
  double u = double(std::atan2(y, x) / (2 * kPi));
  if (u < 0) u += 1;
  std::vector<double> arc{0.0};
  for (std::size_t i = 1; i < profile.size(); ++i) {
    arc.push_back(arc.back() + std::hypot(profile[i].r - profile[i - 1].r, profile[i].z - profile[i - 1].z));
  }
  const Point2 a = profile[hit.segment], b = profile[hit.segment + 1];
  const double along = std::clamp(double(((std::hypot(x, y) - a.r) * (b.r - a.r) + (z - a.z) * (b.z - a.z)) /
                                         ((b.r - a.r) * (b.r - a.r) + (b.z - a.z) * (b.z - a.z))),
                                  0.0, 1.0);
  return {u, (arc[hit.segment] + along * (arc[hit.segment + 1] - arc[hit.segment])) / arc.back()};
}

TEST_F(TraceCliTest, RandomRaysMatchTheOracleLineByLine) {
  // Eight fixed seeds (support/test_seeds.h): 3,200 rays, each through every method.
  for (const std::uint64_t seed : testing::testSeeds({1, 2, 3, 4, 5, 6, 7, 8})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);

    // The hollow vase: non-monotone in z, inner and outer walls, so rays hit many segments.
    const std::vector<Point2> vase = testing::hollowVase();
    const Shape shape{Profile(vase)};  // only for its bounds, to aim the rays
    std::vector<Ray> rays = testing::incoherentRays(shape, random, 400);
    // A quarter get a window [tnear, tfar] inside [0, 2], where their hits lie: each ray is aimed at a
    // point of the shape's box reached at t = 1 / scale, scale in [0.5, 2].
    for (std::size_t i = 0; i < rays.size(); i += 4) {
      std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
      const float a = fraction(random) * 2.0f, b = fraction(random) * 2.0f;
      rays[i].tnear = std::min(a, b);
      rays[i].tfar = std::max(a, b);
    }
    directory.write("p.csv", profileCsv(vase));
    directory.write("r.csv", raysCsv(rays));

    std::vector<std::optional<reference::RefHit>> expected;
    std::vector<bool> isRobust;
    std::size_t robustCount = 0, robustHits = 0;
    for (const Ray& r : rays) {
      const reference::RefRay ray{r.origin.x,    r.origin.y,    r.origin.z, r.direction.x,
                                  r.direction.y, r.direction.z, r.tnear,    r.tfar};
      expected.push_back(reference::intersectProfile(vase, ray));
      isRobust.push_back(robust(vase, ray, expected.back()));
      robustCount += isRobust.back();
      robustHits += isRobust.back() && expected.back().has_value();
    }
    std::printf("seed %llu: %zu of %zu rays robust, %zu of them hits\n", static_cast<unsigned long long>(seed),
                robustCount, rays.size(), robustHits);
    // Otherwise the test would check next to nothing.
    ASSERT_GT(robustCount, rays.size() * 8 / 10);
    ASSERT_GT(robustHits, rays.size() / 4);
    ASSERT_LT(robustHits, robustCount);  // some misses too

    double rMax = 0;
    for (const Point2& p : vase) rMax = std::max(rMax, p.r);
    for (const char* method : {"mibit", "linear", "kajiya", "mesh"}) {
      SCOPED_TRACE(std::string("--method ") + method);
      const Result result =
          runTrace({"--profile", profilePath(), "--rays", raysPath(), "--out", outPath(), "--method", method});
      ASSERT_EQ(result.status, 0) << result.err;
      const std::vector<HitLine> hits = readHits(outPath());
      ASSERT_EQ(hits.size(), rays.size());
      const bool mesh = method == std::string("mesh");
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        const HitLine& hit = hits[i];
        const long double length = std::hypot(r.direction.x, r.direction.y, r.direction.z);
        if (mesh) {
          // Every mesh hit is a point of the mesh, within the tessellation error of the surface.
          if (!hit.hit) continue;
          const long double x = r.origin.x + hit.t * r.direction.x, y = r.origin.y + hit.t * r.direction.y,
                            z = r.origin.z + hit.t * r.direction.z;
          EXPECT_LE(reference::meridianDistance(vase, x, y, z), meshError(rMax, 64) + 1e-5) << "ray " << i;
          EXPECT_GE(hit.t, r.tnear) << "ray " << i;
          EXPECT_LE(hit.t, r.tfar) << "ray " << i;
          continue;
        }
        if (!isRobust[i]) continue;
        const std::optional<reference::RefHit>& want = expected[i];
        ASSERT_EQ(hit.hit, want.has_value()) << "ray " << i;
        if (!want) continue;
        // Distances along the ray to 1e-4 (the robustness margin); normals and u, v likewise.
        EXPECT_NEAR(hit.t * length, double(want->t * length), 1e-4) << "ray " << i;
        EXPECT_NEAR(hit.nx, double(want->nx), 1e-4) << "ray " << i;
        EXPECT_NEAR(hit.ny, double(want->ny), 1e-4) << "ray " << i;
        EXPECT_NEAR(hit.nz, double(want->nz), 1e-4) << "ray " << i;
        const reference::RefRay ray{r.origin.x,    r.origin.y,    r.origin.z, r.direction.x,
                                    r.direction.y, r.direction.z, r.tnear,    r.tfar};
        const auto [u, v] = expectedUv(vase, ray, *want);
        EXPECT_LT(uDistance(hit.u, u), 1e-4) << "ray " << i << ": u = " << hit.u << ", expected " << u;
        EXPECT_NEAR(hit.v, v, 1e-4) << "ray " << i;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Successful runs: the files they leave and what they print.

TEST_F(TraceCliTest, EmptyRaysFileGivesTheHeaderAlone) {
  directory.write("p.csv", kCylinderCsv);
  directory.write("r.csv", "");
  const Result result = runTrace({"--profile", profilePath(), "--rays", raysPath(), "--out", outPath()});
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(readWholeFile(outPath()), "hit,t,nx,ny,nz,u,v\n");
}

TEST_F(TraceCliTest, SuccessReplacesAnExistingOutputWhole) {
  directory.write("p.csv", kCylinderCsv);
  directory.write("r.csv", "-5,0,3,1,0,0,0,inf\n");  // passes over the top: a miss
  directory.write("h.csv", std::string(10000, 'x') + "\n");
  const Result result = runTrace({"--profile", profilePath(), "--rays", raysPath(), "--out", outPath()});
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(readWholeFile(outPath()), "hit,t,nx,ny,nz,u,v\n0,inf,0,0,0,0,0\n");
  EXPECT_THAT(directory.entries(), ::testing::ElementsAre("h.csv", "p.csv", "r.csv"));  // no temporary left
}

TEST_F(TraceCliTest, RepeatedProfilePointIsAWarningWithFileAndLine) {
  // Line 4 repeats line 3's (1, 0); dropping it leaves the capped cylinder, arc lengths unchanged.
  directory.write("p.csv", "r,z\n0,0\n1,0\n1,0\n1,2\n0,2\n");
  directory.write("r.csv", "-5,0,1,1,0,0,0,inf\n");
  const Result result = runTrace({"--profile", profilePath(), "--rays", raysPath(), "--out", outPath()});
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_THAT(result.err, StartsWith(profilePath() + ":4: warning: "));
  const std::vector<HitLine> hits = readHits(outPath());
  ASSERT_EQ(hits.size(), 1u);
  ASSERT_TRUE(hits[0].hit);
  EXPECT_NEAR(hits[0].t, 4, 1e-6);  // as for the first cylinder case
  EXPECT_NEAR(hits[0].v, 0.5, 1e-6);
}

TEST_F(TraceCliTest, SplinesAreTracedExactlyOrWithinTheirTolerance) {
  // A sphere of radius 0.5 as four cubic arcs (each within arcError outside the sphere), rays from 3
  // towards its centre: exact hits lie between the sphere and its offset, with radial normals;
  // with --tolerance the polyline lies within the tolerance inside the curve.
  const double radius = 0.5, error = testing::arcError(radius, kPi / 4);
  std::string csv = "r,z\n";
  for (const Point2& p : testing::bezierSphere(radius, 4)) {
    char line[96];
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", p.r, p.z);
    csv += line;
  }
  directory.write("p.csv", csv);
  std::string rays;
  std::vector<std::array<double, 3>> directions;
  std::mt19937_64 random(7);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 200; ++i) {
    const double x = gauss(random), y = gauss(random), z = gauss(random), n = std::sqrt(x * x + y * y + z * z);
    directions.push_back({x / n, y / n, z / n});
    rays += std::to_string(3 * x / n) + "," + std::to_string(3 * y / n) + "," + std::to_string(3 * z / n) + "," +
            std::to_string(-x / n) + "," + std::to_string(-y / n) + "," + std::to_string(-z / n) + ",0,inf\n";
  }
  directory.write("r.csv", rays);
  for (const double tolerance : {0.0, 1e-3}) {
    std::vector<std::string> args{"--profile", profilePath(), "--rays",   raysPath(),
                                  "--out",     outPath(),     "--spline", "bezier"};
    if (tolerance > 0) args.insert(args.end(), {"--tolerance", "0.001"});
    const Result result = runTrace(args);
    ASSERT_EQ(result.status, 0) << result.err;
    // The summary names what was traced: the curve's own 13 points, or its polyline's.
    if (tolerance == 0) {
      EXPECT_THAT(result.out, HasSubstr("; a bezier spline of 13 points (mibit, exactly) traced in "));
    } else {
      EXPECT_THAT(result.out, ::testing::ContainsRegex("; [0-9]+ polyline points \\(mibit\\) traced in "));
    }
    const std::vector<HitLine> hits = readHits(outPath());
    ASSERT_EQ(hits.size(), directions.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
      ASSERT_TRUE(hits[i].hit);
      // The ray's origin is printed with 6 decimals: 3 +- 1e-6 from the centre.
      EXPECT_GE(hits[i].t, 3 - radius - error - 2e-6);
      EXPECT_LE(hits[i].t, 3 - radius + tolerance + 2e-6);
      if (tolerance == 0) {
        const auto& d = directions[i];
        EXPECT_NEAR(hits[i].nx * d[0] + hits[i].ny * d[1] + hits[i].nz * d[2], 1.0, 1e-5);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Bad input: non-zero status, one line naming file, line and problem, no output file.

constexpr const char* kAbsent =
    "\x01"
    "absent";  // a file the case does not create
constexpr const char* kGoodRays = "-5,0,1,1,0,0,0,inf\n";

struct BadInput {
  const char* name;
  std::string profile = kCylinderCsv;  // contents of p.csv, or kAbsent
  std::string rays = kGoodRays;        // contents of r.csv, or kAbsent
  // Arguments after the three file options; "@" stands for the scratch directory. For cases that
  // replace a file option, `replaceFiles` drops the defaults.
  std::vector<std::string> args = {};
  // Substrings of stderr, "@" as above.
  std::vector<std::string> message = {};
  bool usageError = false;     // an option error, which points to --help
  bool outputCanExist = true;  // whether a pre-existing output file can be set up
  bool replaceFiles = false;
};

std::string substitute(std::string text, const std::string& directory) {
  for (std::size_t at; (at = text.find('@')) != std::string::npos;) text.replace(at, 1, directory);
  return text;
}

std::ostream& operator<<(std::ostream& out, const BadInput& input) { return out << input.name; }

const char* const kSelfIntersecting =
    // Lines 2, 4, 5, 6, 7 hold points 0 to 4. Segment 1 (1,0)-(1,2) and segment 3 (2,1)-(0.5,1)
    // cross at (1, 1); no other pair meets, so the error is about point 1, on line 4.
    "r,z\n1,-1\n\n1,0\n1,2\n2,1\n0.5,1\n";

const std::vector<BadInput> kBadInputs = {
    {.name = "MissingProfile", .profile = kAbsent, .message = {"@/p.csv: ", "No such file or directory"}},
    {.name = "MissingRays", .rays = kAbsent, .message = {"@/r.csv: ", "No such file or directory"}},
    {.name = "ProfileBeneathARegularFile",
     .args = {"--profile", "@/r.csv/p.csv", "--rays", "@/r.csv", "--out", "@/h.csv"},
     .message = {"@/r.csv/p.csv: ", "Not a directory"},
     .replaceFiles = true},
    {.name = "GarbageProfile",
     .profile = "\x7f"
                "ELF\x02\x01\x01\0\0\0,\x03\n\xff\xfe"s,
     .message = {"@/p.csv:1: ", "header"}},
    {.name = "GarbageRays", .rays = "PK\x03\x04\x14\0\x08\0\x08\0\n"s, .message = {"@/r.csv:1: ", "header"}},
    {.name = "SelfIntersectingProfile", .profile = kSelfIntersecting, .message = {"@/p.csv:4: ", "intersect"}},
    // Point 2, on line 5 (after the header and a blank line 3), has r = -0.5.
    {.name = "NegativeRadius", .profile = "r,z\n0,0\n\n1,0\n-0.5,2\n", .message = {"@/p.csv:5: ", "r = -0.5", ">= 0"}},
    {.name = "NonFiniteProfilePoint", .profile = "0,0\n1,0\n1,nan\n", .message = {"@/p.csv:3: ", "finite"}},
    // Point 1, on line 3, lies beyond Profile::kMaxCoordinate (2^60).
    {.name = "CoordinateOutOfRange", .profile = "r,z\n0,0\n1e300,1\n", .message = {"@/p.csv:3: ", "1e+300"}},
    // One point: the message is about the only point, on line 2.
    {.name = "SinglePointProfile", .profile = "r,z\n1,1\n", .message = {"@/p.csv:2: ", "at least 2"}},
    {.name = "ProfileWithoutPoints", .profile = "r,z\n\n", .message = {"@/p.csv: ", "no profile points"}},
    {.name = "EmptyProfile", .profile = "", .message = {"@/p.csv: ", "no profile points"}},
    {.name = "TnearAboveTfar",
     .rays = std::string(kGoodRays) + "\n0,0,0,1,0,0,2,1\n",
     .message = {"@/r.csv:3: ", "tnear = \"2\"", "tfar = \"1\""}},
    {.name = "RayWithSevenFields", .rays = "0,0,0,1,0,0,0\n", .message = {"@/r.csv:1: ", "expected 8", "found 7"}},
    {.name = "ZeroDirection",
     .rays = "ox,oy,oz,dx,dy,dz,tnear,tfar\n0,0,0,0,0,0,0,1\n",
     .message = {"@/r.csv:2: ", "direction"}},
    {.name = "NanInRay", .rays = std::string(kGoodRays) + "0,nan,0,1,0,0,0,1\n", .message = {"@/r.csv:2: ", "oy"}},
    {.name = "OutputDirectoryMissing",
     .args = {"--profile", "@/p.csv", "--rays", "@/r.csv", "--out", "@/no/such/h.csv"},
     .message = {"@/no/such/h.csv: ", "No such file or directory"},
     .outputCanExist = false,
     .replaceFiles = true},
    {.name = "MethodNotAnOption", .args = {"--method", "exact"}, .message = {"--method"}, .usageError = true},
    {.name = "ShellNotAnOption", .args = {"--shell", "sphere"}, .message = {"--shell"}, .usageError = true},
    {.name = "TooFewSlices",
     .args = {"--slices", "2"},
     .message = {"--slices: 2 is out of range: it must lie in [3, 16777216]"},
     .usageError = true},
    {.name = "SubdivisionsNotANumber",
     .args = {"--subdivisions", "two"},
     .message = {"--subdivisions"},
     .usageError = true},
    {.name = "NegativeSubdivisions",
     .args = {"--subdivisions", "-1"},
     .message = {"--subdivisions"},
     .usageError = true},
    {.name = "UnknownOption", .args = {"--bogus", "1"}, .message = {"--bogus"}, .usageError = true},
    {.name = "SplineNotAnOption", .args = {"--spline", "cubic"}, .message = {"--spline"}, .usageError = true},
    // --tolerance is read as revolve-render reads it (io/curve_tolerance.h): the value as
    // written, and the rule, in a sentence.
    {.name = "ToleranceNotPositive",
     .args = {"--spline", "natural", "--tolerance", "0"},
     .message = {"--tolerance: \"0\" is out of range: a polyline tolerance is a finite number > 0 (the polyline's "
                 "largest distance from the curve"},
     .usageError = true},
    {.name = "ToleranceNegative",
     .args = {"--spline", "natural", "--tolerance", "-1"},
     .message = {"--tolerance: \"-1\" is out of range: a polyline tolerance is a finite number > 0"},
     .usageError = true},
    {.name = "ToleranceNotANumber",
     .args = {"--spline", "natural", "--tolerance", "nan"},
     .message = {"--tolerance: \"nan\" is out of range: a polyline tolerance is a finite number > 0"},
     .usageError = true},
    {.name = "ToleranceInfinite",
     .args = {"--spline", "natural", "--tolerance", "inf"},
     .message = {"--tolerance: \"inf\" is out of range: a polyline tolerance is a finite number > 0"},
     .usageError = true},
    {.name = "ToleranceText",
     .args = {"--spline", "natural", "--tolerance", "abc"},
     .message = {"--tolerance: \"abc\" is not a number: a polyline tolerance is a finite number > 0"},
     .usageError = true},
    {.name = "ToleranceEmpty",
     .args = {"--spline", "natural", "--tolerance", ""},
     .message = {"--tolerance: \"\" is not a number: a polyline tolerance is a finite number > 0"},
     .usageError = true},
    {.name = "ToleranceForAPolyline", .args = {"--tolerance", "0.01"}, .message = {"--tolerance", "curved --spline"}},
    // Five points cannot make cubic Bezier pieces sharing their ends: the last point, line 6.
    {.name = "BezierPointCount",
     .profile = "r,z\n0,0\n1,0\n1,1\n1,2\n0,2\n",
     .args = {"--spline", "bezier"},
     .message = {"@/p.csv:6: ", "3n + 1"}},
    // Points 1 and 2 (lines 3 and 4) of a natural spline are equal: the chord between has no length.
    {.name = "NaturalSplineRepeatedPoint",
     .profile = "r,z\n0,0\n1,0\n1,0\n0,1\n",
     .args = {"--spline", "natural"},
     .message = {"@/p.csv:4: ", "repeats point 1"}},
    // One Bezier piece from the axis to the axis, reaching r = 0.375: within 2 its polyline is the
    // chord on the axis, which nothing hits.
    {.name = "ToleranceCollapsingTheCurve",
     .profile = "r,z\n0,0\n0.5,0.2\n0.5,0.8\n0,1\n",
     .args = {"--spline", "bezier", "--tolerance", "2"},
     .message = {"--tolerance: polyline tolerance 2 collapses the bezier spline onto the axis", "r = 0.375"}},
    {.name = "ToleranceBelowTheCurvesResolution",
     .args = {"--spline", "catmull-rom", "--tolerance", "1e-30"},
     .message = {"--tolerance", "2^-40"}},
    {.name = "KajiyaForACurve",
     .args = {"--spline", "natural", "--method", "kajiya"},
     .message = {"--method kajiya: Kajiya's strip tree bounds polylines only",
                 "--method mibit or linear, or --tolerance"}},
    // r = (1 - 2u)^2 on the middle piece (points 2 to 4, lines 4 to 6): it touches the axis at u = 1/2,
    // between the points the curve passes through.
    {.name = "QuadraticTouchingTheAxisBetweenItsPoints",
     .profile = "r,z\n0,0\n0.5,0\n1,0\n-1,0.5\n1,1\n0.5,1\n0,1\n",
     .args = {"--spline", "quadratic"},
     .message = {"@/p.csv:4: ", "touches the axis", "at u = 0.5"}},
    {.name = "OutOptionMissing",
     .args = {"--profile", "@/p.csv", "--rays", "@/r.csv"},
     .message = {"--out"},
     .usageError = true,
     .replaceFiles = true},
};

class BadInputTest : public TraceCliTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(BadInputTest, FailsWithOneLineAndWritesNothing) {
  const BadInput& input = GetParam();
  const std::string root = directory.path().string();
  if (input.profile != kAbsent) directory.write("p.csv", input.profile);
  if (input.rays != kAbsent) directory.write("r.csv", input.rays);
  std::vector<std::string> args;
  if (!input.replaceFiles) args = {"--profile", profilePath(), "--rays", raysPath(), "--out", outPath()};
  for (const std::string& arg : input.args) args.push_back(substitute(arg, root));

  // Run once with no output file, once with one holding bytes that must survive.
  for (const bool outputExists : {false, true}) {
    if (outputExists && !input.outputCanExist) continue;
    SCOPED_TRACE(outputExists ? "with an existing output file" : "without an output file");
    constexpr const char* kPrecious = "precious,bytes\r\nnot,a,hits,file\n";
    if (outputExists) directory.write("h.csv", kPrecious);
    const auto before = directory.entries();

    const Result result = runTrace(args);
    // Option errors too: one line and status 1, never CLI11's two lines and status 105.
    EXPECT_EQ(result.status, 1) << result.err;
    EXPECT_EQ(lineCount(result.err), 1u) << result.err;
    EXPECT_TRUE(result.err.starts_with("revolve-trace: ")) << result.err;
    if (input.usageError) {
      EXPECT_TRUE(result.err.ends_with(" (see --help)\n")) << result.err;
    }
    for (const std::string& part : input.message) EXPECT_THAT(result.err, HasSubstr(substitute(part, root)));

    EXPECT_EQ(directory.entries(), before) << "files were created or removed";
    if (outputExists) {
      EXPECT_EQ(readWholeFile(outPath()), kPrecious);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInputTest, ::testing::ValuesIn(kBadInputs),
                         [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

// A directory given as a file opens but would read as empty; for rays that would be a valid file
// of no rays. It is refused as what it is.
TEST_F(TraceCliTest, RaysPathThatIsADirectoryIsAnError) {
  directory.write("p.csv", kCylinderCsv);
  std::filesystem::create_directory(directory / "rays");
  const Result result = runTrace({"--profile", profilePath(), "--rays", directory / "rays", "--out", outPath()});
  EXPECT_NE(result.status, 0);
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_THAT(result.err, HasSubstr(directory / "rays" + ": "));
  EXPECT_FALSE(std::filesystem::exists(outPath()));
}

}  // namespace
}  // namespace revolve
