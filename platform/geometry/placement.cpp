#include "geometry/placement.h"

#include "geometry/ray_limits.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace revolve::app {
namespace {

// Every digit a double needs (65537 must not read as a rounded 6.55e+04 within 65536).
std::string shortest(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

// The largest eigenvalue of the symmetric positive semi-definite 3x3 matrix `a`, by the closed form
// of its characteristic cubic (Smith 1961): within a few units of rounding of |a| (the error of
// the trigonometric root is relative to the spread of the eigenvalues, at most the largest).
double largestEigenvalue(const Matrix3d& a) {
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3;
  const double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  const double p2 =
      (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) + (a[2][2] - q) * (a[2][2] - q) + 2 * p1;
  if (!(p2 > 0)) return q;  // a multiple of the identity (or NaN, which passes on)
  const double p = std::sqrt(p2 / 6);
  Matrix3d b = a;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) b[i][j] = (a[i][j] - (i == j ? q : 0.0)) / p;
  }
  const double r = std::clamp(
      0.5 * (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
             b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0])),
      -1.0, 1.0);
  return q + 2 * p * std::cos(std::acos(r) / 3);
}

// The largest singular value of m: the square root of the largest eigenvalue of m^T m.
double largestSingularValue(const Matrix3d& m) { return std::sqrt(largestEigenvalue(m.transposed() * m)); }

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

Vec3d applyAffine(const Matrix3d& m, const Vec3d& v, const Vec3d& t) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2] + t[0],
          m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2] + t[1],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2] + t[2]};
}

}  // namespace

Matrix3d rotationOf(const Transform& transform) {
  return rotationAbout(transform.rotateAxis, transform.rotateDegrees * std::numbers::pi / 180.0);
}

Matrix3d linearPart(const Transform& transform) {
  Matrix3d m = rotationOf(transform);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i][j] *= transform.scale[j];
  }
  return m;
}

Matrix3d inverseLinearPart(const Transform& transform) {
  const Matrix3d rotation = rotationOf(transform);
  Matrix3d inverse;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) inverse[i][j] = rotation[j][i] / transform.scale[i];
  }
  return inverse;
}

Vec3d rotate(const Transform& transform, const Vec3d& v) {
  const double theta = transform.rotateDegrees * std::numbers::pi / 180.0, c = std::cos(theta), s = std::sin(theta);
  const Vec3d& k = transform.rotateAxis;
  const Vec3d kv = cross(k, v);
  const double along = dot(k, v);
  Vec3d out;
  for (int i = 0; i < 3; ++i) out[i] = v[i] * c + kv[i] * s + k[i] * along * (1 - c);
  return out;
}

std::optional<std::string> scaleFactorFault(double factor, std::string_view written) {
  const std::string text = written.empty() ? shortest(factor) : std::string(written);
  if (!(factor > 0)) return text + " is not positive: scale factors must be > 0";
  if (!(factor >= kMinScale && factor <= kMaxScale)) return text + " is out of range: " + kScaleFactorRule;
  return std::nullopt;
}

std::optional<std::string> scaleRatioFault(double smallest, double largest) {
  if (largest <= kMaxScaleRatio * smallest) return std::nullopt;
  return "the scale factors differ by a factor " + shortest(largest / smallest) +
         ": they lie within a factor 2^16 (65536) of each other, so that Embree's float transform keeps rays leaving "
         "the object within range";
}

std::optional<std::string> reachFault(double reach) {
  if (reach <= kMaxWorldCoordinate) return std::nullopt;
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", reach);  // computed: three digits say it
  return std::string("the placed object reaches ") + text + ", beyond the coordinate limit: " + kCoordinateLimitRule;
}

Placement::Placement(const Transform& transform)
    : linear_(linearPart(transform)), inverse_(inverseLinearPart(transform)), translate_(transform.translate) {
  for (const double s : transform.scale) {
    if (std::optional<std::string> fault = scaleFactorFault(s, {})) throw PlacementError(*fault);
  }
  const auto [smallest, largest] = std::minmax({transform.scale[0], transform.scale[1], transform.scale[2]});
  if (std::optional<std::string> fault = scaleRatioFault(smallest, largest)) throw PlacementError(*fault);
  similarity_ = similarityScale(linear_);
}

