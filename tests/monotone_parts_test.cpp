// monotoneParts (src/curve/monotone_parts.h): a cubic Bezier curve split where r or z turns. Checked
// against de Casteljau's evaluation written here in long double, on the test splines, random
// curves and hand-made cases (a cusp where r and z turn at once, a derivative that touches zero
// without changing sign, a turn closer to an end than 2^-50 of the extent):
// - the parts join exactly: each starts at the bit-identical point where the previous one ends,
//   the first at the curve's start, the last at its end, and their parameter ranges tile each piece;
// - each part is monotone in r and in z, so it lies in the box of its ends (what lets a part take a
//   segment's place in MIBIT's monotone intervals and cylinder shells);
// - the parts reproduce the curve: part k at v is its piece at u0 + v (u1 - u0).
//
// Tolerances, in units of the curve's extent X (its largest coordinate magnitude): a split skipped
// for lying within 2^-50 X of an end or of the previous split lets a part overshoot its box by that
// much (the header's rule); the parts' control values are blossoms evaluated in double (three
// levels of de Casteljau's scheme on values within X, a few u X; 2^-48 X = 32 u X with room). At a
// split, the control next to the end may be pinned to the end's r or z, which moves the curve by at
// most 4/9 of that control's shift (the maximum of its Bernstein weight 3 v (1 - v)^2), the shift
// being (u1 - u0) / 3 |c'(u)| with c' at the split (zero up to the split parameter's rounding),
// computed here from the piece; pins at both ends add.
#include "curve/monotone_parts.h"
#include "support/spline_profiles.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

using Real = long double;
using detail::MonotonePart;

// de Casteljau's scheme on four control values.
Real casteljau(Real c0, Real c1, Real c2, Real c3, Real t) {
  const Real a = c0 + t * (c1 - c0), b = c1 + t * (c2 - c1), d = c2 + t * (c3 - c2);
  const Real e = a + t * (b - a), f = b + t * (d - b);
  return e + t * (f - e);
}

struct RealPoint {
  Real r, z;
};

RealPoint at(const Point2* c, Real t) {
  return {casteljau(c[0].r, c[1].r, c[2].r, c[3].r, t), casteljau(c[0].z, c[1].z, c[2].z, c[3].z, t)};
}

// c'(t): 3 times the quadratic Bezier of the control differences.
RealPoint derivativeAt(const Point2* c, Real t) {
  const auto d = [&](Real c0, Real c1, Real c2, Real c3) {
    const Real d0 = c1 - c0, d1 = c2 - c1, d2 = c3 - c2;
    return 3 * ((1 - t) * (1 - t) * d0 + 2 * t * (1 - t) * d1 + t * t * d2);
  };
  return {d(c[0].r, c[1].r, c[2].r, c[3].r), d(c[0].z, c[1].z, c[2].z, c[3].z)};
}

bool same(Point2 a, Point2 b) { return a.r == b.r && a.z == b.z; }

