// Arc length of a curved part (src/curve/arc_length.h, arc_table.h), from which a hit's v is
// computed: against closed forms (straight pieces, whose length is their chord whatever the
// spacing of their control points; a quarter circle's cubic arc, whose length lies between those
// of the circles it lies between) and
// against an independent integration of |c'(u)|: adaptive Simpson's rule with Richardson's
// correction in long double, on the test splines' and random curves' monotone parts.
//
// Tolerances, in units of the part's length L. arcTableOf halves its Gauss-Legendre panels until
// two levels agree within 2^-40 L in all (the finer level, kept, is the more accurate), and sums up
// to 1,024 steps (rounding 1,024 u L = 2^-43 L): 2^-39 L bounds its lengths. The reference is
// asked for 2^-56 L. A step's entry plus one five-point rule from the step's start (what a hit
// computes) is promised within 2^-30 L in every step (checked at 16 points of each) once the table stops refining below
// its 1,024-step cap.
#include "curve/arc_table.h"
#include "curve/arc_length.h"
#include "curve/arc_record.h"
#include "curve/monotone_parts.h"
#include "support/spline_profiles.h"
#include "support/test_seeds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

using Real = long double;

constexpr double u = 0x1p-53;  // the unit roundoff of double

struct Part {
  double r[4], z[4];
};

Part partOf(const Point2* c) { return {{c[0].r, c[1].r, c[2].r, c[3].r}, {c[0].z, c[1].z, c[2].z, c[3].z}}; }

// |c'(t)|, from the derivative's own Bernstein form: 3 sum of the control differences' weights.
Real speed(const Part& p, Real t) {
  const auto d = [t](const double c[4]) {
    return 3 * ((1 - t) * (1 - t) * (Real(c[1]) - c[0]) + 2 * t * (1 - t) * (Real(c[2]) - c[1]) +
                t * t * (Real(c[3]) - c[2]));
  };
  return std::hypot(d(p.r), d(p.z));
}

// Adaptive Simpson (Lyness' criterion, with the Richardson term added), tolerance `eps` on [a, b].
Real simpson(const Part& p, Real a, Real b, Real eps, Real fa, Real fm, Real fb, Real whole, int depth) {
  const Real m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  const Real flm = speed(p, lm), frm = speed(p, rm);
  const Real left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  const Real delta = left + right - whole;
  if (depth >= 40 || std::abs(delta) <= 15 * eps) return left + right + delta / 15;
  return simpson(p, a, m, eps / 2, fa, flm, fm, left, depth + 1) +
         simpson(p, m, b, eps / 2, fm, frm, fb, right, depth + 1);
}

Real lengthBetween(const Part& p, Real a, Real b, Real eps) {
  const Real fa = speed(p, a), fm = speed(p, (a + b) / 2), fb = speed(p, b);
  return simpson(p, a, b, eps, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), 0);
}

// The table checked against the reference: its length, every entry (arc length at u = k / steps),
// and what a hit computes from it (arcLengthFrom: the step's entry plus one five-point rule) at 16
// points of every step, most of them points the table's own refinement never looked at.
void checkTable(const Part& p, const std::string& what) {
  SCOPED_TRACE(what);
  const detail::ArcTable table = detail::arcTableOf(p.r, p.z);
  ASSERT_TRUE(table.steps >= 1 && table.steps <= 1024 && std::has_single_bit(table.steps)) << table.steps << " steps";
  ASSERT_EQ(table.cumulative.size(), table.steps + 1);
  const Real chord = std::hypot(Real(p.r[3]) - p.r[0], Real(p.z[3]) - p.z[0]);  // <= L, and > L / 2 for a monotone part
  const Real L = lengthBetween(p, 0, 1, 0x1p-57L * chord);
  const Real eps = 0x1p-56L * L / table.steps;
  const Real lengthTolerance = 0x1p-39L * L;
  Real cumulative = 0;
  for (std::uint32_t k = 0; k <= table.steps; ++k) {
    const Real t = Real(k) / table.steps;
    if (k > 0) cumulative += lengthBetween(p, Real(k - 1) / table.steps, t, eps);
    ASSERT_LE(std::abs(table.cumulative[k] - cumulative), lengthTolerance) << "arc length at u = " << double(t);
    if (k < table.steps && table.steps < 1024) {
      for (int j = 1; j <= 16; ++j) {
        const Real at = (k + j / 16.0L) / table.steps;
        const Real exact = cumulative + lengthBetween(p, t, at, eps);
        ASSERT_LE(
            std::abs(detail::arcLengthFrom(table.cumulative.data() + 1, table.steps, p.r, p.z, double(at)) - exact),
            0x1p-30L * L + lengthTolerance)
            << "arc length at " << j << "/16 of step " << k;
      }
    }
  }
  EXPECT_LE(std::abs(table.length - cumulative), lengthTolerance);
  EXPECT_EQ(table.length, table.cumulative[table.steps]);
  // u is clamped to [0, 1]: below, the first entry exactly (a rule over no width adds 0).
  EXPECT_EQ(detail::arcLengthFrom(table.cumulative.data() + 1, table.steps, p.r, p.z, -0.5), table.cumulative[0]);
  if (table.steps < 1024) {
    EXPECT_LE(std::abs(detail::arcLengthFrom(table.cumulative.data() + 1, table.steps, p.r, p.z, 1.5) - cumulative),
              0x1p-30L * L + lengthTolerance);
  }
}

