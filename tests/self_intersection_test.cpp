// Tests of the exact orientation predicate and of the polyline self-intersection sweep.
//
// Expected answers come from sources independent of the code under test: exact integer arithmetic
// (__int128, or a small big-integer sum for arbitrary doubles), symmetry and scaling laws, and
// geometry reasoned out by hand.
#include "profile/self_intersection.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "profile/exact_predicates.h"

namespace revolve::detail {
namespace {

__extension__ using Int = __int128;  // exact reference arithmetic
__extension__ using UInt = unsigned __int128;

int signOf(Int x) { return (x > 0) - (x < 0); }

// ---------------------------------------------------------------------------------------------
// Independent exact references for orientation.

struct IntPoint {
  Int r;
  Int z;
};

int exactIntegerOrient(IntPoint a, IntPoint b, IntPoint c) {
  return signOf((b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r));
}

// Converts a double that must be an integer (after the caller's scaling) to __int128.
Int toInt(double x) {
  EXPECT_EQ(x, std::trunc(x));
  EXPECT_LT(std::abs(x), 0x1p100);
  return static_cast<Int>(x);
}

// Exact orientation of arbitrary finite doubles by plain big-integer arithmetic: every double is
// m * 2^e with an integer m < 2^53 and e >= -1074, so every product x * y is an integer multiple of
// 2^-2148, and the determinant a.r b.z - a.r c.z + ... is summed as such, positive and negative
// parts apart, in 32-bit limbs.
class BigDeterminant {
 public:
  void addProduct(double x, double y, int sign) {
    if (x == 0 || y == 0) return;
    int xExponent = 0;
    int yExponent = 0;
    const auto xMantissa = static_cast<std::int64_t>(std::ldexp(std::frexp(x, &xExponent), 53));
    const auto yMantissa = static_cast<std::int64_t>(std::ldexp(std::frexp(y, &yExponent), 53));
    if ((xMantissa < 0) != (yMantissa < 0)) sign = -sign;
    const UInt magnitude = static_cast<UInt>(std::llabs(xMantissa)) * std::llabs(yMantissa);
    // value = magnitude * 2^(xExponent + yExponent - 106); shift so the smallest case is bit 0.
    const int shift = xExponent + yExponent - 106 + kOffset;
    addShifted(sign > 0 ? positive_ : negative_, magnitude, shift);
  }

  int sign() const {
    for (std::size_t i = kLimbs; i-- > 0;) {
      if (positive_[i] != negative_[i]) return positive_[i] > negative_[i] ? 1 : -1;
    }
    return 0;
  }

 private:
  static constexpr int kOffset = 2252;        // smallest e_x + e_y - 106 is -2146 - 106
  static constexpr std::size_t kLimbs = 150;  // 4800 bits > 2048 - 106 + kOffset + 106 + carries
  using Limbs = std::array<std::uint32_t, kLimbs>;

  // limbs += value * 2^shift, value < 2^106, fed in 32-bit pieces.
  static void addShifted(Limbs& limbs, UInt value, int shift) {
    ASSERT_GE(shift, 0);
    std::size_t limb = static_cast<std::size_t>(shift) / 32;
    const int bitShift = shift % 32;
    UInt carry = 0;
    while (value != 0 || carry != 0) {
      ASSERT_LT(limb, kLimbs);
      const auto piece = static_cast<UInt>(static_cast<std::uint32_t>(value)) << bitShift;
      value >>= 32;
      const UInt sum = limbs[limb] + piece + carry;
      limbs[limb] = static_cast<std::uint32_t>(sum);
      carry = sum >> 32;
      ++limb;
    }
  }

  Limbs positive_{};
  Limbs negative_{};
};

int bigOrient(Point2 a, Point2 b, Point2 c) {
  BigDeterminant determinant;
  determinant.addProduct(a.r, b.z, +1);
  determinant.addProduct(a.r, c.z, -1);
  determinant.addProduct(b.r, c.z, +1);
  determinant.addProduct(b.r, a.z, -1);
  determinant.addProduct(c.r, a.z, +1);
  determinant.addProduct(c.r, b.z, -1);
  return determinant.sign();
}

int naiveOrient(Point2 a, Point2 b, Point2 c) {
  const double determinant = (b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r);
  return (determinant > 0) - (determinant < 0);
}

Point2 scaled(Point2 p, int rExponent, int zExponent) {
  return {std::ldexp(p.r, rExponent), std::ldexp(p.z, zExponent)};
}

// ---------------------------------------------------------------------------------------------
// OrientTest

TEST(OrientTest, BasicTurns) {
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), 1);  // counter-clockwise
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0);
  EXPECT_EQ(orient2d({1, 2}, {1, 2}, {3, 4}), 0);  // repeated point
  EXPECT_EQ(orient2d({1, 2}, {3, 4}, {1, 2}), 0);
  EXPECT_EQ(orient2d({5, 5}, {5, 5}, {5, 5}), 0);
}