Placement Placement::fromRows(const double rows[16], std::string_view name) {
  const std::string what(name);
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(rows[i])) {
      throw PlacementError(what + "[" + std::to_string(i / 4) + ", " + std::to_string(i % 4) +
                           "] = " + shortest(rows[i]) + " is not finite");
    }
  }
  if (rows[12] != 0 || rows[13] != 0 || rows[14] != 0 || rows[15] != 1) {
    throw PlacementError(what + "'s last row is (" + shortest(rows[12]) + ", " + shortest(rows[13]) + ", " +
                         shortest(rows[14]) + ", " + shortest(rows[15]) +
                         "); a placement is affine: its last row must be (0, 0, 0, 1)");
  }
  Placement placement;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) placement.linear_[r][c] = rows[4 * r + c];
    placement.translate_[r] = rows[4 * r + 3];
  }
  placement.inverse_ = app::inverse(placement.linear_);
  // The scale factors are the singular values: the largest of the linear part, and the smallest as
  // the reciprocal of its inverse's largest (each a largest eigenvalue, computed within 2^-48 of
  // itself). Within 2^-40 of a limit they count as at it, so that a factor written exactly at a
  // limit (a matrix of 2^-16 on its diagonal) is taken as written.
  const double largest = largestSingularValue(placement.linear_);
  const double smallest = 1 / largestSingularValue(placement.inverse_);
  if (!(smallest > 0)) {
    throw PlacementError(what + "'s 3x3 part is singular (a scale factor of 0): " + kScaleFactorRule);
  }
  constexpr double kComputed = 0x1p-40;
  const auto snapped = [](double factor) {
    for (const double limit : {kMinScale, kMaxScale}) {
      if (std::abs(factor - limit) <= kComputed * limit) return limit;
    }
    return factor;
  };
  for (const auto& [factor, which] : {std::pair{smallest, "smallest"}, std::pair{largest, "largest"}}) {
    if (const double at = snapped(factor); !(at >= kMinScale && at <= kMaxScale)) {
      throw PlacementError(what + "'s 3x3 part scales by " + shortest(factor) + " (its " + which +
                           " singular value): " + kScaleFactorRule);
    }
  }
  if (largest > kMaxScaleRatio * smallest * (1 + kComputed)) {
    throw PlacementError(what + "'s 3x3 part: " + *scaleRatioFault(smallest, largest));
  }
  placement.similarity_ = similarityScale(placement.linear_);
  return placement;
}

Vec3d Placement::toWorld(const Vec3d& p) const { return plus(linear_.apply(p), translate_); }

Vec3d Placement::toObject(const Vec3d& p) const { return inverse_.apply(minus(p, translate_)); }

Vec3d Placement::normalToWorld(const Vec3d& n) const {
  const Matrix3d& m = inverse_;
  const Vec3d w{m[0][0] * n[0] + m[1][0] * n[1] + m[2][0] * n[2], m[0][1] * n[0] + m[1][1] * n[1] + m[2][1] * n[2],
                m[0][2] * n[0] + m[1][2] * n[1] + m[2][2] * n[2]};
  const double length = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  return {w[0] / length, w[1] / length, w[2] / length};
}

std::array<float, 12> Placement::embreeColumns() const {
  std::array<float, 12> columns{};
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) columns[3 * c + r] = float(linear_[r][c]);
  }
  for (int r = 0; r < 3; ++r) columns[9 + r] = float(translate_[r]);
  return columns;
}

double Placement::reach(const Vec3d& lower, const Vec3d& upper) const {
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d local{corner & 1 ? upper[0] : lower[0], corner & 2 ? upper[1] : lower[1],
                      corner & 4 ? upper[2] : lower[2]};
    for (const double x : applyAffine(linear_, local, translate_)) reach = std::max(reach, std::abs(x));
  }
  return reach;
}

double worldReach(const Profile& profile, const Placement& placement) {
  return worldReach(profile.points(), placement);
}

double worldReach(std::span<const Point2> points, const Placement& placement) {
  double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
  for (const Point2 p : points) rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
  return placement.reach({-rMax, -rMax, zLow}, {rMax, rMax, zHigh});
}

}  // namespace revolve::app
