// The placement rule (geometry/placement.h): scale factors in [2^-16, 2^40] within a factor 2^16 of
// each other, whether given as the scene file's factors or as a 4x4 matrix, whose factors are its
// singular values. Matrices are built as R S from a known rotation R and known factors S, so the
// expected verdicts come from the factors, not from the code's own computation of them.
#include "geometry/placement.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace revolve {
namespace {

using ::testing::HasSubstr;

// Rows of the 4x4 matrix [R diag(factors) | t; 0 0 0 1], R a rotation of 50 degrees about (1, 2, 3).
std::array<double, 16> rotatedRows(app::Vec3d factors, app::Vec3d t = {0, 0, 0}) {
  const double n = std::sqrt(14.0);
  const app::Matrix3d r = app::rotationAbout({1 / n, 2 / n, 3 / n}, 50 * std::numbers::pi / 180);
  std::array<double, 16> rows{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rows[4 * i + j] = r[i][j] * factors[j];
    rows[4 * i + 3] = t[i];
  }
  rows[15] = 1;
  return rows;
}

std::string refusal(const std::array<double, 16>& rows) {
  try {
    (void)app::Placement::fromRows(rows.data(), "m");
  } catch (const app::PlacementError& error) {
    return error.what();
  }
  return "";
}

TEST(PlacementTest, AMatrixIsHeldToItsSingularValuesAsTheSceneFileToItsFactors) {
  // At the limits, rotated: accepted, as the same factors in a scene file are.
  EXPECT_EQ(refusal(rotatedRows({0x1p-16, 0x1p-16, 0x1p-16})), "");
  EXPECT_EQ(refusal(rotatedRows({0x1p-16, 1, 1})), "");
  EXPECT_EQ(refusal(rotatedRows({0x1p40, 0x1p40, 0x1p24})), "");
  // Just beyond: refused, naming the factor and the rule.
  EXPECT_THAT(refusal(rotatedRows({0x1p-16 * 0.999, 1, 1})), HasSubstr("m's 3x3 part scales by 1.52"));
  EXPECT_THAT(refusal(rotatedRows({0x1p-16 * 0.999, 1, 1})),
              HasSubstr("(its smallest singular value): scale factors lie in [2^-16, 2^40]"));
  EXPECT_THAT(refusal(rotatedRows({1, 0x1p40 * 1.001, 1e8})), HasSubstr("(its largest singular value)"));
  EXPECT_THAT(refusal(rotatedRows({1, 0x1p16 * 1.001, 1})), HasSubstr("the scale factors differ by a factor 65601"));
  EXPECT_EQ(refusal(rotatedRows({1, 0x1p16, 1})), "");
  // Unrotated, a factor of 2^-17 keeps every row of the inverse within Embree's range by norms,
  // but it is no scale factor the rule allows (nor the scene file).
  EXPECT_THAT(refusal(rotatedRows({0x1p-17, 1, 1})), HasSubstr("scales by 7.62939453125e-06"));
  // A shear's singular values are not its entries: [[1, 1e6], [0, 1]] scales by about 1e6 and 1e-6.
  std::array<double, 16> shear{1, 1e6, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THAT(refusal(shear), HasSubstr("(its smallest singular value)"));
  std::array<double, 16> flat{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  EXPECT_THAT(refusal(flat), HasSubstr("m's 3x3 part is singular"));
}

TEST(PlacementTest, AMatrixNamesItsFirstBadEntryAndAnAffineLastRow) {
  std::array<double, 16> rows = rotatedRows({1, 1, 1});
  rows[6] = NAN;
  EXPECT_EQ(refusal(rows), "m[1, 2] = nan is not finite");
  rows = rotatedRows({1, 1, 1});
  rows[12] = 0.5;
  EXPECT_THAT(refusal(rows), HasSubstr("m's last row is (0.5, 0, 0, 1); a placement is affine"));
}

TEST(PlacementTest, TheSceneFilesTransformGivesItsOwnMatrixAndInverse) {
  app::Transform t;
  t.scale = {2, 3, 0.5};
  t.rotateAxis = {0, 0, 1};
  t.rotateDegrees = 90;
  t.translate = {1, 2, 3};
  const app::Placement p(t);
  // x -> translate + Rz(90) (scale x): (1, 0, 0) -> (1, 2, 3) + (0, 2, 0).
  const app::Vec3d world = p.toWorld({1, 0, 0});
  EXPECT_NEAR(world[0], 1, 1e-15);
  EXPECT_DOUBLE_EQ(world[1], 4);
  EXPECT_DOUBLE_EQ(world[2], 3);
  const app::Vec3d back = p.toObject(world);
  EXPECT_NEAR(back[0], 1, 1e-15);
  EXPECT_NEAR(back[1], 0, 1e-15);
  EXPECT_NEAR(back[2], 0, 1e-15);
  EXPECT_EQ(p.similarity(), 0);  // unequal factors
  t.scale = {2, 2, 2};
  EXPECT_NEAR(app::Placement(t).similarity(), 2, 1e-15);
  t.scale = {1e-20, 1, 1};
  EXPECT_THROW(app::Placement{t}, app::PlacementError);
}

TEST(PlacementTest, ReachIsTheFarthestCornerPlaced) {
  const std::array<double, 16> rows = rotatedRows({1, 1, 1}, {10, 0, 0});
  const app::Placement p = app::Placement::fromRows(rows.data(), "m");
  // A unit cube about the origin, rotated, lies within sqrt(3) of (10, 0, 0); its farthest x reaches at most 10 +
  // sqrt 3.
  const double reach = p.reach({-1, -1, -1}, {1, 1, 1});
  EXPECT_GT(reach, 10 + 1);
  EXPECT_LE(reach, 10 + std::sqrt(3.0) + 1e-12);
  EXPECT_FALSE(app::reachFault(0x1p40).has_value());
  EXPECT_THAT(*app::reachFault(2e12), HasSubstr("the placed object reaches 2e+12, beyond the coordinate limit"));
}

}  // namespace
}  // namespace revolve