// Points (k * step.r + base.r, k * step.z + base.z) for small integers k, all exactly
// representable, lie on one line; one unit in the last place off the line they do not.
TEST(OrientTest, ExactlyRepresentableLines) {
  for (const int exponent : {-1074, -1060, -600, -52, 0, 40, 600, 960}) {
    SCOPED_TRACE("scale 2^" + std::to_string(exponent));
    const auto at = [&](double k) { return Point2{std::ldexp(3 + 7 * k, exponent), std::ldexp(-5 + 2 * k, exponent)}; };
    for (int i = -4; i <= 4; ++i) {
      EXPECT_EQ(orient2d(at(-9), at(13), at(i)), 0);
      EXPECT_EQ(orient2d(at(i), at(-9), at(13)), 0);
      EXPECT_EQ(orient2d(at(13), at(i), at(-9)), 0);
    }
    // Line direction (7, 2) points to growing r, so larger z is to the left.
    const Point2 onLine = at(3);
    const Point2 above{onLine.r, std::nextafter(onLine.z, 1e308)};
    const Point2 below{onLine.r, std::nextafter(onLine.z, -1e308)};
    EXPECT_EQ(orient2d(at(-9), at(13), above), 1);
    EXPECT_EQ(orient2d(at(-9), at(13), below), -1);
    EXPECT_EQ(orient2d(at(13), at(-9), above), -1);
  }
}

// The classic near-degenerate family (Kettner et al., "Classroom examples of robustness
// problems"): a point within a few ulps of the line through (12, 12) and (24, 24). Exact answers
// from __int128 after scaling by 2^53, which makes every coordinate an integer.
TEST(OrientTest, NaiveDeterminantGetsNearDegenerateSignsWrong) {
  const Point2 b{12, 12};
  const Point2 c{24, 24};
  int naiveWrong = 0;     // naive sign differs from the exact one
  int naiveOpposite = 0;  // ... and is the opposite nonzero sign
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Point2 a{0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53};
      const auto integer = [](Point2 p) { return IntPoint{toInt(std::ldexp(p.r, 53)), toInt(std::ldexp(p.z, 53))}; };
      const int exact = exactIntegerOrient(integer(a), integer(b), integer(c));
      ASSERT_EQ(orient2d(a, b, c), exact) << "i=" << i << " j=" << j;
      ASSERT_EQ(orient2d(b, c, a), exact) << "i=" << i << " j=" << j;
      ASSERT_EQ(orient2d(c, a, b), exact) << "i=" << i << " j=" << j;
      ASSERT_EQ(orient2d(b, a, c), -exact) << "i=" << i << " j=" << j;
      const int naive = naiveOrient(a, b, c);
      naiveWrong += naive != exact;
      if (naive == -exact && exact != 0 && naiveOpposite++ == 0) {
        std::printf("naive determinant says %d, exact answer %d, for a = (%a, %a)\n", naive, exact, a.r, a.z);
      }
    }
  }
  EXPECT_GT(naiveOpposite, 0) << "the naive determinant was expected to get a sign backwards";
  RecordProperty("naive_wrong_of_4096", naiveWrong);
  // Points on the diagonal itself are exactly collinear with b and c.
  const Point2 onDiagonal{0.5 + 17 * 0x1p-53, 0.5 + 17 * 0x1p-53};
  EXPECT_EQ(orient2d(onDiagonal, b, c), 0);
}

// Differences between coordinates overflow (2 * 1.5e308 > DBL_MAX), products more so.
TEST(OrientTest, HugeCoordinatesWhoseDifferencesOverflow) {
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orient2d({-big, 0}, {big, 0}, {0, tiny}), 1);
  EXPECT_EQ(orient2d({-big, 0}, {big, 0}, {0, -tiny}), -1);
  EXPECT_EQ(orient2d({-big, 0}, {big, 0}, {1e300, 0}), 0);
  EXPECT_EQ(orient2d({-big, -big}, {big, big}, {3, 3}), 0);
  EXPECT_EQ(orient2d({-big, -big}, {big, big}, {3, std::nextafter(3.0, 4.0)}), 1);
  EXPECT_EQ(orient2d({-big, -big}, {big, big}, {tiny, 0}), -1);
  EXPECT_EQ(orient2d({-big, -big}, {big, big}, {-big, std::nextafter(-big, 0.0)}), 1);
}

// a = (t, 2t) and c = (2t, 3t) lie on z = r + t, b = (H, H) on z = r. Expanding,
// D = (H - t)(t) - (H - 2t)(t) = t^2: its sign hinges on a product far below the smallest double.
TEST(OrientTest, SignDecidedBelowTheUnderflowThreshold) {
  for (const double t : {0x1p-1000, 0x1p-1070, 0x1.8p-990}) {  // 2t and 3t exact
    for (const double huge : {0x1p1000, 1e300, 1.0}) {
      EXPECT_EQ(orient2d({t, 2 * t}, {huge, huge}, {2 * t, 3 * t}), 1);
      EXPECT_EQ(orient2d({2 * t, t}, {huge, huge}, {3 * t, 2 * t}), -1);
      EXPECT_EQ(orient2d({t, t}, {huge, huge}, {2 * t, 2 * t}), 0);
    }
  }
}

