#include "geometry/matrix3d.h"

#include <algorithm>
#include <cmath>

namespace revolve::app {

Vec3 Matrix3d::applyAbsolute(Vec3 v) const {
  return {float(std::abs(m[0][0]) * v.x + std::abs(m[0][1]) * v.y + std::abs(m[0][2]) * v.z),
          float(std::abs(m[1][0]) * v.x + std::abs(m[1][1]) * v.y + std::abs(m[1][2]) * v.z),
          float(std::abs(m[2][0]) * v.x + std::abs(m[2][1]) * v.y + std::abs(m[2][2]) * v.z)};
}

double Matrix3d::infinityNorm() const {
  double worst = 0;
  for (const auto& row : m) {
    const double sum = std::abs(row[0]) + std::abs(row[1]) + std::abs(row[2]);
    worst = sum > worst || std::isnan(sum) ? sum : worst;
  }
  return worst;
}

Matrix3d Matrix3d::transposed() const {
  Matrix3d t;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) t[r][c] = m[c][r];
  }
  return t;
}

Matrix3d operator*(const Matrix3d& a, const Matrix3d& b) {
  Matrix3d c;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  }
  return c;
}

Matrix3d inverse(const Matrix3d& a) {
  const auto& m = a.m;
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Matrix3d r;
  r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  return r;
}

Matrix3d roundedToFloat(const Matrix3d& a) {
  Matrix3d r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i][j] = float(a[i][j]);
  }
  return r;
}

Matrix3d rotationAboutX(double a) {
  return {Vec3d{1, 0, 0}, Vec3d{0, std::cos(a), -std::sin(a)}, Vec3d{0, std::sin(a), std::cos(a)}};
}

Matrix3d rotationAboutY(double a) {
  return {Vec3d{std::cos(a), 0, std::sin(a)}, Vec3d{0, 1, 0}, Vec3d{-std::sin(a), 0, std::cos(a)}};
}

Matrix3d rotationAboutZ(double a) {
  return {Vec3d{std::cos(a), -std::sin(a), 0}, Vec3d{std::sin(a), std::cos(a), 0}, Vec3d{0, 0, 1}};
}

Matrix3d rotationAbout(const Vec3d& k, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return {Vec3d{c + k[0] * k[0] * (1 - c), k[0] * k[1] * (1 - c) - k[2] * s, k[0] * k[2] * (1 - c) + k[1] * s},
          Vec3d{k[1] * k[0] * (1 - c) + k[2] * s, c + k[1] * k[1] * (1 - c), k[1] * k[2] * (1 - c) - k[0] * s},
          Vec3d{k[2] * k[0] * (1 - c) - k[1] * s, k[2] * k[1] * (1 - c) + k[0] * s, c + k[2] * k[2] * (1 - c)}};
}

}  // namespace revolve::app