TEST(ArcTable, StraightPiecesAreTheirChordsHoweverTheirControlsAreSpaced) {
  // c(u) = a + lambda(u) (b - a) with lambda' >= 0: the length to u is lambda(u) |b - a|, exactly; the
  // speed, a quadratic, is integrated exactly by the five-point Gauss-Legendre rule (degree 9), so
  // only rounding separates the table from the closed form: the 2^-39 L budget holds it.
  const Point2 a{0.25, -1.0}, b{1.5, 2.0};
  const double chord = std::hypot(b.r - a.r, b.z - a.z);
  for (const std::array<double, 4> lambda :
       {std::array<double, 4>{0.0, 1.0 / 3, 2.0 / 3, 1.0}, std::array<double, 4>{0.0, 0.05, 0.95, 1.0},
        std::array<double, 4>{0.0, 0.0, 1.0, 1.0},  // speed 0 at both ends
        std::array<double, 4>{0.0, 0.6, 0.6, 1.0}}) {
    Part p;
    for (int i = 0; i < 4; ++i) p.r[i] = a.r + lambda[i] * (b.r - a.r), p.z[i] = a.z + lambda[i] * (b.z - a.z);
    const detail::ArcTable table = detail::arcTableOf(p.r, p.z);
    EXPECT_NEAR(table.length, chord, 0x1p-39 * chord);
    for (std::uint32_t k = 0; k <= table.steps; ++k) {
      const Real t = Real(k) / table.steps, v = 1 - t;
      const Real along = 3 * v * v * t * lambda[1] + 3 * v * t * t * lambda[2] + t * t * t * lambda[3];
      EXPECT_NEAR(table.cumulative[k], double(along * chord), 0x1p-39 * chord) << "u = " << double(t);
    }
    // And the quadrature itself on any sub-interval: exact up to its nodes' and weights' 16
    // digits and the sum's rounding, 8 u of the interval's largest speed (at most 3 chord) times its width.
    for (const auto& [from, to] : {std::pair{0.0, 1.0}, std::pair{0.125, 0.5}, std::pair{0.3, 0.9}}) {
      const auto lambdaAt = [&](double t) {
        const double v = 1 - t;
        return 3 * v * v * t * lambda[1] + 3 * v * t * t * lambda[2] + t * t * t * lambda[3];
      };
      EXPECT_NEAR(detail::arcLengthBetween(p.r, p.z, from, to), (lambdaAt(to) - lambdaAt(from)) * chord,
                  8 * u * 3 * chord * (to - from) + 4 * u * chord);
    }
    checkTable(p, "straight piece");
  }
}

TEST(ArcTable, QuarterCircleArcLiesBetweenTheCirclesLengths) {
  // The standard cubic arc of a quarter circle of radius R lies outside the circle, at most
  // e = arcError(R, pi/2) from it (Goldapp 1991), and turns monotonically from one radius to the
  // other: with those two radii it bounds a convex region between the sectors of radius R and
  // R + e, so by the monotonicity of convex perimeters pi R / 2 <= L <= 2 e + pi (R + e) / 2.
  const double pi = std::numbers::pi;
  for (const double R : {1.0, 0x1p-30, 0x1p30}) {
    std::vector<Point2> c{{R, 0.0}};
    for (const Point2& p : testing::arcControls({0.0, 0.0}, R, 0.0, pi / 2, 1)) c.push_back(p);
    const Part part = partOf(c.data());
    const detail::ArcTable table = detail::arcTableOf(part.r, part.z);
    const double e = testing::arcError(R, pi / 2);
    EXPECT_GE(table.length, pi * R / 2);
    EXPECT_LE(table.length, 2 * e + pi * (R + e) / 2);
    checkTable(part, "quarter circle, R = " + std::to_string(R));
  }
}

