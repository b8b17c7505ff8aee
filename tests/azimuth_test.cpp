// u = atan2(y, x) / 2 pi, computed by a polynomial (src/util/azimuth.h), against long double atan2.
#include "util/azimuth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace revolve {
namespace {

// Distance in float ulps between u and the exact fraction, measured the short way round the
// circle (u = 0 and u just below 1 are neighbours).
double ulpsFromExact(float u, long double x, long double y) {
  long double exact = std::atan2(y, x) / (2.0L * 3.141592653589793238462643383279502884L);
  if (exact < 0) exact += 1;
  long double difference = std::abs(static_cast<long double>(u) - exact);
  difference = std::min(difference, 1 - difference);
  const long double ulp = std::max(std::nextafter(float(exact), 2.0f) - float(exact), 0x1p-149f);
  return double(difference / ulp);
}

TEST(AzimuthTest, FractionIsWithinOneFloatUlpOfAtan2) {
  std::mt19937_64 random(0xa71);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  double worst = 0.0;
  for (int i = 0; i < 2'000'000; ++i) {
    double x = normal(random), y = normal(random);
    if (i % 4 == 1) y *= std::pow(2.0, exponent(random) / 10.0);  // near the x axis: tiny u, or u near 1
    if (i % 4 == 2) x *= std::pow(2.0, exponent(random) / 10.0);  // near the y axis
    if (i % 4 == 3) {                                             // any scale
      const double scale = std::pow(2.0, exponent(random));
      x *= scale, y *= scale;
    }
    const float u = detail::azimuthFraction(x, y);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    const double ulps = ulpsFromExact(u, x, y);
    worst = std::max(worst, ulps);
    ASSERT_LE(ulps, 1.0) << "x = " << x << ", y = " << y << ": u = " << u;
  }
  std::printf("azimuth fraction: worst %.3f float ulps from long double atan2 over 2 million points\n", worst);
}

TEST(AzimuthTest, FractionIsExactOnTheAxesAndZeroOnTheZAxis) {
  EXPECT_EQ(detail::azimuthFraction(1.0, 0.0), 0.0f);
  EXPECT_EQ(detail::azimuthFraction(0.0, 2.0), 0.25f);
  EXPECT_EQ(detail::azimuthFraction(-3.0, 0.0), 0.5f);
  EXPECT_EQ(detail::azimuthFraction(0.0, -4.0), 0.75f);
  EXPECT_EQ(detail::azimuthFraction(0.0, 0.0), 0.0f);
  EXPECT_EQ(detail::azimuthFraction(1.0, -1e-300), 0.0f);  // just below 2 pi: the same azimuth as 0
}

}  // namespace
}  // namespace revolve