// Denormal inputs: integer multiples of 2^-1074, compared against the integers themselves.
TEST(OrientTest, DenormalCoordinates) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<int> coordinate(-5000, 5000);
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<IntPoint, 3> integer{};
    std::array<Point2, 3> point{};
    for (int k = 0; k < 3; ++k) {
      integer[k] = {coordinate(random), coordinate(random)};
      point[k] = {std::ldexp(static_cast<double>(integer[k].r), -1074),
                  std::ldexp(static_cast<double>(integer[k].z), -1074)};
    }
    ASSERT_EQ(orient2d(point[0], point[1], point[2]), exactIntegerOrient(integer[0], integer[1], integer[2]))
        << "trial " << trial;
  }
}

// Random small integers, each coordinate scaled by its own power of two within a window of 40, the
// window itself anywhere from denormals to near overflow; r and z scaled independently (which
// keeps the sign: D scales by a positive factor). Reference: __int128 on the unscaled integers.
TEST(OrientTest, MatchesInt128OnScaledSmallIntegers) {
  const std::uint64_t seed = 20240611;
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> mantissa(-(1 << 20), 1 << 20);
  std::uniform_int_distribution<int> smallCoordinate(-3, 3);
  std::uniform_int_distribution<int> localExponent(0, 40);
  std::uniform_int_distribution<int> windowExponent(-1074, 1023 - 62);
  int zeros = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
    const bool degenerate = trial % 2 == 0;  // tiny coordinates: many collinear triples
    const int rWindow = windowExponent(random);
    const int zWindow = trial % 3 == 0 ? rWindow : windowExponent(random);
    std::array<IntPoint, 3> integer{};
    std::array<Point2, 3> point{};
    for (int k = 0; k < 3; ++k) {
      const int rShift = degenerate ? 0 : localExponent(random);
      const int zShift = degenerate ? 0 : localExponent(random);
      const int rValue = degenerate ? smallCoordinate(random) : mantissa(random);
      const int zValue = degenerate ? smallCoordinate(random) : mantissa(random);
      integer[k] = {static_cast<Int>(rValue) << rShift, static_cast<Int>(zValue) << zShift};
      point[k] = {std::ldexp(static_cast<double>(rValue), rShift + rWindow),
                  std::ldexp(static_cast<double>(zValue), zShift + zWindow)};
    }
    const int expected = exactIntegerOrient(integer[0], integer[1], integer[2]);
    zeros += expected == 0;
    ASSERT_EQ(orient2d(point[0], point[1], point[2]), expected);
  }
  EXPECT_GT(zeros, 10000);  // the degenerate half is rich in exactly collinear triples
}

// Collinear triples far beyond __int128: c = a + k (b - a) with small integer parts, then r and z
// scaled independently anywhere in the double range, so |r| and |z| differ by up to 2^2000.
TEST(OrientTest, CollinearAcrossTheWholeExponentRange) {
  std::mt19937_64 random(99);
  std::uniform_int_distribution<int> small(-50, 50);
  std::uniform_int_distribution<int> exponent(-1074, 1000);
  for (int trial = 0; trial < 20000; ++trial) {
    const IntPoint a{small(random), small(random)};
    const IntPoint d{small(random), small(random)};
    const int k = small(random);
    const IntPoint b{a.r + d.r, a.z + d.z};
    const IntPoint c{a.r + k * d.r, a.z + k * d.z};
    const int rExponent = exponent(random);
    const int zExponent = exponent(random);
    const auto toPoint = [&](IntPoint p) {
      return scaled({static_cast<double>(p.r), static_cast<double>(p.z)}, rExponent, zExponent);
    };
    // Shift c by one unit of the integer grid: off the line unless d is zero in that direction.
    const IntPoint cUp{c.r, c.z + 1};
    ASSERT_EQ(orient2d(toPoint(a), toPoint(b), toPoint(c)), 0) << "trial " << trial;
    ASSERT_EQ(orient2d(toPoint(a), toPoint(b), toPoint(cUp)), exactIntegerOrient(a, b, cUp)) << "trial " << trial;
  }
}

// A double drawn from a mix of raw bit patterns (any exponent), special magnitudes and a few
// repeated values (which make equal coordinates and degenerate triples common).
double interestingDouble(std::mt19937_64& random) {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
  static constexpr std::array<double, 12> kPool = {0.0,        -0.0,      1.0,    -1.0,  0.5,  3.0,
                                                   kDenormMin, 0x1p-1022, 1e-300, 1e300, kMax, -kMax};
  switch (random() % 3) {
    case 0:
      return kPool[random() % kPool.size()] * ((random() & 1) ? 1 : -1);
    case 1: {
      const std::uint64_t bits = random() & ~(std::uint64_t{0x7ff} << 52);  // exponent != 0x7ff
      const std::uint64_t exponent = random() % 0x7ff;
      return std::bit_cast<double>(bits | (exponent << 52));
    }
    default:
      return std::ldexp(static_cast<double>(static_cast<int>(random() % 9) - 4),
                        static_cast<int>(random() % 2095) - 1074);  // 4 * 2^1020 is finite
  }
}

