// The library against the long-double brute-force oracle on every standard profile: hit or miss,
// distance, segment and normal. Disagreements are allowed only where the oracle itself changes its
// verdict under a 1e-9 nudge of the ray (a silhouette, an edge or a seam within rounding).
#include "support/reference.h"
#include "support/test_profiles.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace revolve {
namespace {

reference::RefRay toRef(const Ray& ray) {
  return {ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z, ray.tnear, ray.tfar};
}

double norm(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

TEST(ReferenceAgreementTest, MatchesTheLongDoubleOracleOnEveryStandardProfile) {
  constexpr std::uint64_t kSeed = 0x0dd1;
  std::mt19937_64 random(kSeed);
  std::size_t compared = 0, fragileIncoherent = 0, fragileAwkward = 0;
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    SCOPED_TRACE(named.name + ", seed " + std::to_string(kSeed));
    const Shape shape{Profile(named.points)};
    const double size = norm(shape.bounds().upper);
    constexpr std::size_t kIncoherent = 8000;
    std::vector<Ray> rays = testing::incoherentRays(shape, random, kIncoherent);
    const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 2000);
    rays.insert(rays.end(), awkward.begin(), awkward.end());
    int reported = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Ray& ray = rays[i];
      const std::optional<Hit> got = intersect(shape, ray);
      const std::optional<reference::RefHit> expected = reference::intersectProfile(named.points, toRef(ray));
      const bool sameVerdict = got.has_value() == expected.has_value();
      const bool sameDistance =
          !got || !expected ||
          std::abs(got->t - double(expected->t)) * norm(ray.direction) <= 0x1p-22 * (std::abs(got->t) * norm(ray.direction) + size);
      if (sameVerdict && sameDistance) {
        ++compared;
        if (got && got->segment == expected->segment) {
          // Same segment: the same normal, up to float rounding and the azimuth's conditioning
          // near the axis.
          if (std::hypot(got->point.x, got->point.y) > 1e-3 * size) {
            EXPECT_NEAR(got->normal.x, double(expected->nx), 1e-5);
            EXPECT_NEAR(got->normal.y, double(expected->ny), 1e-5);
            EXPECT_NEAR(got->normal.z, double(expected->nz), 1e-5);
          }
        }
        continue;
      }
      if (reference::verdictIsFragile(named.points, toRef(ray), 1e-9L * size, size)) {
        ++(i < kIncoherent ? fragileIncoherent : fragileAwkward);
        continue;
      }
      if (++reported <= 5) {
        ADD_FAILURE() << "o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=(" << ray.direction.x
                      << ", " << ray.direction.y << ", " << ray.direction.z << ") [" << ray.tnear << ", " << ray.tfar
                      << "]: oracle " << (expected ? "t=" + std::to_string(double(expected->t)) : std::string("miss"))
                      << ", library " << (got ? "t=" + std::to_string(got->t) : std::string("miss"));
      }
    }
  }
  EXPECT_GE(compared, 110000u);
  // Among random rays, fragile cases are rounding-level coincidences: a handful, not a habit. The
  // awkward rays aim at vertex heights and the axis, edges by design, so they are only reported.
  EXPECT_LE(fragileIncoherent, 24u);
  std::printf("compared %zu; fragile disagreements: %zu incoherent, %zu awkward\n", compared, fragileIncoherent, fragileAwkward);
}

}  // namespace
}  // namespace revolve
