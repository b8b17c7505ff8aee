// Watertight seams. A ray from inside a closed profile's solid must leave it, so it must be reported
// hitting the surface, even when aimed exactly at a vertex circle: the seam shared by two segments,
// including horizontal-vertical corners, apexes on the axis and the closing point of a loop.
// The kernel guarantees it by construction (segment_hits.h: the inside/outside state at a vertex
// plane is one predicate both neighbours evaluate identically), not by tolerance.
#include "support/hard_profiles.h"
#include "support/test_profiles.h"
#include "support/test_scale.h"

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace revolve {
namespace {

struct SeamRays {
  std::vector<Ray> rays;
};

// `count` rays from interior points (at least 1e-4 of the size from the surface) towards random
// points of random vertex circles (the apex itself for a vertex on the axis).
std::vector<Ray> raysAtVertexCircles(std::span<const Point2> points, std::mt19937_64& random, std::size_t count) {
  const std::vector<Vec3> origins = testing::interiorPoints(points, random, 512, 1e-4);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  std::vector<Ray> rays;
  rays.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Point2 vertex = points[random() % points.size()];
    const double phi = angle(random);
    const Vec3 target{float(vertex.r * std::cos(phi)), float(vertex.r * std::sin(phi)), float(vertex.z)};
    const Vec3 origin = origins[i % origins.size()];
    rays.push_back({origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}});
  }
  return rays;
}

struct Variant {
  const char* name;
  BuildOptions options;
  std::size_t raysPerProfile;
};

TEST(SeamTest, RaysFromInsideAimedAtVertexCirclesNeverLeak) {
  constexpr std::uint64_t kSeed = 0x5ea5;
  std::mt19937_64 random(kSeed);
  const std::vector<testing::ClosedProfile> profiles = testing::closedProfiles();
  ASSERT_GE(profiles.size(), 8u);
  // The default MIBIT carries the ten million rays; every other search is checked on fewer.
  const std::size_t defaultRays = testing::scaledRays(10'000'000) / profiles.size() + 1;
  const std::vector<Variant> variants = {
      {"mibit (the default: cylinder, wide)", {}, defaultRays},
      {"mibit/cylinder/binary",
       {.method = Method::mibit, .shell = ShellKind::cylinder, .wideNodes = false},
       testing::scaledRays(100'000)},
      {"mibit/hybrid", {.method = Method::mibit, .shell = ShellKind::hybrid}, testing::scaledRays(100'000)},
      {"mibit/cone", {.method = Method::mibit, .shell = ShellKind::cone}, testing::scaledRays(100'000)},
      {"mibit/no split",
       {.method = Method::mibit, .shell = ShellKind::hybrid, .monotoneSplit = false},
       testing::scaledRays(50'000)},
      {"kajiya", {.method = Method::kajiya}, testing::scaledRays(50'000)},
      {"linear", {.method = Method::linear}, testing::scaledRays(20'000)},
  };
  for (const Variant& variant : variants) {
    std::size_t fired = 0, leaks = 0;
    for (const testing::ClosedProfile& closed : profiles) {
      SCOPED_TRACE(std::string(variant.name) + ", " + closed.name + ", seed " + std::to_string(kSeed));
      const Shape shape(Profile(closed.points), variant.options);
      // The linear scan over 20,000 segments costs a millisecond a ray: fewer rays there.
      const std::size_t count = variant.options.method == Method::linear && closed.points.size() > 1000
                                    ? testing::scaledRays(500)
                                    : variant.raysPerProfile;
      int reported = 0;
      for (const Ray& ray : raysAtVertexCircles(closed.points, random, count)) {
        ++fired;
        if (intersect(shape, ray)) continue;
        ++leaks;
        if (++reported <= 3) {
          ADD_FAILURE() << "leak: o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                        << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << ")";
        }
      }
    }
    std::printf("seams, %s: %zu rays from inside at vertex circles, %zu leaks\n", variant.name, fired, leaks);
    EXPECT_EQ(leaks, 0u) << variant.name;
    if (variant.raysPerProfile == defaultRays) {
      EXPECT_GE(fired, testing::scaledRays(10'000'000));
    }
  }
}

}  // namespace
}  // namespace revolve
