#include "placement.h"

#include "geometry/ray_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace revolve::python {
namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

// NaN entries (a singular matrix's inverse) give NaN, which every range test refuses.
double infinityNorm(const Matrix3d& m) {
  double worst = 0;
  for (const Vec3d& row : m) {
    const double sum = std::abs(row[0]) + std::abs(row[1]) + std::abs(row[2]);
    worst = sum > worst || std::isnan(sum) ? sum : worst;
  }
  return worst;
}

Vec3d apply(const Matrix3d& m, const Vec3d& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// The inverse by cofactors; a singular matrix gives non-finite entries, which the range test refuses.
Matrix3d inverseOf(const Matrix3d& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Matrix3d r;
  r[0] = {(m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det,
          (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det};
  r[1] = {(m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det,
          (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det};
  r[2] = {(m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det,
          (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det};
  return r;
}

// s when m^T m = s^2 I to the tolerance, else 0.
double similarityScale(const Matrix3d& m) {
  double gram[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) gram[i][j] = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
  }
  const double square = (gram[0][0] + gram[1][1] + gram[2][2]) / 3;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (!(std::abs(gram[i][j] - (i == j ? square : 0.0)) <= Placement::kSimilarityTolerance * square)) return 0;
    }
  }
  return std::sqrt(square);
}

}  // namespace

Vec3d Placement::toWorld(const Vec3d& p) const {
  const Vec3d v = apply(linear, p);
  return {v[0] + translate[0], v[1] + translate[1], v[2] + translate[2]};
}

Vec3d Placement::toObject(const Vec3d& p) const {
  return apply(inverse, {p[0] - translate[0], p[1] - translate[1], p[2] - translate[2]});
}

Vec3d Placement::normalToWorld(const Vec3d& n) const {
  const Vec3d w{inverse[0][0] * n[0] + inverse[1][0] * n[1] + inverse[2][0] * n[2],
                inverse[0][1] * n[0] + inverse[1][1] * n[1] + inverse[2][1] * n[2],
                inverse[0][2] * n[0] + inverse[1][2] * n[1] + inverse[2][2] * n[2]};
  const double length = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  return {w[0] / length, w[1] / length, w[2] / length};
}

std::array<float, 12> Placement::embreeColumns() const {
  std::array<float, 12> columns{};
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) columns[3 * c + r] = float(linear[r][c]);
  }
  for (int r = 0; r < 3; ++r) columns[9 + r] = float(translate[r]);
  return columns;
}

Placement placementOf(const double* rows, const Shape& shape) {
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(rows[i])) {
      throw std::invalid_argument("transform[" + std::to_string(i / 4) + ", " + std::to_string(i % 4) +
                                  "] = " + number(rows[i]) + " is not finite");
    }
  }
  if (rows[12] != 0 || rows[13] != 0 || rows[14] != 0 || rows[15] != 1) {
    throw std::invalid_argument("transform's last row is (" + number(rows[12]) + ", " + number(rows[13]) + ", " +
                                number(rows[14]) + ", " + number(rows[15]) +
                                "); a placement is affine: its last row must be (0, 0, 0, 1)");
  }
  Placement placement;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) placement.linear[r][c] = rows[4 * r + c];
    placement.translate[r] = rows[4 * r + 3];
  }
  placement.inverse = inverseOf(placement.linear);
  // The test the scene builder applies to a scene file's transforms (platform/scene/embree_scene.cpp):
  // Embree's object-space rays stay within its range, from any ray origin revolve accepts.
  const double norm = infinityNorm(placement.linear), inverseNorm = infinityNorm(placement.inverse);
  if (!(inverseNorm * (app::kMaxRayOrigin + app::kMaxWorldCoordinate) <= 0.5 * double(app::kEmbreeLargest)) ||
      !(norm <= 3 * app::kMaxScale) || !(norm * inverseNorm <= 3 * app::kMaxScaleRatio * (1 + 0x1p-20))) {
    throw std::invalid_argument("transform's 3x3 part (infinity norm " + number(norm) + ", of its inverse " +
                                number(inverseNorm) +
                                ") would carry rays beyond Embree's range: its scale factors must lie in [2^-16, "
                                "2^40], within a factor 2^16 of each other");
  }
  placement.similarity = similarityScale(placement.linear);

  const Bounds box = shape.bounds();
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d local{corner & 1 ? box.upper.x : box.lower.x, corner & 2 ? box.upper.y : box.lower.y,
                      corner & 4 ? box.upper.z : box.lower.z};
    for (const double x : placement.toWorld(local)) reach = std::max(reach, std::abs(x));
  }
  if (!(reach <= app::kMaxWorldCoordinate)) {
    throw std::invalid_argument("the placed shape reaches " + number(reach) +
                                ", beyond the coordinate limit: positions lie within +-2^40 (1.1e12)");
  }
  return placement;
}

}  // namespace revolve::python