void checkParts(std::span<const Point2> bezier, const std::string& what, std::size_t* partCount = nullptr) {
  SCOPED_TRACE(what);
  double extent = 0.0;  // as Shape computes it
  for (const Point2& p : bezier) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  const std::vector<MonotonePart> parts = detail::monotoneParts(bezier, extent);
  if (partCount != nullptr) *partCount = parts.size();
  const std::size_t pieces = (bezier.size() - 1) / 3;
  ASSERT_GE(parts.size(), pieces);
  const Real overshoot = 0x1p-50L * extent, rounding = 0x1p-48L * extent;

  // Joined exactly, tiling each piece's parameters.
  EXPECT_TRUE(same(parts.front().c[0], bezier.front()));
  EXPECT_TRUE(same(parts.back().c[3], bezier.back()));
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const MonotonePart& part = parts[k];
    ASSERT_LT(part.piece, pieces);
    ASSERT_LT(part.u0, part.u1) << "part " << k;
    const bool firstOfPiece = k == 0 || parts[k - 1].piece != part.piece;
    const bool lastOfPiece = k + 1 == parts.size() || parts[k + 1].piece != part.piece;
    if (firstOfPiece) {
      EXPECT_EQ(part.u0, 0.0) << "part " << k;
      EXPECT_EQ(part.piece, k == 0 ? 0u : parts[k - 1].piece + 1) << "part " << k << ": a piece skipped";
    } else {
      EXPECT_EQ(part.u0, parts[k - 1].u1) << "part " << k;
    }
    if (lastOfPiece) {
      EXPECT_EQ(part.u1, 1.0) << "part " << k;
    }
    if (k + 1 < parts.size()) {
      EXPECT_TRUE(same(part.c[3], parts[k + 1].c[0])) << "parts " << k << " and " << k + 1 << " do not join";
    }
  }
  EXPECT_EQ(parts.back().piece, pieces - 1);

  for (std::size_t k = 0; k < parts.size(); ++k) {
    const MonotonePart& part = parts[k];
    const Point2* piece = &bezier[3 * part.piece];
    // The pins' allowance, per coordinate: at a split (not a piece's own end), where the part's end
    // control pair shares that coordinate exactly (the pinned case, or a coincidence, which the
    // allowance then merely covers), the shift (u1 - u0) / 3 |c'| at the split.
    const Real third = (Real(part.u1) - part.u0) / 3;
    const RealPoint d0 = derivativeAt(piece, part.u0), d1 = derivativeAt(piece, part.u1);
    const bool split0 = part.u0 != 0.0, split1 = part.u1 != 1.0;
    const Real pinR = (split0 && part.c[1].r == part.c[0].r ? third * std::abs(d0.r) : 0) +
                      (split1 && part.c[2].r == part.c[3].r ? third * std::abs(d1.r) : 0);
    const Real pinZ = (split0 && part.c[1].z == part.c[0].z ? third * std::abs(d0.z) : 0) +
                      (split1 && part.c[2].z == part.c[3].z ? third * std::abs(d1.z) : 0);
    // Monotone: along 64 samples each coordinate moves one way (the way from start to end) up to
    // the overshoot and the rounding, and the curve stays in the box of the part's ends.
    const RealPoint start = at(part.c, 0), end = at(part.c, 1);
    const int dirR = end.r > start.r   ? 1
                     : end.r < start.r ? -1
                                       : 0,
              dirZ = end.z > start.z   ? 1
                     : end.z < start.z ? -1
                                       : 0;
    const Real monotoneSlack = overshoot + rounding;
    RealPoint previous = start;
    for (int j = 0; j <= 64; ++j) {
      const Real v = Real(j) / 64;
      const RealPoint p = at(part.c, v);
      const auto backwards = [&](Real now, Real before, int dir) {
        return dir == 0 ? std::abs(now - before) : dir * (before - now);
      };
      ASSERT_LE(backwards(p.r, previous.r, dirR), monotoneSlack)
          << "part " << k << ": r turns back at v = " << double(v);
      ASSERT_LE(backwards(p.z, previous.z, dirZ), monotoneSlack)
          << "part " << k << ": z turns back at v = " << double(v);
      ASSERT_TRUE(std::min(start.r, end.r) - monotoneSlack <= p.r && p.r <= std::max(start.r, end.r) + monotoneSlack &&
                  std::min(start.z, end.z) - monotoneSlack <= p.z && p.z <= std::max(start.z, end.z) + monotoneSlack)
          << "part " << k << " leaves the box of its ends at v = " << double(v);
      previous = p;
      // The part is its piece restricted to [u0, u1].
      const RealPoint q = at(piece, part.u0 + v * (Real(part.u1) - part.u0));
      ASSERT_LE(std::abs(p.r - q.r), rounding + 4 * pinR / 9) << "part " << k << " at v = " << double(v);
      ASSERT_LE(std::abs(p.z - q.z), rounding + 4 * pinZ / 9) << "part " << k << " at v = " << double(v);
    }
  }
}

