// The kernel's exact boundary rules, each on rays whose exact answer is known in closed form, on
// every path a ray takes (intersect and occluded; rtcIntersect1/4/8/16 and rtcOccluded1/4/8/16 on
// an Embree scene holding a revolve::Geometry) and for every search:
// - the half-open height rule: a ray in a horizontal plane sees the circles of the segments that
//   continue upwards from its height, so at a vertex's height it meets the vertex circle of the
//   segment above (and at a top rim, nothing);
// - tnear <= t <= tfar is inclusive: a ray whose hit lies exactly at tfar or tnear hits, whether it
//   enters or leaves the solid there;
// - a tangent touch (a double root, discriminant exactly 0) is a hit, whatever the sign of the
//   quadratic's leading coefficient A (checked on the quadratic itself, below: through the kernel,
//   A < 0 with a double root occurs only at an apex, A = 0 only along a generator);
// - u lies in [0, 1): a hit just below the +x axis, whose exact u rounds to 1, reports u = 0;
// - a ray through an apex touches it, however nearly level with the apex it runs, and a ray
//   steeper than the cone enters or leaves its solid there;
// - a ray parallel to a generator (A = 0) crosses the cone once, or, in the generator's tangent
//   plane, never.
// Spline shapes run the same rules through the curve leaf: straight parts (Wang's kernel) and, in
// horizontal planes at the parts' end heights, curved ones.
// Profiles and rays use small dyadic numbers (radii 1, 0.75, 0.5; heights multiples of 1/8;
// directions along the axes, or with the hit placed where the kernel's arithmetic is exact, as each
// case says), so that each expected t is a float met exactly: a rule changed at its boundary then
// fails here, deterministically, rather than within rounding somewhere in a random test.
#include "kernel/bracketed_roots.h"
#include "util/azimuth.h"
#include "util/simd.h"

