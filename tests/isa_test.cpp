// The per-ray code is compiled once per instruction set (src/util/isa.h): every copy must give the
// same answers bit for bit, whichever one the CPU picks.
#include <revolve/baselines.h>
#include "shape/query_kernels.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace revolve {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameHit(const Hit& a, const Hit& b) {
  return sameBits(a.t, b.t) && sameBits(a.u, b.u) && sameBits(a.v, b.v) && a.segment == b.segment &&
         sameBits(a.normal.x, b.normal.x) && sameBits(a.normal.y, b.normal.y) && sameBits(a.normal.z, b.normal.z);
}

TEST(IsaTest, EveryInstructionSetGivesTheSameHitsBitForBit) {
  const detail::QueryKernels* baseline = detail::queryKernelsFor(detail::Isa::sse2);
  const detail::QueryKernels* avx2 = detail::queryKernelsFor(detail::Isa::avx2);
  ASSERT_NE(baseline, nullptr);
  if (avx2 == nullptr) GTEST_SKIP() << "this CPU has no AVX2: only the baseline copy runs here";
  std::mt19937_64 random(20240);
  std::size_t hits = 0;
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    for (const BuildOptions options :
         {BuildOptions{}, BuildOptions{.method = Method::linear}, BuildOptions{.method = Method::kajiya},
          BuildOptions{.method = Method::mibit, .shell = ShellKind::hybrid}}) {
      const Shape shape(Profile(named.points), options);
      std::vector<Ray> rays = testing::incoherentRays(shape, random, 3000);
      const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 1000);
      rays.insert(rays.end(), awkward.begin(), awkward.end());
      for (const Ray& ray : rays) {
        Stats statsA, statsB;
        const std::optional<Hit> a = baseline->intersect(detail::implOf(shape), ray, &statsA);
        const std::optional<Hit> b = avx2->intersect(detail::implOf(shape), ray, &statsB);
        ASSERT_EQ(a.has_value(), b.has_value()) << named.name;
        ASSERT_EQ(baseline->occluded(detail::implOf(shape), ray, nullptr),
                  avx2->occluded(detail::implOf(shape), ray, nullptr))
            << named.name;
        EXPECT_EQ(statsA.quadratics, statsB.quadratics) << named.name;
        if (!a) continue;
        ++hits;
        ASSERT_TRUE(sameHit(*a, *b)) << named.name << ": t " << a->t << " vs " << b->t;
        const std::optional<Hit> c = baseline->attributes(detail::implOf(shape), ray, a->segment, a->t);
        const std::optional<Hit> d = avx2->attributes(detail::implOf(shape), ray, a->segment, a->t);
        ASSERT_TRUE(c && d && sameHit(*c, *d)) << named.name << ": surfaceAttributes";
      }
    }
  }
  EXPECT_GT(hits, 10000u);
}

TEST(IsaTest, SplineShapesGiveTheSameHitsBitForBit) {
  const detail::QueryKernels* baseline = detail::queryKernelsFor(detail::Isa::sse2);
  const detail::QueryKernels* avx2 = detail::queryKernelsFor(detail::Isa::avx2);
  ASSERT_NE(baseline, nullptr);
  if (avx2 == nullptr) GTEST_SKIP() << "this CPU has no AVX2: only the baseline copy runs here";
  std::mt19937_64 random(20241);
  std::size_t hits = 0;
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Shape shape(Spline(named.kind, named.points));
    std::vector<Ray> rays = testing::incoherentRays(shape, random, 2000);
    const std::vector<Ray> awkward = testing::axisAlignedRays(shape, random, 500);
    rays.insert(rays.end(), awkward.begin(), awkward.end());
    for (const Ray& ray : rays) {
      const std::optional<Hit> a = baseline->intersect(detail::implOf(shape), ray, nullptr);
      const std::optional<Hit> b = avx2->intersect(detail::implOf(shape), ray, nullptr);
      ASSERT_EQ(a.has_value(), b.has_value()) << named.name;
      ASSERT_EQ(baseline->occluded(detail::implOf(shape), ray, nullptr),
                avx2->occluded(detail::implOf(shape), ray, nullptr))
          << named.name;
      if (!a) continue;
      ++hits;
      ASSERT_TRUE(sameHit(*a, *b)) << named.name << ": t " << a->t << " vs " << b->t;
      const std::optional<Hit> c = baseline->attributes(detail::implOf(shape), ray, a->segment, a->t);
      const std::optional<Hit> d = avx2->attributes(detail::implOf(shape), ray, a->segment, a->t);
      ASSERT_TRUE(c && d && sameHit(*c, *d)) << named.name << ": surfaceAttributes";
    }
  }
  EXPECT_GT(hits, 10000u);
}

}  // namespace
}  // namespace revolve