TEST(ArcTable, MonotonePartsOfTestSplinesAndRandomCurves) {
  std::size_t tables = 0;
  const auto checkCurve = [&](std::span<const Point2> bezier, const std::string& name) {
    double extent = 0.0;
    for (const Point2& p : bezier) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
    int index = 0;
    for (const detail::MonotonePart& part : detail::monotoneParts(bezier, extent)) {
      checkTable(partOf(part.c), name + ", part " + std::to_string(index++));
      ++tables;
      if (::testing::Test::HasFatalFailure()) return;
    }
  };
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    checkCurve(Spline(named.kind, named.points).bezier(), named.name);
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (const std::uint64_t seed : testing::testSeeds({0xa2c})) {
    SCOPED_TRACE(testing::seedTrace(seed));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int curve = 0; curve < 40; ++curve) {
      const double scale = std::ldexp(1.0, std::uniform_int_distribution<int>(-30, 30)(random));
      std::vector<Point2> bezier;
      for (int i = 0; i < 4; ++i) bezier.push_back({scale * coordinate(random), scale * coordinate(random)});
      checkCurve(bezier, "random curve " + std::to_string(curve));
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  EXPECT_GT(tables, 100u);
}

TEST(ArcRecord, VIsTheArcLengthFractionAndMeetsTheNeighboursExactly) {
  // A curve of curved parts (a wave's: the natural spline through a zigzag, split where r or z
  // turns), recorded as a spline shape records them (arc_record.h: each table without its ends; the
  // curve's length up to each part from the tables' lengths): v at 16 points of every step against
  // the long-double length up to there over the long-double length of the curve, within the
  // promised 2^-30 of the part's length (over the curve's), plus 2^-39 for each of the three table
  // lengths it rests on (the part's own, the sum up to the part, the curve's: each within 2^-39 of
  // its length, at most the curve's), plus 2^-52 for the roundings of v itself. At u = 0 v is the
  // part's v0 exactly, and at u = 1 at most the next part's: v never steps back across a join.
  std::vector<Point2> zigzag;
  for (int i = 0; i <= 12; ++i) zigzag.push_back({1.0 + 0.3 * (i % 2), 0.25 * i});
  const Spline curve(SplineKind::natural, zigzag);
  double extent = 0.0;
  for (const Point2& p : curve.bezier()) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  std::vector<Part> parts;
  for (const detail::MonotonePart& part : detail::monotoneParts(curve.bezier(), extent))
    parts.push_back(partOf(part.c));
  ASSERT_GT(parts.size(), 12u);
  std::vector<double> records, arc{0.0};
  std::vector<std::uint32_t> first, steps;
  std::vector<Real> exactArc{0};
  for (const Part& p : parts) {
    const detail::ArcTable table = detail::arcTableOf(p.r, p.z);
    first.push_back(std::uint32_t(records.size()));
    steps.push_back(table.steps);
    records.insert(records.end(), table.cumulative.begin() + 1, table.cumulative.end() - 1);
    arc.push_back(arc.back() + table.length);
    exactArc.push_back(exactArc.back() + lengthBetween(p, 0, 1, 0x1p-60L));
  }
  ASSERT_EQ(records.size(), std::size_t(std::accumulate(steps.begin(), steps.end(), 0u)) - parts.size());
  const double total = arc.back();
  const Real exactTotal = exactArc.back();
  for (std::size_t k = 0; k < parts.size(); ++k) {
    SCOPED_TRACE("part " + std::to_string(k));
    const Part& p = parts[k];
    const auto v = [&](double u) {
      return detail::arcRecordV(records.data() + first[k], steps[k], p.r, p.z, u, arc[k], arc[k + 1], total);
    };
    const Real L = exactArc[k + 1] - exactArc[k];
    const Real tolerance = 0x1p-30L * L / exactTotal + 3 * 0x1p-39L + 0x1p-52L;
    for (int j = 1; j < 16 * int(steps[k]); ++j) {
      const Real at = Real(j) / (16 * steps[k]);
      const Real exact = (exactArc[k] + lengthBetween(p, 0, at, 0x1p-60L)) / exactTotal;
      ASSERT_LE(std::abs(v(double(at)) - exact), tolerance) << "u = " << double(at);
    }
    EXPECT_EQ(v(0.0), arc[k] / total);
    EXPECT_LE(v(1.0), arc[k + 1] / total);
  }
}

}  // namespace
}  // namespace revolve
