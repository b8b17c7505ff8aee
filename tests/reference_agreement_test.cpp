// The library against the long-double brute-force oracle on every standard profile: hit or miss,
// distance, segment and normal. Disagreements are allowed only where the oracle itself changes its
// verdict under a 1e-9 nudge of the ray (a silhouette, a rim or an apex within rounding), and
// their number is bounded.
#include "support/reference.h"
#include "support/test_profiles.h"
#include "support/test_seeds.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace revolve {
namespace {

reference::RefRay toRef(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

double norm(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

TEST(ReferenceAgreementTest, MatchesTheLongDoubleOracleOnEveryStandardProfile) {
  for (const std::uint64_t seed : testing::testSeeds({0x0dd1})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::size_t compared = 0;
    for (const testing::NamedProfile& named : testing::standardProfiles()) {
      SCOPED_TRACE(named.name);
      const Shape shape{Profile(named.points)};
      const double size = norm(shape.bounds().upper);
      std::vector<Ray> rays = testing::incoherentRays(shape, random, 8000);
      // Half of these lie in a vertex's plane or aim at a vertex's height on the axis: compared
      // like any other ray, the oracle applying the half-open rule.
      const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 2000);
      rays.insert(rays.end(), awkward.begin(), awkward.end());
      std::size_t nearApex = 0, elsewhere = 0;
      int reported = 0;
      for (const Ray& ray : rays) {
        const std::optional<Hit> got = intersect(shape, ray);
        const std::optional<reference::RefHit> expected = reference::intersectProfile(named.points, toRef(ray));
        const bool sameVerdict = got.has_value() == expected.has_value();
        const bool sameDistance = !got || !expected ||
                                  std::abs(got->t - double(expected->t)) * norm(ray.direction) <=
                                      0x1p-22 * (std::abs(got->t) * norm(ray.direction) + size);
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
        // A disagreement is excused only where the exact answer is ambiguous at the rounding level:
        // the oracle's own verdict changes under a 1e-9 nudge of the ray (a ray in a vertex's plane
        // nudged within it, where the half-open rule decides).
        if (reference::verdictIsFragile(named.points, toRef(ray), 1e-9L * size, size)) {
          ++(reference::passesNearAnApex(named.points, toRef(ray), 1e-9L * size) ? nearApex : elsewhere);
          continue;
        }
        if (++reported <= 5) {
          ADD_FAILURE() << "o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                        << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << ") [" << ray.tnear
                        << ", " << ray.tfar << "]: oracle "
                        << (expected ? "t=" + std::to_string(double(expected->t)) : std::string("miss")) << ", library "
                        << (got ? "t=" + std::to_string(got->t) : std::string("miss"));
        }
      }
      // The excuses, bounded. Elsewhere than at an apex (within 1e-9 of a silhouette or a rim,
      // where the library too must err by rounding to disagree) a random ray lands with
      // probability far below 1e-6: more than one such excuse in a profile means the excuse hides
      // a wrong answer. At an apex: the rays through the axis aimed at an apex's height (an eighth
      // of the awkward rays, times the apexes' share of the vertex heights) pass it within the
      // rounding of their direction, often exactly, and the touch there flips under a nudge; the
      // kernel misses many exact touches at shallow slopes (|dz| below a few percent of |d|: its
      // touch point is clamped to the apex's plane, whose crossing rounds by about u R / |dz|,
      // beyond the touch's tolerance). Measured: at most 3 a profile, on the open cone (half its
      // vertex heights an apex's), over 40 seeds.
      EXPECT_LE(elsewhere, 1u);
      EXPECT_LE(nearApex, 4u);
      std::printf("%s: %zu disagreements excused near an apex, %zu elsewhere\n", named.name.c_str(), nearApex,
                  elsewhere);
    }
    EXPECT_GE(compared, 119000u);
  }
}

}  // namespace
}  // namespace revolve