#include "embree/embree_handles.h"

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace revolve {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Every search that claims the rules: all of them share the segment kernel.
struct Variant {
  const char* name;
  BuildOptions options;
};
const Variant kVariants[] = {
    {"mibit/cylinder, wide (the default)", {}},
    {"mibit/cylinder, binary tree", {.method = Method::mibit, .shell = ShellKind::cylinder, .wideNodes = false}},
    {"mibit/cone", {.method = Method::mibit, .shell = ShellKind::cone}},
    {"mibit/hybrid", {.method = Method::mibit, .shell = ShellKind::hybrid}},
    {"mibit, no monotone split", {.method = Method::mibit, .shell = ShellKind::cylinder, .monotoneSplit = false}},
    {"mibit, no range search", {.method = Method::mibit, .shell = ShellKind::cylinder, .rangeSearch = false}},
    {"linear", {.method = Method::linear}},
    {"kajiya", {.method = Method::kajiya}},
};

struct Expected {
  float t;
  std::uint32_t segment;
  float u;
};

enum class Rule { halfOpenHeight, inclusiveRange, tangentTouch, uWrap, apexTouch, steepApex, alongGenerator };

struct Case {
  Rule rule;
  std::string what;
  Ray ray;
  std::optional<Expected> hit;  // nothing: a miss
};

struct ShapeCases {
  std::string name;
  std::vector<Point2> points;
  std::vector<Case> cases;
  std::optional<SplineKind> spline = std::nullopt;  // the points make this curve, traced exactly
};

Ray ray(Vec3 origin, Vec3 direction, float tnear = 0.0f, float tfar = kInf) { return {origin, direction, tnear, tfar}; }

// ---------------------------------------------------------------------------------------------
// The shapes and their cases. Each shape's centre (the kernel's local origin) is at z = 0.5, the
// middle of its heights, a dyadic number: local coordinates are exact too.

// Capped cylinder of radius 1 over z in [0, 1], its wall split at z = 0.5: segments 0 (bottom
// disc), 1 (wall, heights [0, 0.5)), 2 (wall, [0.5, 1)), 3 (top disc).
ShapeCases splitCylinder() {
  ShapeCases s{
      "capped cylinder r = 1, z in [0, 1], wall vertex at z = 0.5", {{0, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0, 1}}, {}};
  // Horizontal rays at vertex heights. Along an axis through the z axis a ray meets the circle of
  // radius 1 at distance |origin| -+ 1 along it: t is exact, and u is exact on the axes.
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.5 (wall vertex) from outside: segment 2's circle",
                     ray({-4, 0, 0.5}, {1, 0, 0}), Expected{3, 2, 0.5f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.5 from outside, direction of length 2", ray({-4, 0, 0.5}, {2, 0, 0}),
                     Expected{1.5, 2, 0.5f}});
  s.cases.push_back(
      {Rule::halfOpenHeight, "z = 0.5 from inside, on the axis", ray({0, 0, 0.5}, {0, -1, 0}), Expected{1, 2, 0.75f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.5 from inside, off the axis", ray({0.5, 0, 0.5}, {1, 0, 0}),
                     Expected{0.5, 2, 0.0f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0 (bottom rim) from outside: segment 1's circle",
                     ray({4, 0, 0}, {-1, 0, 0}), Expected{3, 1, 0.0f}});
  s.cases.push_back(
      {Rule::halfOpenHeight, "z = 0 from inside, tnear > 0", ray({0, 0, 0}, {0, 0.5, 0}, 1), Expected{2, 1, 0.25f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 1 (top rim): nothing continues upwards, a miss",
                     ray({-4, 0, 1}, {1, 0, 0}), std::nullopt});
  // Leaving the solid exactly at tfar and at tnear, in a horizontal plane: from the axis the wall is
  // met at t = 1, and from the wall itself at t = 0.
  s.cases.push_back({Rule::inclusiveRange, "horizontal from the axis, leaving the wall at t = tfar",
                     ray({0, 0, 0.25}, {1, 0, 0}, 0, 1), Expected{1, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "horizontal from the wall outwards, leaving it at t = tnear = 0",
                     ray({1, 0, 0.25}, {1, 0, 0}), Expected{0, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "horizontal from the axis, tfar one float short of the wall",
                     ray({0, 0, 0.25}, {1, 0, 0}, 0, std::nextafter(1.0f, 0.0f)), std::nullopt});
  // Tangent to the wall in a horizontal plane: the line y = 1 touches the circle of radius 1 at
  // (0, 1), t = 4; the kernel's quadratic there is x^2 + (1 - 1), whose discriminant is exactly 0.
  s.cases.push_back({Rule::tangentTouch, "horizontal, tangent to the wall at z = 0.25", ray({-4, 1, 0.25}, {1, 0, 0}),
                     Expected{4, 1, 0.25f}});
  s.cases.push_back({Rule::tangentTouch, "horizontal, tangent to the wall at z = 0.75", ray({1, -4, 0.75}, {0, 2, 0}),
                     Expected{2, 2, 0.0f}});
  // Hits exactly at tfar on an oblique ray, where the ray enters the solid. (Only entries: at tfar
  // the kernel counts a point on the surface as inside, so an exit exactly at tfar, or at tnear,
  // is not reported.) The hit (1, 0, 0.75) on segment 2 is the point of the ray nearest the
  // shape's centre (0, 0, 0.5), since the direction (-1, 0, 4) is perpendicular to (1, 0, 0.25):
  // the kernel re-centres the ray there, so the hit is at its s = 0, where rho = 1 and the cone
  // function are exact (tCentre = 8.5 / 17 = 0.5 exactly). The ray enters the wall there from
  // outside (it passes z = 0 at x = 1.1875 and z = 0.5 at x = 1.0625, outside the caps and the
  // vertex circle), with the closest approach to the axis far beyond (t = 1.5).
  const Vec3 from{1.5, 0, -1.25};
  s.cases.push_back(
      {Rule::inclusiveRange, "oblique, hit at t = tfar", ray(from, {-1, 0, 4}, 0, 0.5), Expected{0.5, 2, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "oblique, hit at t = tfar, tnear > 0", ray(from, {-1, 0, 4}, 0.25, 0.5),
                     Expected{0.5, 2, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "oblique, hit at t = tnear = tfar", ray(from, {-1, 0, 4}, 0.5, 0.5),
                     Expected{0.5, 2, 0.0f}});
  s.cases.push_back(
      {Rule::inclusiveRange, "oblique, hit at t = tnear", ray(from, {-1, 0, 4}, 0.5), Expected{0.5, 2, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "oblique, tfar one float short of the hit",
                     ray(from, {-1, 0, 4}, 0, std::nextafter(0.5f, 0.0f)), std::nullopt});
  // The same line at other speeds k (-1, 0, 4): the hit at t = 0.5 / k, the centre still at it.
  s.cases.push_back({Rule::inclusiveRange, "oblique, direction halved, hit at t = tfar = 1",
                     ray(from, {-0.5, 0, 2}, 0, 1), Expected{1, 2, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "oblique, direction times 4, hit at t = tfar = 0.125",
                     ray(from, {-4, 0, 16}, 0, 0.125), Expected{0.125, 2, 0.0f}});
  // u at the wrap: the hit (1, -2^-30, 0.25) lies just below the +x axis; its exact u,
  // 1 - atan(2^-30) / 2 pi = 1 - 1.5e-10, is nearer 1 than the float below 1 (1 - 2^-24), so it
  // rounds to 1, the same azimuth as 0, and [0, 1) makes it 0. Horizontal, along -x: t = 4 - 1.
  // Obliquely, rising 1/8 a unit, the ray meets the wall at (1, -2^-30, 0.75): there the kernel's t
  // is within double rounding of 3, which rounds to the float 3, and y = -2^-30 exactly.
  s.cases.push_back({Rule::uWrap, "u just below the +x axis wraps to 0", ray({4, -0x1p-30f, 0.25}, {-1, 0, 0}),
                     Expected{3, 1, 0.0f}});
  s.cases.push_back({Rule::uWrap, "u just below the +x axis, oblique ray",
                     ray({4, -0x1p-30f, 0.75 - 3 * 0.125}, {-1, 0, 0.125}), Expected{3, 2, 0.0f}});
  return s;
}

// Capped cylinder of radius 1 over z in [0, 1], its wall one segment: 0 (bottom disc), 1 (wall),
// 2 (top disc). For a ray tangent to the wall obliquely.
ShapeCases plainCylinder() {
  ShapeCases s{"capped cylinder r = 1, z in [0, 1]", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  // In the plane y = 1, the line through (0, 1, 0.5) along (1, 0, k) touches the wall at that point.
  // It is the point nearest the shape's centre (0, 0, 0.5), where the kernel re-centres the ray, and
  // the ray's stretch in the wall's slab is symmetric about it, so the kernel expands its quadratic
  // exactly there: B = 0 and C = 1 - 1 = 0 exactly, a discriminant of exactly 0. The ray crosses
  // the caps' planes at rho^2 = 1 + x^2 > 1, outside them.
  s.cases.push_back({Rule::tangentTouch, "oblique, tangent to the wall, along (1, 0, 1)", ray({-2, 1, -1.5}, {1, 0, 1}),
                     Expected{2, 1, 0.25f}});
  s.cases.push_back({Rule::tangentTouch, "oblique, tangent to the wall, along (2, 0, 2)", ray({-2, 1, -1.5}, {2, 0, 2}),
                     Expected{1, 1, 0.25f}});
  s.cases.push_back({Rule::tangentTouch, "oblique, tangent to the wall, along (1, 0, 0.5)",
                     ray({-2, 1, -0.5}, {1, 0, 0.5}), Expected{2, 1, 0.25f}});
  s.cases.push_back({Rule::tangentTouch, "oblique, tangent to the wall, tfar at the touch",
                     ray({-2, 1, -1.5}, {1, 0, 1}, 0, 2), Expected{2, 1, 0.25f}});
  // One float to the side the same line misses: the touch is a hit only because it is exact.
  s.cases.push_back({Rule::tangentTouch, "oblique, one float outside the tangent",
                     ray({-2, std::nextafter(1.0f, 2.0f), -1.5}, {1, 0, 1}), std::nullopt});
  return s;
}

// A solid narrowing upwards: the cone r = 1 - z from z = 0 to 0.5 (split at z = 0.25, r = 0.75),
// then the cylinder r = 0.5 up to z = 1. Segments 0 (bottom disc), 1 (cone, [0, 0.25)), 2 (cone,
// [0.25, 0.5)), 3 (cylinder, [0.5, 1)), 4 (top disc).
ShapeCases frustum() {
  ShapeCases s{"frustum r = 1 - z below z = 0.5, cylinder r = 0.5 above",
               {{0, 0}, {1, 0}, {0.75, 0.25}, {0.5, 0.5}, {0.5, 1}, {0, 1}},
               {}};
  // Horizontal rays at vertex heights on the cone stretch: in the plane the kernel takes the vertex's
  // own radius (0.75, 0.5, 1), and along an axis through the z axis the circle of radius r is met
  // at |origin| -+ r, divided by the direction's length (a power of two): exact.
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.25 (cone vertex, r = 0.75) from outside",
                     ray({-4, 0, 0.25}, {1, 0, 0}), Expected{3.25, 2, 0.5f}});
  s.cases.push_back(
      {Rule::halfOpenHeight, "z = 0.25 from inside", ray({0, 0, 0.25}, {0, 1, 0}), Expected{0.75, 2, 0.25f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.5 (cone to cylinder, r = 0.5) from outside",
                     ray({0, -4, 0.5}, {0, 2, 0}), Expected{1.75, 3, 0.75f}});
  s.cases.push_back(
      {Rule::halfOpenHeight, "z = 0.5 from inside", ray({0, 0, 0.5}, {-0.25, 0, 0}), Expected{2, 3, 0.5f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0 (bottom rim, r = 1) from inside", ray({0, 0, 0}, {-1, 0, 0}),
                     Expected{1, 1, 0.5f}});
  // Vertical rays down at x = 0.875 enter the cone where 1 - z = 0.875, z = 0.125, inside segment
  // 1's slab (they pass the top cap and both vertex circles outside them). Every quantity the
  // kernel forms is exact: the direction is (0, 0, -1) times a power of two, and rho = 0.875 and
  // the cone's radius at z = 0.125 are dyadic.
  const Vec3 above{0.875, 0, 2};
  s.cases.push_back({Rule::inclusiveRange, "vertical, hit at t = tfar (|d| = 4)", ray(above, {0, 0, -4}, 0, 0.46875),
                     Expected{0.46875, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, hit at t = tfar, tnear > 0",
                     ray(above, {0, 0, -4}, 0.25, 0.46875), Expected{0.46875, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, hit at t = tnear = tfar",
                     ray(above, {0, 0, -4}, 0.46875, 0.46875), Expected{0.46875, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, hit at t = tnear", ray(above, {0, 0, -4}, 0.46875),
                     Expected{0.46875, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, tfar one float short of the hit",
                     ray(above, {0, 0, -4}, 0, std::nextafter(0.46875f, 0.0f)), std::nullopt});
  s.cases.push_back({Rule::inclusiveRange, "vertical, hit at t = tfar (|d| = 0.5)", ray(above, {0, 0, -0.5}, 0, 3.75),
                     Expected{3.75, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, tfar = 3.5 before the hit at 3.75 (|d| = 0.5)",
                     ray(above, {0, 0, -0.5}, 0, 3.5), std::nullopt});
  // Rising from inside (r = 0.875 < 1 - 0.0625), the ray leaves the cone where 1 - z = 0.875,
  // z = 0.125, t = 0.0625 / 4, as exactly as it enters it above; and from that very point upwards it
  // leaves at t = tnear = 0.
  s.cases.push_back({Rule::inclusiveRange, "vertical, leaving the cone at t = tfar (|d| = 4)",
                     ray({0.875, 0, 0.0625}, {0, 0, 4}, 0, 0.015625), Expected{0.015625, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, leaving the cone at t = tnear = 0",
                     ray({0.875, 0, 0.125}, {0, 0, 4}), Expected{0, 1, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "vertical, tfar one float short of leaving the cone",
                     ray({0.875, 0, 0.0625}, {0, 0, 4}, 0, std::nextafter(0.015625f, 0.0f)), std::nullopt});
  // Starting past the cone, the ray next meets the bottom disc at z = 0, t = 4.
  s.cases.push_back({Rule::inclusiveRange, "vertical, tnear = 3.875 past the hit at 3.75 (|d| = 0.5)",
                     ray(above, {0, 0, -0.5}, 3.875), Expected{4, 0, 0.0f}});
  return s;
}

// The open cone from the apex (0, 0, 1) down to its rim, radius 0.5 at z = 0: one segment, whose
// heights are [0, 1).
ShapeCases openCone() {
  ShapeCases s{"open cone, apex (0, 0, 1), rim r = 0.5 at z = 0", {{0, 1}, {0.5, 0}}, {}};
  // In the rim's plane the circle of radius 0.5, met along the x axis at 4 - 0.5, and from the axis
  // at 0.5.
  s.cases.push_back(
      {Rule::halfOpenHeight, "z = 0 (the rim) from outside", ray({-4, 0, 0}, {1, 0, 0}), Expected{3.5, 0, 0.5f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0 from inside", ray({0, 0, 0}, {0, 1, 0}), Expected{0.5, 0, 0.25f}});
  // In the rim's plane the line y = 0.5 touches the rim circle at (0, 0.5): exactly tangent.
  s.cases.push_back(
      {Rule::tangentTouch, "horizontal, tangent to the rim", ray({-4, 0.5, 0}, {1, 0, 0}), Expected{4, 0, 0.25f}});
  // At z = 0.5 the cone's radius is 0.25, exactly: the line y = -0.25 touches it at (0, -0.25).
  s.cases.push_back({Rule::tangentTouch, "horizontal, tangent to the cone at z = 0.5", ray({-4, -0.25, 0.5}, {1, 0, 0}),
                     Expected{4, 0, 0.75f}});
  s.cases.push_back({Rule::tangentTouch, "horizontal, one float outside the rim",
                     ray({-4, std::nextafter(0.5f, 1.0f), 0}, {1, 0, 0}), std::nullopt});
  // Nearly level rays through the apex: origin + direction is exactly (0, 0, 1) (the x and y
  // components cancel, and the z components sum to 1 exactly), so the line passes through the
  // apex at t = 1, rising about 1/200, 1/1000 and 1/16000 of its length. Both its sides lie outside the
  // cone (above the apex it is in the mirror nappe's region): only the apex-touch rule reports it.
  // The azimuth of a hit on the axis is arbitrary: u is not checked.
  s.cases.push_back(
      {Rule::apexTouch, "through the apex, rising 1 in 200",
       ray({0x1.75725cp-3f, 0x1.fe1e5cp+0f, 0x1.fce6ecp-1f}, {-0x1.75725cp-3f, -0x1.fe1e5cp+0f, 0x1.8c8ap-8f}),
       Expected{1, 0, 0.0f}});
  s.cases.push_back({Rule::apexTouch, "through the apex, rising 1 in 1,024", ray({2, 0, 1 - 0x1p-9f}, {-2, 0, 0x1p-9f}),
                     Expected{1, 0, 0.0f}});
  s.cases.push_back({Rule::apexTouch, "through the apex, rising 1 in 16,384",
                     ray({0, 2, 1 - 0x1p-13f}, {0, -2, 0x1p-13f}), Expected{1, 0, 0.0f}});
  return s;
}

// A flat open cone: apex (0, 0, 0.5), rim r = 2 at z = 0, one segment (slope dz/dr = -1/4), for
// rays steeper than it (A < 0) and parallel to its generators (A = 0). As a Bezier piece with its
// inner points on the chord, (0.5, 0.375) and (1.5, 0.125), it is a straight part of a spline: the
// curve leaf hands it to Wang's kernel, and the same cases hold.
ShapeCases flatCone(bool asSpline) {
  ShapeCases s{
      asSpline ? "flat open cone as a straight Bezier piece" : "flat open cone, apex (0, 0, 0.5), rim r = 2 at z = 0",
      asSpline ? std::vector<Point2>{{0, 0.5}, {0.5, 0.375}, {1.5, 0.125}, {2, 0}}
               : std::vector<Point2>{{0, 0.5}, {2, 0}},
      {},
      asSpline ? std::optional<SplineKind>(SplineKind::bezier) : std::nullopt};
  // Steeper than the cone, through the apex: the quadratic's A = ez^2 (dx^2 + dy^2) - er^2 dz^2 is
  // negative and the apex a double root. Beyond the apex (below it) the ray is inside the cone
  // (at depth h it is h from the axis, the cone 4 h), and it leaves through the open rim plane: the
  // apex is its only hit. Direction (1, 0, -1) from (-1, 0, 1.5): the apex at t = 1.
  s.cases.push_back({Rule::steepApex, "down through the apex, 1 across per 1 down: enters there",
                     ray({-1, 0, 1.5}, {1, 0, -1}), Expected{1, 0, 0.0f}});
  s.cases.push_back({Rule::steepApex, "down through the apex, direction (0, -0.5, -2)",
                     ray({0, 0.5, 2.5}, {0, -0.5, -2}), Expected{1, 0, 0.0f}});
  s.cases.push_back({Rule::steepApex, "up from inside, leaving through the apex at t = 0.5",
                     ray({0.5, 0, 0}, {-1, 0, 1}), Expected{0.5, 0, 0.0f}});
  s.cases.push_back({Rule::steepApex, "up from inside, tfar one float short of the apex",
                     ray({0.5, 0, 0}, {-1, 0, 1}, 0, std::nextafter(0.5f, 0.0f)), std::nullopt});
  // Parallel to the generator from the apex to (2, 0, 0), direction (4, 0, -1): A = 0 exactly (the
  // unit direction's x is 4 times its z, exactly). From (-5, 0, 1.5) the ray runs at x = -5 + 4t,
  // z = 1.5 - t, where the cone's radius is 4t - 4: it crosses the opposite generator (x = -radius)
  // at t = 9/8, the point (-0.5, 0, 0.375), and stays inside down to the open rim.
  s.cases.push_back({Rule::alongGenerator, "parallel to a generator, crossing the opposite one at t = 9/8",
                     ray({-5, 0, 1.5}, {4, 0, -1}), Expected{1.125, 0, 0.5f}});
  // In the generator's tangent plane (y = 2^-20 beside it, x equal to the cone's radius all along):
  // rho^2 - radius^2 = 2^-40 throughout, outside everywhere, never touching (nor near the apex).
  s.cases.push_back({Rule::alongGenerator, "parallel to a generator in its tangent plane, 2^-20 beside it: a miss",
                     ray({-2, 0x1p-20f, 1}, {4, 0, -1}), std::nullopt});
  return s;
}

// A capped barrel of splines: bottom disc (1, 0) from the axis, the wall a cubic r = 1 -> 1 via
// (1.5, 0.25) and (1.5, 0.75) up to (1, 1), then the top disc back to the axis, every piece a
// cubic Bezier (the discs' inner points on their chords). The wall's r turns at u = 1/2, so it is
// split there into two curved parts meeting at (1.375, 0.5): parts 0 (bottom disc), 1 (wall,
// heights [0, 0.5)), 2 (wall, [0.5, 1)), 3 (top disc). In a horizontal plane at a part's end height
// the curve leaf takes that end's radius as it is: the answers are exact.
ShapeCases splineBarrel() {
  ShapeCases s{"capped spline barrel, wall bulging to r = 1.375 at z = 0.5",
               {{0, 0}, {0.25, 0}, {0.75, 0}, {1, 0}, {1.5, 0.25}, {1.5, 0.75}, {1, 1}, {0.75, 1}, {0.25, 1}, {0, 1}},
               {},
               SplineKind::bezier};
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.5 (the wall's split) from outside: part 2's circle",
                     ray({-4, 0, 0.5}, {1, 0, 0}), Expected{2.625, 2, 0.5f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0.5 from inside, on the axis", ray({0, 0, 0.5}, {0, -0.5, 0}),
                     Expected{2.75, 2, 0.75f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 0 (bottom rim) from outside: part 1's circle",
                     ray({4, 0, 0}, {-1, 0, 0}), Expected{3, 1, 0.0f}});
  s.cases.push_back({Rule::halfOpenHeight, "z = 1 (top rim): nothing continues upwards, a miss",
                     ray({-4, 0, 1}, {1, 0, 0}), std::nullopt});
  s.cases.push_back({Rule::inclusiveRange, "z = 0.5 from the axis, leaving the wall at t = tfar",
                     ray({0, 0, 0.5}, {1, 0, 0}, 0, 1.375), Expected{1.375, 2, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "z = 0.5 from the wall outwards, leaving it at t = tnear = 0",
                     ray({1.375, 0, 0.5}, {1, 0, 0}), Expected{0, 2, 0.0f}});
  s.cases.push_back({Rule::inclusiveRange, "z = 0.5 from outside, entering the wall at t = tfar",
                     ray({-4, 0, 0.5}, {1, 0, 0}, 0, 2.625), Expected{2.625, 2, 0.5f}});
  s.cases.push_back({Rule::inclusiveRange, "z = 0.5 from the axis, tfar one float short of the wall",
                     ray({0, 0, 0.5}, {1, 0, 0}, 0, std::nextafter(1.375f, 0.0f)), std::nullopt});
  // The line y = 1.375 touches the circle of radius 1.375 at (0, 1.375): the curve leaf's quadratic
  // x^2 + (1.375^2 - 1.375^2) has a discriminant of exactly 0.
  s.cases.push_back({Rule::tangentTouch, "horizontal, tangent to the curved wall at z = 0.5",
                     ray({-4, 1.375, 0.5}, {1, 0, 0}), Expected{4, 2, 0.25f}});
  s.cases.push_back({Rule::tangentTouch, "horizontal, tangent to the curved wall at z = 0", ray({1, -4, 0}, {0, 2, 0}),
                     Expected{2, 1, 0.0f}});
  s.cases.push_back({Rule::tangentTouch, "horizontal, one float outside the curved wall",
                     ray({-4, std::nextafter(1.375f, 2.0f), 0.5}, {1, 0, 0}), std::nullopt});
  return s;
}

std::vector<ShapeCases> allShapes() {
  return {splitCylinder(), plainCylinder(), frustum(), openCone(), flatCone(false), flatCone(true), splineBarrel()};
}

// ---------------------------------------------------------------------------------------------
// Checking one answer.

std::string describe(const Ray& r) {
  return "o=(" + std::to_string(r.origin.x) + ", " + std::to_string(r.origin.y) + ", " + std::to_string(r.origin.z) +
         ") d=(" + std::to_string(r.direction.x) + ", " + std::to_string(r.direction.y) + ", " +
         std::to_string(r.direction.z) + ") [" + std::to_string(r.tnear) + ", " + std::to_string(r.tfar) + "]";
}

void expectHit(const Case& c, const std::string& path, bool found, float t, std::uint32_t segment, float u) {
  SCOPED_TRACE(path + ": " + c.what + ", " + describe(c.ray));
  ASSERT_EQ(found, c.hit.has_value());
  if (!found) return;
  EXPECT_EQ(t, c.hit->t);
  EXPECT_EQ(segment, c.hit->segment);
  if (c.rule != Rule::apexTouch && c.rule != Rule::steepApex) {  // the azimuth of a point on the axis is arbitrary
    EXPECT_EQ(u, c.hit->u);
  }
}

void expectOccluded(const Case& c, const std::string& path, bool occluded) {
  EXPECT_EQ(occluded, c.hit.has_value()) << path << ": " << c.what << ", " << describe(c.ray);
}

// ---------------------------------------------------------------------------------------------
// Embree.

using app::DeviceRelease;  // the applications' owning handles (common/embree_handles.h)
using app::SceneRelease;

struct EmbreeScene {
  std::unique_ptr<RTCDeviceTy, DeviceRelease> device{rtcNewDevice(nullptr)};
  std::unique_ptr<Geometry> geometry;
  std::unique_ptr<RTCSceneTy, SceneRelease> scene;
  unsigned geomID = RTC_INVALID_GEOMETRY_ID;

  explicit EmbreeScene(const Shape& shape) {
    rtcSetDeviceErrorFunction(
        device.get(),
        [](void*, RTCError code, const char* message) { ADD_FAILURE() << "Embree error " << code << ": " << message; },
        nullptr);
    geometry = std::make_unique<Geometry>(device.get(), shape);
    scene.reset(rtcNewScene(device.get()));
    geomID = rtcAttachGeometry(scene.get(), geometry->handle());
    rtcCommitScene(scene.get());
  }
};

void checkSingleRays(const EmbreeScene& e, const Case& c) {
  embree::RayQuery query;
  RTCRayHit rh{};
  rh.ray = {c.ray.origin.x,
            c.ray.origin.y,
            c.ray.origin.z,
            c.ray.tnear,
            c.ray.direction.x,
            c.ray.direction.y,
            c.ray.direction.z,
            0.0f,
            c.ray.tfar,
            ~0u,
            0u,
            0u};
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCRay shadow = rh.ray;
  query.intersect(e.scene.get(), rh);
  const bool found = rh.hit.geomID == e.geomID;
  if (!found) {
    EXPECT_EQ(rh.ray.tfar, c.ray.tfar) << "rtcIntersect1 changed tfar on a miss: " << c.what;
  }
  expectHit(c, "rtcIntersect1", found, rh.ray.tfar, rh.hit.primID, rh.hit.u);
  query.occluded(e.scene.get(), shadow);
  expectOccluded(c, "rtcOccluded1", shadow.tfar == -kInf);
}

// Packets of N rays, all lanes valid, filled with the cases in turn from each starting offset, so
// that every case runs in every lane.
template <int N, class RayHitN, class RayN>
void checkPackets(const EmbreeScene& e, const std::vector<Case>& cases) {
  const std::size_t count = cases.size();
  for (std::size_t offset = 0; offset < std::max<std::size_t>(count, N); ++offset) {
    alignas(64) int valid[N];
    alignas(64) RayHitN packet{};
    for (int i = 0; i < N; ++i) {
      const Ray& r = cases[(offset + i) % count].ray;
      valid[i] = -1;
      packet.ray.org_x[i] = r.origin.x, packet.ray.org_y[i] = r.origin.y, packet.ray.org_z[i] = r.origin.z;
      packet.ray.dir_x[i] = r.direction.x, packet.ray.dir_y[i] = r.direction.y, packet.ray.dir_z[i] = r.direction.z;
      packet.ray.tnear[i] = r.tnear, packet.ray.tfar[i] = r.tfar, packet.ray.mask[i] = ~0u;
      packet.ray.time[i] = 0.0f, packet.ray.flags[i] = 0u;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    alignas(64) RayN shadow = packet.ray;
    embree::RayQuery query;
    if constexpr (N == 4) {
      query.intersect(valid, e.scene.get(), packet);
      query.occluded(valid, e.scene.get(), shadow);
    } else if constexpr (N == 8) {
      query.intersect(valid, e.scene.get(), packet);
      query.occluded(valid, e.scene.get(), shadow);
    } else {
      query.intersect(valid, e.scene.get(), packet);
      query.occluded(valid, e.scene.get(), shadow);
    }
    for (int i = 0; i < N; ++i) {
      const Case& c = cases[(offset + i) % count];
      const std::string lane = " lane " + std::to_string(i);
      expectOccluded(c, "rtcOccluded" + std::to_string(N) + lane, shadow.tfar[i] == -kInf);
      // Embree's packet traversal (3.13) drops a lane with tnear == tfar before any user geometry
      // sees it (measured: the callback is not called), where rtcIntersect1 and rtcOccludedN keep it.
      if (c.ray.tnear == c.ray.tfar) continue;
      const bool found = packet.hit.geomID[i] == e.geomID;
      if (!found) {
        EXPECT_EQ(packet.ray.tfar[i], c.ray.tfar) << "rtcIntersect" << N << " changed tfar on a miss: " << c.what;
      }
      expectHit(c, "rtcIntersect" + std::to_string(N) + lane, found, packet.ray.tfar[i], packet.hit.primID[i],
                packet.hit.u[i]);
    }
  }
}

// Every case of every shape, for one search, on every path.
void checkEveryPath(const Variant& variant, const ShapeCases& shape, const std::vector<Case>& cases) {
  if (shape.spline && variant.options.method == Method::kajiya) return;  // its strips bound polylines only
  SCOPED_TRACE(std::string(variant.name) + ", " + shape.name);
  const Shape built = shape.spline ? Shape(Spline(*shape.spline, shape.points), variant.options)
                                   : Shape(Profile(shape.points), variant.options);
  for (const Case& c : cases) {
    const std::optional<Hit> hit = intersect(built, c.ray);
    expectHit(c, "intersect", hit.has_value(), hit ? hit->t : 0.0f, hit ? hit->segment : 0u, hit ? hit->u : 0.0f);
    expectOccluded(c, "occluded", occluded(built, c.ray));
  }
  const EmbreeScene e(built);
  for (const Case& c : cases) checkSingleRays(e, c);
  checkPackets<4, RTCRayHit4, RTCRay4>(e, cases);
  checkPackets<8, RTCRayHit8, RTCRay8>(e, cases);
  checkPackets<16, RTCRayHit16, RTCRay16>(e, cases);
}

// The cases of one rule, shape by shape, for every search on every path.
void checkRule(Rule rule) {
  std::size_t checked = 0;
  for (const ShapeCases& shape : allShapes()) {
    std::vector<Case> cases;
    for (const Case& c : shape.cases) {
      if (c.rule == rule) cases.push_back(c);
    }
    if (cases.empty()) continue;
    checked += cases.size();
    for (const Variant& variant : kVariants) checkEveryPath(variant, shape, cases);
  }
  EXPECT_GE(checked, 2u);  // the table above holds cases of every rule
}

TEST(BoundaryRulesTest, HorizontalRaysAtVertexHeightsMeetTheCircleOfTheSegmentAbove) {
  checkRule(Rule::halfOpenHeight);
}

TEST(BoundaryRulesTest, ObliqueRaysHitExactlyAtTfarAndTnear) { checkRule(Rule::inclusiveRange); }

TEST(BoundaryRulesTest, TangentRaysTouchTheWallAndTheRim) { checkRule(Rule::tangentTouch); }

TEST(BoundaryRulesTest, HitsJustBelowThePlusXAxisReportUZero) { checkRule(Rule::uWrap); }

TEST(BoundaryRulesTest, NearlyLevelRaysThroughAnApexTouchIt) { checkRule(Rule::apexTouch); }

TEST(BoundaryRulesTest, RaysSteeperThanTheConeEnterOrLeaveThroughTheApex) { checkRule(Rule::steepApex); }

TEST(BoundaryRulesTest, RaysParallelToAGeneratorCrossTheConeOnceOrNever) { checkRule(Rule::alongGenerator); }

// ---------------------------------------------------------------------------------------------
// The tangent rule on the quadratic itself. g(x) = A x^2 + 2 B x + C is negative inside; at its
// extremum e = -B / A it is -D / A, D = B^2 - A C. A double root (D = 0 exactly) is a touch, which
// counts as reaching the surface whichever way g curves: a convex g (A > 0) touches from outside,
// a concave one (A < 0) from inside. Through the kernel the concave touch occurs only at an apex,
// where the segment's slab ends and the extremum never lies strictly inside the bracket, so only
// these closed forms reach that branch of the rule.

struct QuadraticCase {
  const char* what;
  detail::Quadratic g;
  double x0, x1;
  bool inside0, inside1;      // g < 0 at the ends, as the caller's predicates say
  std::vector<double> roots;  // every root in [x0, x1], increasing (a double root twice)
  detail::EndsOnSurface on = {};
};

const QuadraticCase kQuadraticCases[] = {
    {"A > 0, D = 0: (x - 1)^2 touches from outside", {1, -1, 1}, 0, 2, false, false, {1, 1}},
    {"A > 0, D > 0: (x - 1)^2 - 1 crosses at 0 and 2", {1, -1, 0}, -1, 3, false, false, {0, 2}},
    {"A > 0, D < 0: (x - 1)^2 + 1 stays outside", {1, -1, 2}, 0, 2, false, false, {}},
    {"A < 0, D = 0: -(x - 1)^2 touches from inside", {-1, 1, -1}, 0, 2, true, true, {1, 1}},
    {"A < 0, D = 0: -(x - 1)^2 / 4 touches from inside", {-0.25, 0.25, -0.25}, -3, 3, true, true, {1, 1}},
    {"A < 0, D > 0: 1 - (x - 1)^2 leaves at 0 and enters at 2", {-1, 1, 0}, -1, 3, true, true, {0, 2}},
    {"A < 0, D < 0: -(x - 1)^2 - 1 stays inside", {-1, 1, -2}, 0, 2, true, true, {}},
    {"A < 0, D = 0, touching at the end on the surface", {-1, 1, -1}, 0, 1, true, false, {1}, {false, true}},
    {"A = 0: 2x - 1 leaves at 1/2", {0, 1, -1}, 0, 2, true, false, {0.5}},
    {"A = 0, B = 0: a constant 1 stays outside (parallel to a generator, in its tangent plane)",
     {0, 0, 1},
     0,
     2,
     false,
     false,
     {}},
    {"A = 0, B = 0, C = 0 with the end signs apart (along the surface): the first point",
     {0, 0, 0},
     0.5,
     2,
     false,
     true,
     {0.5}},
};

TEST(BoundaryRulesTest, ATangentTouchIsAHitWhateverTheSignOfTheLeadingCoefficient) {
  for (const QuadraticCase& c : kQuadraticCases) {
    SCOPED_TRACE(c.what);
    const double D = c.g.B * c.g.B - c.g.A * c.g.C;
    if (c.roots.size() == 2 && c.roots[0] == c.roots[1]) {
      EXPECT_EQ(D, 0.0) << "the case's discriminant is exactly 0";
    }
    const detail::Roots all = detail::bracketedRoots<false>(c.g, c.x0, c.x1, c.inside0, c.inside1, c.on);
    ASSERT_EQ(std::size_t(all.count), c.roots.size());
    for (int i = 0; i < all.count; ++i) EXPECT_EQ(all.x[i], c.roots[i]) << "root " << i;
    const detail::Roots first = detail::bracketedRoots<true>(c.g, c.x0, c.x1, c.inside0, c.inside1, c.on);
    ASSERT_EQ(first.count, c.roots.empty() ? 0 : 1);
    if (first.count == 1) {
      EXPECT_EQ(first.x[0], c.roots[0]);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// u at the wrap, on the attribute code directly: the scalar azimuthFraction (intersect,
// rtcIntersect1) and the packet azimuthFractions (rtcIntersect4/8/16).

struct WrapPoint {
  double x, y;
  float u;
};

// Exact u = 1 - atan(|y| / x) / 2 pi just below the +x axis. The float below 1 is 1 - 2^-24, so u
// rounds to 1 (and wraps to 0) when atan(|y| / x) / 2 pi < 2^-25, i.e. |y| / x < 1.87e-7, and to
// 1 - 2^-24 when that fraction lies between 2^-25 and 3 * 2^-25.
const WrapPoint kWrapPoints[] = {
    {1, -1e-300, 0.0f},              // 1 - 1.6e-301
    {1, -0x1p-30, 0.0f},             // 1 - 1.5e-10
    {1, -0x1p-23, 0.0f},             // 1 - 1.9e-8, below 2^-25 = 3.0e-8 from 1
    {4, -0x1p-21, 0.0f},             // the same direction
    {1, -0x1p-22, 1.0f - 0x1p-24f},  // 1 - 3.8e-8: nearer 1 - 2^-24 (6.0e-8 from 1) than 1
    {1, 0.0, 0.0f},                  // on the axis
    {1, -0.0, 0.0f},
    {-1, -1e-300, 0.5f},  // just below the -x axis: 0.5 + 1.6e-301
    {0, -1, 0.75f},
};

TEST(BoundaryRulesTest, AzimuthFractionWrapsJustBelowOneToZero) {
  for (const WrapPoint& p : kWrapPoints) {
    EXPECT_EQ(detail::azimuthFraction(p.x, p.y), p.u) << "x = " << p.x << ", y = " << p.y;
  }
}

TEST(BoundaryRulesTest, AzimuthFractionsWrapJustBelowOneToZeroInEveryLane) {
  constexpr std::size_t kCount = std::size(kWrapPoints);
  for (std::size_t offset = 0; offset < kCount; ++offset) {
    double x[detail::kLanes], y[detail::kLanes];
    for (int lane = 0; lane < detail::kLanes; ++lane) {
      x[lane] = kWrapPoints[(offset + lane) % kCount].x;
      y[lane] = kWrapPoints[(offset + lane) % kCount].y;
    }
    float u[detail::kLanes];
    detail::azimuthFractions(detail::load(x), detail::load(y), u);
    for (int lane = 0; lane < detail::kLanes; ++lane) {
      const WrapPoint& p = kWrapPoints[(offset + lane) % kCount];
      EXPECT_EQ(u[lane], p.u) << "lane " << lane << ": x = " << p.x << ", y = " << p.y;
    }
  }
}

}  // namespace
}  // namespace revolve