// Arbitrary finite doubles against the big-integer reference, plus the symmetry laws.
TEST(OrientTest, MatchesBigIntegerReferenceOnArbitraryDoubles) {
  const std::uint64_t seed = 31337;
  std::mt19937_64 random(seed);
  int zeros = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
    Point2 a{interestingDouble(random), interestingDouble(random)};
    Point2 b{interestingDouble(random), interestingDouble(random)};
    Point2 c{interestingDouble(random), interestingDouble(random)};
    if (trial % 4 == 0) b.r = a.r;  // shared coordinates: more cancellation
    if (trial % 5 == 0) c.z = b.z;
    const int expected = bigOrient(a, b, c);
    zeros += expected == 0;
    ASSERT_EQ(orient2d(a, b, c), expected);
    ASSERT_EQ(orient2d(b, c, a), expected);
    ASSERT_EQ(orient2d(c, a, b), expected);
    ASSERT_EQ(orient2d(b, a, c), -expected);
    ASSERT_EQ(orient2d({a.z, a.r}, {b.z, b.r}, {c.z, c.r}), -expected);  // mirror image
  }
  EXPECT_GT(zeros, 1000);
}

// Nearly collinear triples with full 53-bit mantissas, where the floating-point filter cannot
// decide and every bit of the exact stage matters: c is the rounded point a + t (b - a), nudged by
// a few ulps, with a and b drawn within a window of exponents placed anywhere in the double range.
TEST(OrientTest, NearlyCollinearFullPrecisionTriplesMatchBigIntegerReference) {
  const std::uint64_t seed = 5150;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> parameter(-2.0, 3.0);
  std::uniform_int_distribution<int> window(-1074, 900);  // + spread keeps |c| < 2^964
  std::uniform_int_distribution<int> spread(0, 60);
  std::uniform_int_distribution<int> nudge(-3, 3);
  const auto step = [](double x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, 1e308);
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -1e308);
    return x;
  };
  int zeros = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
    const int base = window(random);
    const auto coordinate = [&] { return std::ldexp(unit(random), base + spread(random)); };
    const Point2 a{coordinate(), coordinate()};
    const Point2 b{coordinate(), coordinate()};
    const double t = parameter(random);
    Point2 c{a.r + t * (b.r - a.r), a.z + t * (b.z - a.z)};
    c = {step(c.r, nudge(random)), step(c.z, nudge(random))};
    ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.z));
    const int expected = bigOrient(a, b, c);
    zeros += expected == 0;
    ASSERT_EQ(orient2d(a, b, c), expected);
    ASSERT_EQ(orient2d(b, c, a), expected);
    ASSERT_EQ(orient2d(c, a, b), expected);
    ASSERT_EQ(orient2d(c, b, a), -expected);
  }
  RecordProperty("exactly_collinear", zeros);
}

