#include "geometry/transform.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::scene {

Vec3 Matrix3d::applyAbsolute(Vec3 v) const {
  return {float(std::abs(m[0][0]) * v.x + std::abs(m[0][1]) * v.y + std::abs(m[0][2]) * v.z),
          float(std::abs(m[1][0]) * v.x + std::abs(m[1][1]) * v.y + std::abs(m[1][2]) * v.z),
          float(std::abs(m[2][0]) * v.x + std::abs(m[2][1]) * v.y + std::abs(m[2][2]) * v.z)};
}

double Matrix3d::infinityNorm() const {
  double worst = 0;
  for (const auto& row : m) worst = std::max(worst, std::abs(row[0]) + std::abs(row[1]) + std::abs(row[2]));
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

Matrix3d rotationOf(const io::SceneTransform& transform) {
  const double theta = transform.rotateDegrees * std::numbers::pi / 180.0;
  const double c = std::cos(theta), s = std::sin(theta);
  const auto& k = transform.rotateAxis;
  return {Vec3d{c + k[0] * k[0] * (1 - c), k[0] * k[1] * (1 - c) - k[2] * s, k[0] * k[2] * (1 - c) + k[1] * s},
          Vec3d{k[1] * k[0] * (1 - c) + k[2] * s, c + k[1] * k[1] * (1 - c), k[1] * k[2] * (1 - c) - k[0] * s},
          Vec3d{k[2] * k[0] * (1 - c) - k[1] * s, k[2] * k[1] * (1 - c) + k[0] * s, c + k[2] * k[2] * (1 - c)}};
}

Matrix3d linearPart(const io::SceneTransform& transform) {
  Matrix3d m = rotationOf(transform);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i][j] *= transform.scale[j];
  }
  return m;
}

Matrix3d inverseLinearPart(const io::SceneTransform& transform) {
  const Matrix3d rotation = rotationOf(transform);
  Matrix3d inverse;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) inverse[i][j] = rotation[j][i] / transform.scale[i];
  }
  return inverse;
}

double worldReach(const Profile& profile, const io::SceneTransform& transform) {
  double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
  for (const Point2 p : profile.points())
    rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
  const Matrix3d m = linearPart(transform);
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d local{corner & 1 ? rMax : -rMax, corner & 2 ? rMax : -rMax, corner & 4 ? zHigh : zLow};
    for (int a = 0; a < 3; ++a) {
      reach = std::max(reach,
                       std::abs(m[a][0] * local[0] + m[a][1] * local[1] + m[a][2] * local[2] + transform.translate[a]));
    }
  }
  return reach;
}

Vec3d rotate(const io::SceneTransform& transform, const Vec3d& v) {
  const double theta = transform.rotateDegrees * std::numbers::pi / 180.0, c = std::cos(theta), s = std::sin(theta);
  const Vec3d& k = transform.rotateAxis;
  const Vec3d kv{k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
  const double along = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
  Vec3d out;
  for (int i = 0; i < 3; ++i) out[i] = v[i] * c + kv[i] * s + k[i] * along * (1 - c);
  return out;
}

}  // namespace revolve::scene