TEST(MonotoneParts, TestSplinesJoinExactlyStayMonotoneAndReproduceTheCurve) {
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Spline spline(named.kind, named.points);
    checkParts(spline.bezier(), named.name);
  }
  checkParts(testing::bezierSphere(1.0, 3), "sphere in 3 arcs (each turning through the pole or the equator)");
  checkParts(testing::bezierTorus(1.0, 0.5, 5), "torus in 5 arcs");
}

TEST(MonotoneParts, RandomCurvesAtEveryScale) {
  for (const std::uint64_t seed : testing::testSeeds({0x9a27})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::size_t split = 0;
    for (int curve = 0; curve < 500; ++curve) {
      const int pieces = 1 + curve % 4;
      const double scale = std::ldexp(1.0, std::uniform_int_distribution<int>(-20, 20)(random));
      std::vector<Point2> bezier;
      for (int i = 0; i < 3 * pieces + 1; ++i) {
        bezier.push_back({scale * coordinate(random), scale * coordinate(random)});
      }
      std::size_t parts = 0;
      checkParts(bezier, "curve " + std::to_string(curve), &parts);
      if (::testing::Test::HasFatalFailure()) return;
      split += parts - pieces;
    }
    EXPECT_GT(split, 500u) << "random cubics turn often";
  }
}

// A cubic in power form a0 + a1 u + a2 u^2 + a3 u^3 as Bernstein control values.
std::array<double, 4> bernstein(double a0, double a1, double a2, double a3) {
  return {a0, a0 + a1 / 3, a0 + 2 * a1 / 3 + a2 / 3, a0 + a1 + a2 + a3};
}

std::vector<Point2> curveOf(const std::array<double, 4>& r, const std::array<double, 4>& z) {
  return {{r[0], z[0]}, {r[1], z[1]}, {r[2], z[2]}, {r[3], z[3]}};
}

TEST(MonotoneParts, HandMadeTurns) {
  // Monotone already: one part, the piece itself.
  const std::vector<Point2> monotoneCurve{{0.0, 0.0}, {0.5, 0.1}, {0.6, 0.9}, {1.0, 1.0}};
  const std::vector<MonotonePart> one = detail::monotoneParts(monotoneCurve, 1.0);
  ASSERT_EQ(one.size(), 1u);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(same(one[0].c[i], monotoneCurve[i]));
  // r' = 3 (1 - 2u)^2 touches zero at u = 1/2 without changing sign: r stays monotone, no split.
  EXPECT_EQ(detail::monotoneParts(curveOf({0.0, 1.0, 0.0, 1.0}, {0.0, 1.0 / 3, 2.0 / 3, 1.0}), 1.0).size(), 1u);
  checkParts(curveOf({0.0, 1.0, 0.0, 1.0}, {0.0, 1.0 / 3, 2.0 / 3, 1.0}), "derivative touching zero");
  // A cusp: r = (u - 1/2)^2 + 1/4 and z = (u - 1/2)^2 + (u - 1/2)^3 / 2 both turn at u = 1/2.
  const auto cusp = curveOf(bernstein(0.5, -1.0, 1.0, 0.0), bernstein(0.1875, -0.625, 0.25, 0.5));
  EXPECT_EQ(detail::monotoneParts(cusp, 0.5).size(), 2u);
  checkParts(cusp, "cusp");
  // r turns at u ~ 5e-18, 10^-35 from the start: skipped (within 2^-50 of the extent), one part.
  const std::vector<Point2> nearTheEnd{{0.0, 0.0}, {-1e-17, 1.0 / 3}, {1.0, 2.0 / 3}, {1.0, 1.0}};
  EXPECT_EQ(detail::monotoneParts(nearTheEnd, 1.0).size(), 1u);
  checkParts(nearTheEnd, "turn next to an end");
  // Both coordinates turning twice in one piece: up to five parts.
  const auto wiggle = curveOf(bernstein(0.0, 3.0, -9.0, 6.5), bernstein(0.0, -2.0, 9.0, -7.5));
  EXPECT_EQ(detail::monotoneParts(wiggle, 2.0).size(), 5u);
  checkParts(wiggle, "two turns in r and in z");
}

}  // namespace
}  // namespace revolve