// The big-integer reference itself, on triples whose answer is known by construction.
TEST(OrientTest, BigIntegerReferenceSanity) {
  EXPECT_EQ(bigOrient({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(bigOrient({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(bigOrient({0x1p-1070, 0x1p-1069}, {0x1p1000, 0x1p1000}, {0x1p-1069, 0x1.8p-1069}), 1);
  EXPECT_EQ(bigOrient({-1e308, -1e308}, {1e308, 1e308}, {1e-320, 1e-320}), 0);
}

// ---------------------------------------------------------------------------------------------
// SelfIntersectionTest: hand-made degeneracies.

std::optional<SegmentPair> find(std::initializer_list<Point2> points) {
  const std::vector<Point2> polyline(points);
  return findSelfIntersection(polyline);
}

bool isPair(const std::optional<SegmentPair>& found, std::size_t first, std::size_t second) {
  return found && found->first == first && found->second == second;
}

// Whether `found` is one of the listed pairs (when several pairs are at fault).
bool isOneOf(const std::optional<SegmentPair>& found,
             std::initializer_list<std::pair<std::size_t, std::size_t>> pairs) {
  return found && std::any_of(pairs.begin(), pairs.end(),
                              [&](auto pair) { return found->first == pair.first && found->second == pair.second; });
}

TEST(SelfIntersectionTest, SingleSegmentNeverIntersects) { EXPECT_FALSE(find({{0, 0}, {1, 1}})); }

TEST(SelfIntersectionTest, SimpleOpenPathIsAccepted) { EXPECT_FALSE(find({{1, 0}, {2, 1}, {2, 3}, {1, 4}, {0.5, 6}})); }

// Neighbours share their common vertex, even at sharp turns where both leave it to the same side.
TEST(SelfIntersectionTest, NeighboursMayShareTheirVertex) {
  EXPECT_FALSE(find({{0, 0}, {1, 5}, {2, 0}}));  // both segments end at (1, 5) in sweep order
  EXPECT_FALSE(find({{1, 0}, {0, 5}, {2, 5}}));  // both start at (0, 5)
  EXPECT_FALSE(find({{0, 0}, {5, 1}, {0, 2}}));  // a hairpin, but not collinear
}

TEST(SelfIntersectionTest, CollinearContinuationIsAccepted) {
  EXPECT_FALSE(find({{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
  EXPECT_FALSE(find({{0, 0}, {0, 1}, {0, 2}}));
  EXPECT_FALSE(find({{0, 0}, {1, 1}, {3, 3}, {4, 4}}));
}

// (0,0)->(2,0)->(1,0): the second segment runs back over the first on [1, 2].
TEST(SelfIntersectionTest, FoldBackOfNeighboursIsAnIntersection) {
  EXPECT_TRUE(isPair(find({{0, 0}, {2, 0}, {1, 0}}), 0, 1));
  EXPECT_TRUE(isPair(find({{1, 0}, {2, 0}, {0, 0}}), 0, 1));  // folds back past the start
  EXPECT_TRUE(isPair(find({{0, 0}, {0, 2}, {0, 1}}), 0, 1));  // vertical
  EXPECT_TRUE(isPair(find({{3, 3}, {1, 1}, {2, 2}}), 0, 1));  // diagonal, folding at the left
  // Exact retrace of segment 2; its end (7, 0) is also vertex 2, touched by segment 1.
  EXPECT_TRUE(isOneOf(find({{5, 0}, {6, 1}, {7, 0}, {8, 1}, {7, 0}}), {{2, 3}, {1, 3}}));
}

TEST(SelfIntersectionTest, ProperCrossing) {
  // Segments 0 and 2 cross at (1, 1).
  EXPECT_TRUE(isPair(find({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), 0, 2));
  // A vertical segment crossing a horizontal one at (1, 0).
  EXPECT_TRUE(isPair(find({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, -1}}), 0, 3));
}

// A vertex lying in the interior of another segment.
TEST(SelfIntersectionTest, VertexOnAnotherSegmentIsAnIntersection) {
  // The last point (1, 0) lies inside segment 0.
  EXPECT_TRUE(isPair(find({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}}), 0, 3));
  // The interior vertex (2, 0) touches segment 0 from above: segments 3 and 4 both touch it.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 0}, {1, 2}}), {{0, 3}, {0, 4}}));
  // The end point (0, 2) lies inside the vertical segment 0.
  EXPECT_TRUE(isPair(find({{0, 0}, {0, 4}, {1, 4}, {1, 2}, {0, 2}}), 0, 3));
  // The first point lies inside a later vertical segment.
  EXPECT_TRUE(isPair(find({{1, 2}, {2, 2}, {2, 0}, {1, 0}, {1, 4}}), 0, 3));
}

TEST(SelfIntersectionTest, CollinearOverlapOfNonNeighbours) {
  // Segment 4 = (5,0)-(1,0) overlaps segment 0 = (0,0)-(2,0) on [1, 2]; segment 1 starts at
  // (2, 0), which lies inside segment 4.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {2, 0}, {2, 1}, {5, 1}, {5, 0}, {1, 0}}), {{0, 4}, {1, 4}}));
  // Vertical: segment 3 = (0,3)-(0,1) overlaps segment 0 = (0,0)-(0,2) on [1, 2] and contains
  // (0, 2), where segment 1 starts.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {0, 2}, {-1, 3}, {0, 3}, {0, 1}}), {{0, 3}, {1, 3}}));
  // Closed loop whose last segment retraces its first one: the closing pair may share only the
  // closing point. (2, 2) is also visited twice, by segments 0, 1, 5 and 6.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {2, 2}, {4, 0}, {6, 6}, {0, 6}, {0, 4}, {2, 2}, {0, 0}}),
                      {{0, 6}, {0, 5}, {1, 5}, {1, 6}}));
}

// Non-neighbouring segments that only touch at endpoints.
TEST(SelfIntersectionTest, RepeatedVertexIsAnIntersection) {
  // Figure-eight through (1, 1): segment 0 ends there, segments 2 and 3 start there, so no two of
  // the offenders are ever in the sweep status at the same time.
  EXPECT_TRUE(isOneOf(find({{1, 1}, {0, 0}, {2, 0}, {1, 1}, {2, 2}}), {{0, 2}, {0, 3}}));
  // Bow tie: (1, 1) visited twice, four segments meet there.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {1, 1}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}), {{0, 3}, {0, 4}, {1, 3}, {1, 4}}));
  // Two collinear segments meeting end to end without being neighbours.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 0}, {1, 0}}), {{0, 4}, {1, 4}}));
  // An open path ending at a vertex it passed before: segments 0, 1 and 3 meet at (2, 0).
  EXPECT_TRUE(isOneOf(find({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {2, 0}}), {{0, 3}, {1, 3}}));
}

TEST(SelfIntersectionTest, ClosedLoopMayShareItsClosingPoint) {
  EXPECT_FALSE(find({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}));
  EXPECT_FALSE(find({{0, 0}, {1, 0}, {0, 1}, {0, 0}}));                      // triangle
  EXPECT_FALSE(find({{1, 1}, {3, 0}, {2, 2}, {3, 4}, {1, 3}, {1, 1}}));      // closing at a side
  EXPECT_FALSE(find({{0.5, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {0.5, 0}}));  // closing mid-edge
}

// The first and last points coincide, so the first and last segments share that point; no other
// segment may pass through it, and the closing segments must not overlap.
TEST(SelfIntersectionTest, ClosingPointIsReservedForFirstAndLastSegments) {
  // Figure-eight through the closing point (0, 0), which is also visited in the middle.
  // Segments 0 and 5 may meet there (closing), 2 and 3 too (vertex 3), no other combination.
  EXPECT_TRUE(
      isOneOf(find({{0, 0}, {1, 1}, {1, -1}, {0, 0}, {-1, 1}, {-1, -1}, {0, 0}}), {{0, 2}, {0, 3}, {2, 5}, {3, 5}}));
  // Two points, there and back: the only two segments coincide.
  EXPECT_TRUE(isPair(find({{0, 0}, {1, 0}, {0, 0}}), 0, 1));
  // Degenerate triangle: the closing segment (2,0)-(0,0) runs over both others.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {1, 0}, {2, 0}, {0, 0}}), {{0, 2}, {1, 2}}));
  // The closing segment (1,0)-(0,0) runs back over segment 0 and segment 2 ends inside it.
  EXPECT_TRUE(isOneOf(find({{0, 0}, {2, 0}, {2, 1}, {1, 0}, {0, 0}}), {{0, 3}, {0, 2}}));
}

// Not closed (the ends differ), so the first and last segments must not meet at all.
TEST(SelfIntersectionTest, OpenPolylineReturningToItsStartIsAnIntersection) {
  EXPECT_TRUE(isOneOf(find({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {-1, 1}}), {{0, 2}, {0, 3}}));
}

// Coordinates 2^1000 next to 1e-300: the last point is one ulp above, on, or one ulp below the
// line z = r that carries segment 0, so segment 2 crosses, touches or misses it.
TEST(SelfIntersectionTest, ExtremeMagnitudesAreDecidedExactly) {
  const double huge = 0x1p1000;
  const double t = 1e-300;
  const double above = std::nextafter(t, 1.0);
  const double below = std::nextafter(t, 0.0);
  EXPECT_TRUE(isPair(find({{0, 0}, {huge, huge}, {huge, 0}, {t, above}}), 0, 2));  // crosses
  EXPECT_TRUE(isPair(find({{0, 0}, {huge, huge}, {huge, 0}, {t, t}}), 0, 2));      // touches
  EXPECT_FALSE(find({{0, 0}, {huge, huge}, {huge, 0}, {t, below}}));               // misses
  EXPECT_FALSE(find({{0, 0}, {huge, huge}, {huge, 0}, {t, below}, {0, 0}}));       // closed
}

TEST(SelfIntersectionTest, NegativeZeroIsTheSamePoint) {
  EXPECT_FALSE(find({{0.0, 0.0}, {1, 0}, {1, 1}, {-0.0, -0.0}}));  // closed loop
  EXPECT_TRUE(isPair(find({{0, 0}, {2, 0}, {2, 1}, {1, -0.0}}), 0, 2));
}

// ---------------------------------------------------------------------------------------------
// Randomized comparison with an O(n^2) brute force on integer grids (exact, __int128).

// A point given by rational coordinates (r / denominator, z / denominator), denominator > 0.
struct RationalPoint {
  Int r;
  Int z;
  Int denominator;
};

bool equals(RationalPoint p, IntPoint q) { return p.r == q.r * p.denominator && p.z == q.z * p.denominator; }

Int cross(IntPoint o, IntPoint a, IntPoint b) { return (a.r - o.r) * (b.z - o.z) - (a.z - o.z) * (b.r - o.r); }

// How two closed segments meet: not at all, in exactly one point, or along a stretch.
struct Meeting {
  enum Kind { kNone, kPoint, kStretch } kind = kNone;
  RationalPoint point{};
};

Meeting meet(IntPoint a, IntPoint b, IntPoint c, IntPoint d) {
  const IntPoint ab{b.r - a.r, b.z - a.z};
  const IntPoint cd{d.r - c.r, d.z - c.z};
  Int denominator = ab.r * cd.z - ab.z * cd.r;
  if (denominator != 0) {
    // a + t (b - a) = c + u (d - c) with t = tNumerator / denominator, u likewise.
    Int tNumerator = (c.r - a.r) * cd.z - (c.z - a.z) * cd.r;
    Int uNumerator = (c.r - a.r) * ab.z - (c.z - a.z) * ab.r;
    if (denominator < 0) {
      denominator = -denominator;
      tNumerator = -tNumerator;
      uNumerator = -uNumerator;
    }
    if (tNumerator < 0 || tNumerator > denominator || uNumerator < 0 || uNumerator > denominator) {
      return {};
    }
    return {Meeting::kPoint,
            {a.r * denominator + tNumerator * ab.r, a.z * denominator + tNumerator * ab.z, denominator}};
  }
  if (cross(a, b, c) != 0) return {};  // parallel lines
  // Collinear: intersect the projections onto an axis along which the line is not constant.
  const bool useR = ab.r != 0;
  const auto coordinate = [&](IntPoint p) { return useR ? p.r : p.z; };
  const Int low = std::max(std::min(coordinate(a), coordinate(b)), std::min(coordinate(c), coordinate(d)));
  const Int high = std::min(std::max(coordinate(a), coordinate(b)), std::max(coordinate(c), coordinate(d)));
  if (low > high) return {};
  if (low < high) return {Meeting::kStretch, {}};
  for (const IntPoint p : {a, b, c, d}) {
    if (coordinate(p) == low) return {Meeting::kPoint, {p.r, p.z, 1}};
  }
  return {};  // unreachable
}

// Whether segments i < j of the polyline share a point they must not share.
bool bruteForbidden(const std::vector<IntPoint>& p, std::size_t i, std::size_t j) {
  const std::size_t segments = p.size() - 1;
  const bool closed = p.front().r == p.back().r && p.front().z == p.back().z;
  const Meeting meeting = meet(p[i], p[i + 1], p[j], p[j + 1]);
  if (meeting.kind == Meeting::kNone) return false;
  if (meeting.kind == Meeting::kStretch) return true;
  const bool atSharedVertex = j == i + 1 && equals(meeting.point, p[i + 1]);
  const bool atClosingPoint = closed && i == 0 && j == segments - 1 && equals(meeting.point, p[0]);
  return !atSharedVertex && !atClosingPoint;
}

bool bruteHasIntersection(const std::vector<IntPoint>& p) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (std::size_t j = i + 1; j + 1 < p.size(); ++j) {
      if (bruteForbidden(p, i, j)) return true;
    }
  }
  return false;
}

// A random walk on a grid with no two consecutive points equal, sometimes closed.
std::vector<IntPoint> randomPolyline(std::mt19937_64& random) {
  static constexpr std::array<int, 5> kGridSizes = {2, 3, 5, 7, 40};
  const int grid = kGridSizes[random() % kGridSizes.size()];
  const bool axisAligned = random() % 4 == 0;  // many vertical and horizontal runs
  const std::size_t length = 2 + random() % (grid >= 7 ? 12 : 7);
  const auto coordinate = [&] { return static_cast<Int>(random() % grid); };
  std::vector<IntPoint> points{{coordinate(), coordinate()}};
  while (points.size() < length) {
    IntPoint next = {coordinate(), coordinate()};
    if (axisAligned) {
      if (random() & 1) {
        next.r = points.back().r;
      } else {
        next.z = points.back().z;
      }
    }
    if (next.r == points.back().r && next.z == points.back().z) continue;
    points.push_back(next);
  }
  const bool differentEnds = points.front().r != points.back().r || points.front().z != points.back().z;
  if (points.size() >= 3 && differentEnds && random() % 3 == 0) points.push_back(points.front());
  return points;
}

TEST(SelfIntersectionTest, MatchesBruteForceOnRandomGridPolylines) {
  const std::uint64_t seed = revolve::testing::testSeeds({424242}).front();
  std::mt19937_64 random(seed);
  static constexpr std::array<int, 4> kExponents = {0, -1064, 1000, -30};  // exact scalings
  int intersecting = 0;
  int clean = 0;
  int closedClean = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    SCOPED_TRACE(revolve::testing::seedTrace(seed) + ", trial " + std::to_string(trial));
    const std::vector<IntPoint> integer = randomPolyline(random);
    const int rExponent = kExponents[random() % kExponents.size()];
    const int zExponent = kExponents[random() % kExponents.size()];
    std::vector<Point2> points;
    for (const IntPoint p : integer) {
      points.push_back(scaled({static_cast<double>(p.r), static_cast<double>(p.z)}, rExponent, zExponent));
    }
    const bool expected = bruteHasIntersection(integer);
    const std::optional<SegmentPair> found = findSelfIntersection(points);
    ASSERT_EQ(found.has_value(), expected);
    if (found) {
      ASSERT_LT(found->first, found->second);
      ASSERT_LT(found->second, integer.size() - 1);
      ASSERT_TRUE(bruteForbidden(integer, found->first, found->second))
          << "reported pair " << found->first << ", " << found->second;
      ++intersecting;
    } else {
      ++clean;
      const bool closed = integer.front().r == integer.back().r && integer.front().z == integer.back().z;
      closedClean += closed;
    }
  }
  std::printf("seed %llu: %d intersecting, %d clean (%d closed)\n", static_cast<unsigned long long>(seed), intersecting,
              clean, closedClean);
  EXPECT_GT(intersecting, 5000);
  EXPECT_GT(clean, 5000);
  EXPECT_GT(closedClean, 500);
}

// A random walk monotone along one axis (z, or r, up or down), with runs across it: the shapes the
// sweep's shortcut for monotone profiles takes, and the near misses it must leave to the sweep (two
// runs in a row, which may fold back or overlap).
std::vector<IntPoint> randomMonotonePolyline(std::mt19937_64& random) {
  const int grid = 2 + int(random() % 6);
  const std::size_t length = 2 + random() % 10;
  const bool alongR = random() & 1, descending = random() & 1;
  const auto across = [&] { return static_cast<Int>(random() % grid); };
  std::vector<IntPoint> points{{across(), 0}};
  while (points.size() < length) {
    const Int step = random() % 3 == 0 ? 0 : Int(1 + random() % 2);  // 0: a run across the axis
    IntPoint next{across(), points.back().z + step};
    if (next.r == points.back().r && next.z == points.back().z) continue;
    points.push_back(next);
  }
  for (IntPoint& p : points) {
    if (descending) p.z = -p.z;
    if (alongR) std::swap(p.r, p.z);
  }
  return points;
}

TEST(SelfIntersectionTest, MatchesBruteForceOnRandomMonotonePolylines) {
  const std::uint64_t seed = revolve::testing::testSeeds({171717}).front();
  std::mt19937_64 random(seed);
  int intersecting = 0;
  int clean = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    SCOPED_TRACE(revolve::testing::seedTrace(seed) + ", trial " + std::to_string(trial));
    const std::vector<IntPoint> integer = randomMonotonePolyline(random);
    std::vector<Point2> points;
    // Shifted off the axis so that r >= 0 whichever axis the walk follows.
    for (const IntPoint p : integer) points.push_back({double(p.r) + 64.0, double(p.z)});
    const bool expected = bruteHasIntersection(integer);
    const std::optional<SegmentPair> found = findSelfIntersection(points);
    ASSERT_EQ(found.has_value(), expected);
    if (found) {
      ASSERT_TRUE(bruteForbidden(integer, found->first, found->second))
          << "reported pair " << found->first << ", " << found->second;
    }
    (found ? intersecting : clean) += 1;
  }
  std::printf("seed %llu: %d intersecting, %d clean\n", static_cast<unsigned long long>(seed), intersecting, clean);
  EXPECT_GT(intersecting, 5000);
  EXPECT_GT(clean, 5000);
}

// ---------------------------------------------------------------------------------------------
// Large inputs: must complete (O(n log n), no deep recursion); no time is asserted.

constexpr std::size_t kLargeCount = 1'000'000;

TEST(SelfIntersectionTest, MillionPointZigzagIsAccepted) {
  std::vector<Point2> points;
  points.reserve(kLargeCount);
  for (std::size_t i = 0; i < kLargeCount; ++i) {
    points.push_back({static_cast<double>(i), static_cast<double>(i % 2)});
  }
  EXPECT_FALSE(findSelfIntersection(points));
  // Closing the zigzag along a straight bottom edge keeps it simple.
  points.push_back({static_cast<double>(kLargeCount - 1), -1});
  points.push_back({0, -1});
  points.push_back({0, 0});
  EXPECT_FALSE(findSelfIntersection(points));
  // A final dip to the bottom edge is then caught.
  points.back() = {0, -0.5};
  points.push_back({1, -1});
  EXPECT_TRUE(findSelfIntersection(points));
}

// Square spiral: many segments are in the sweep status at once.
TEST(SelfIntersectionTest, MillionPointSpiralIsAccepted) {
  std::vector<Point2> points{{0, 0}};
  points.reserve(kLargeCount);
  double r = 0;
  double z = 0;
  for (std::size_t leg = 1; points.size() < kLargeCount; ++leg) {
    const double length = static_cast<double>(leg);
    switch (leg % 4) {
      case 0:
        r += length;
        break;
      case 1:
        z += length;
        break;
      case 2:
        r -= length;
        break;
      default:
        z -= length;
        break;
    }
    points.push_back({r, z});
  }
  EXPECT_FALSE(findSelfIntersection(points));
}

// A million collinear points on a diagonal: every neighbouring pair continues straight on.
TEST(SelfIntersectionTest, MillionCollinearPointsAreAccepted) {
  std::vector<Point2> points;
  points.reserve(kLargeCount);
  for (std::size_t i = 0; i < kLargeCount; ++i) {
    const double t = static_cast<double>(i);
    points.push_back({t, 3 * t});
  }
  EXPECT_FALSE(findSelfIntersection(points));
}

}  // namespace
}  // namespace revolve::detail
