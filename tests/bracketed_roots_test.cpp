// bracketedRoots (src/kernel/bracketed_roots.h): the roots of g(x) = A x^2 + 2 B x + C in [x0, x1],
// counted from the caller's inside/outside verdicts (inside = g < 0) at the ends and from the sign at
// the extremum, each root then placed by the stable formula and clamped into its bracket.
//
// The quadratics are built from their roots, a and b, as A (x - a)(x - b) with A a power of two and
// a, b, x0, x1 dyadic of few bits: B = -A (a + b) / 2 and C = A a b are then exact, and so are the
// discriminant (A^2 (b - a)^2 / 4, a perfect square whose square root IEEE arithmetic returns exactly),
// q = -(B + sign(B) sqrt(D)) = A a or A b, and the quotients q / A and C / q, which are a and b
// themselves. So the expected roots are a and b, exactly, and every comparison below is exact.
#include "kernel/bracketed_roots.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace revolve {
namespace {

using detail::bracketedRoots;
using detail::EndsOnSurface;
using detail::Quadratic;
using detail::Roots;

Quadratic withRoots(double A, double a, double b) { return {A, -0.5 * A * (a + b), A * a * b}; }

// The caller's verdict, evaluated exactly (long double holds every product of these dyadic values).
bool insideAt(const Quadratic& g, double x) {
  const long double X = x;
  return g.A * X * X + 2.0L * g.B * X + g.C < 0.0L;
}

std::vector<double> rootsOf(const Roots& roots) { return {roots.x, roots.x + roots.count}; }

std::vector<double> solve(const Quadratic& g, double x0, double x1, EndsOnSurface on = {}) {
  return rootsOf(bracketedRoots(g, x0, x1, insideAt(g, x0), insideAt(g, x1), on));
}

TEST(BracketedRoots, ConvexQuadraticWithBothRootsInside) {
  EXPECT_EQ(solve(withRoots(1.0, 1.0, 3.0), 0.0, 4.0), (std::vector<double>{1.0, 3.0}));
  EXPECT_EQ(solve(withRoots(0x1p-6, -2.5, 0.75), -3.0, 1.0), (std::vector<double>{-2.5, 0.75}));
}

TEST(BracketedRoots, ConcaveQuadraticWithBothRootsInside) {
  // g < 0 outside the roots: the ray is inside at both ends and outside between the roots.
  EXPECT_EQ(solve(withRoots(-1.0, 1.0, 3.0), 0.0, 4.0), (std::vector<double>{1.0, 3.0}));
  EXPECT_EQ(solve(withRoots(-0x1p6, -2.5, 0.75), -3.0, 1.0), (std::vector<double>{-2.5, 0.75}));
}

TEST(BracketedRoots, OneRootWhereGIsMonotoneOnTheInterval) {
  // Monotone on the interval (the extremum outside it): one root, on the interval's side of it.
  EXPECT_EQ(solve(withRoots(1.0, 1.0, 3.0), 0.0, 2.0), (std::vector<double>{1.0}));
  EXPECT_EQ(solve(withRoots(1.0, 1.0, 3.0), 2.0, 4.0), (std::vector<double>{3.0}));
  EXPECT_EQ(solve(withRoots(-1.0, 1.0, 3.0), 2.5, 8.0), (std::vector<double>{3.0}));
}

TEST(BracketedRoots, LinearHasOneRootWhereTheSignsDiffer) {
  const Quadratic g{0.0, 0.5, -1.0};  // x - 1
  EXPECT_EQ(solve(g, -4.0, 4.0), (std::vector<double>{1.0}));
  EXPECT_EQ(solve({0.0, -2.0, 3.0}, 0.0, 1.0), (std::vector<double>{0.75}));  // 3 - 4x, decreasing
  EXPECT_TRUE(solve(g, 2.0, 4.0).empty());
  EXPECT_TRUE(solve(g, -4.0, 0.5).empty());
}

TEST(BracketedRoots, ConstantWithDifferentVerdictsIsARayAlongTheSurface) {
  // A = B = 0: signs that differ can only come from a ray running along the surface, where every
  // point is on it within rounding. The first point is reported.
  const Roots roots = bracketedRoots({0.0, 0.0, 0.0}, -1.0, 2.0, true, false);
  EXPECT_EQ(rootsOf(roots), (std::vector<double>{-1.0}));
  EXPECT_EQ(bracketedRoots({0.0, 0.0, 0.0}, -1.0, 2.0, false, false).count, 0);
}

TEST(BracketedRoots, TangentTouchIsADoubleRootForEitherSignOfA) {
  // D = B^2 - A C = 0 exactly: the ray touches the surface. Convex g touches zero from above (the
  // ray outside on both sides), concave g from below (inside on both sides); both are reported
  // twice, or once with kFirstOnly.
  for (const double A : {1.0, -1.0, 0x1p-10, -0x1p10}) {
    SCOPED_TRACE("A = " + std::to_string(A));
    const Quadratic g = withRoots(A, 2.0, 2.0);
    ASSERT_EQ(g.B * g.B - g.A * g.C, 0.0);
    EXPECT_EQ(solve(g, 0.0, 5.0), (std::vector<double>{2.0, 2.0}));
    const Roots first = bracketedRoots<true>(g, 0.0, 5.0, insideAt(g, 0.0), insideAt(g, 5.0));
    EXPECT_EQ(rootsOf(first), (std::vector<double>{2.0}));
    // At the extremum x = 0 (B = 0, q = 0): the formula's special case.
    const Quadratic atZero = withRoots(A, 0.0, 0.0);
    EXPECT_EQ(solve(atZero, -1.0, 1.0), (std::vector<double>{0.0, 0.0}));
  }
}

TEST(BracketedRoots, RootsExactlyAtTheIntervalEnds) {
  const Quadratic g = withRoots(1.0, 1.0, 3.0);
  // Both ends on the roots, the interval inside between them: the verdicts at the ends are
  // "outside" (g = 0 is not g < 0), the extremum inside: both ends are roots.
  EXPECT_EQ(solve(g, 1.0, 3.0), (std::vector<double>{1.0, 3.0}));
  EXPECT_EQ(solve(g, 1.0, 3.0, {.at0 = true, .at1 = true}), (std::vector<double>{1.0, 3.0}));
  // The interval outside, the root at its far end: a hit only where the caller found the ray
  // exactly on the surface there (tfar is inclusive); otherwise that end is the neighbour's.
  EXPECT_TRUE(solve(g, 0.0, 1.0).empty());
  EXPECT_EQ(solve(g, 0.0, 1.0, {.at1 = true}), (std::vector<double>{1.0}));
  EXPECT_TRUE(solve(g, 3.0, 4.0).empty());
  EXPECT_EQ(solve(g, 3.0, 4.0, {.at0 = true}), (std::vector<double>{3.0}));
  // The same with g concave (the interval inside), and for a linear g.
  const Quadratic concave = withRoots(-1.0, 1.0, 3.0);
  EXPECT_EQ(solve(concave, 0.0, 1.0, {.at1 = true}), (std::vector<double>{1.0}));
  EXPECT_EQ(solve(concave, 3.0, 4.0, {.at0 = true}), (std::vector<double>{3.0}));
  const Quadratic linear{0.0, 0.5, -1.0};  // x - 1
  EXPECT_EQ(solve(linear, 1.0, 2.0, {.at0 = true}), (std::vector<double>{1.0}));
  EXPECT_EQ(solve(linear, 0.0, 1.0, {.at1 = true}), (std::vector<double>{1.0}));
}

TEST(BracketedRoots, NoRoots) {
  EXPECT_TRUE(solve(withRoots(1.0, 1.0, 3.0), 4.0, 5.0).empty());   // outside throughout
  EXPECT_TRUE(solve(withRoots(1.0, 1.0, 3.0), 1.5, 2.5).empty());   // inside throughout
  EXPECT_TRUE(solve(withRoots(-1.0, 1.0, 3.0), 1.5, 2.5).empty());  // outside throughout, g concave
  EXPECT_TRUE(solve({1.0, 0.0, 1.0}, -1.0, 1.0).empty());           // x^2 + 1: D < 0, outside
  EXPECT_TRUE(solve({-1.0, 0.0, -1.0}, -1.0, 1.0).empty());         // -x^2 - 1: D < 0, inside
  EXPECT_TRUE(solve({0.0, 0.0, 1.0}, -1.0, 1.0).empty());           // constant
}

TEST(BracketedRoots, TheSignsDecideTheCountAndTheRootsAreClampedIntoTheirBrackets) {
  // Verdicts that say the ray changes sides in [0, 0.5], where (x - 1)(x - 3) has no root (as
  // rounding can make a caller's verdicts disagree with the coefficients): one root, clamped into
  // the interval. Whether a surface is crossed is the verdicts' decision alone.
  const Quadratic g = withRoots(1.0, 1.0, 3.0);
  EXPECT_EQ(rootsOf(bracketedRoots(g, 0.0, 0.5, true, false)), (std::vector<double>{0.5}));
  EXPECT_EQ(rootsOf(bracketedRoots(g, 3.5, 4.0, true, false)), (std::vector<double>{3.5}));
  // And verdicts of "outside" at both ends, where g's extremum (inside) lies between them, give
  // two roots, each within its side of the extremum.
  EXPECT_EQ(rootsOf(bracketedRoots(withRoots(1.0, 1.0, 3.0), 1.5, 2.5, false, false)), (std::vector<double>{1.5, 2.5}));
}

// Dyadic values of 13 bits in [-4, 4) (multiples of 2^-8), and interval ends on the odd multiples
// of 2^-9, which no root equals, so that "the roots in [x0, x1]" is unambiguous.
double dyadic(std::mt19937_64& random) { return std::uniform_int_distribution<int>(-1024, 1023)(random) * 0x1p-8; }
double endBetweenRoots(std::mt19937_64& random) { return dyadic(random) + 0x1p-9; }

TEST(BracketedRoots, RandomQuadraticsWithKnownRoots) {
  for (const std::uint64_t seed : testing::testSeeds({0xb7ac, 0xb7ad})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::size_t withTwo = 0, withOne = 0, withNone = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      double a = dyadic(random), b = dyadic(random);
      if (trial % 16 == 0) b = a;  // a double root
      if (a > b) std::swap(a, b);
      const double A = std::ldexp(random() % 2 == 0 ? 1.0 : -1.0, std::uniform_int_distribution<int>(-6, 6)(random));
      const bool linear = trial % 8 == 1;
      // Linear: 2 B (x - a).
      const Quadratic g = linear ? Quadratic{0.0, A, -2.0 * A * a} : withRoots(A, a, b);
      double x0 = endBetweenRoots(random), x1 = endBetweenRoots(random);
      if (x0 > x1) std::swap(x0, x1);

      std::vector<double> expected;
      for (const double root : linear ? std::vector<double>{a} : std::vector<double>{a, b}) {
        if (x0 < root && root < x1) expected.push_back(root);
      }
      // A double root inside is a touch, reported twice; one outside is nothing.
      const std::vector<double> got = solve(g, x0, x1);
      ASSERT_EQ(got, expected) << "trial " << trial << ": A=" << A << " roots " << a << ", " << b << " on [" << x0
                               << ", " << x1 << "]" << (linear ? " (linear)" : "");
      const Roots first = bracketedRoots<true>(g, x0, x1, insideAt(g, x0), insideAt(g, x1));
      ASSERT_EQ(first.count, std::min<int>(1, int(expected.size()))) << "trial " << trial;
      if (first.count == 1) {
        ASSERT_EQ(first.x[0], expected[0]) << "trial " << trial;
      }
      ++(expected.size() == 2 ? withTwo : expected.size() == 1 ? withOne : withNone);
    }
    // Every case was drawn often.
    EXPECT_GT(withTwo, 1000u);
    EXPECT_GT(withOne, 2000u);
    EXPECT_GT(withNone, 2000u);
  }
}

}  // namespace
}  // namespace revolve
