#include "support/test_profiles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::testing {
namespace {

constexpr double kPi = std::numbers::pi;

// Test profiles use float-representable coordinates, so that float rays can lie exactly in a
// vertex's plane or pass exactly through an apex.
std::vector<Point2> asFloats(std::vector<Point2> points) {
  for (Point2& p : points) p = {double(float(p.r)), double(float(p.z))};
  return points;
}

float uniform(std::mt19937_64& random, double lo, double hi) {
  return float(std::uniform_real_distribution<double>(lo, hi)(random));
}

Vec3 randomUnit(std::mt19937_64& random) {
  std::normal_distribution<double> normal;
  double x, y, z, n;
  do {
    x = normal(random), y = normal(random), z = normal(random);
    n = std::sqrt(x * x + y * y + z * z);
  } while (n < 1e-3);
  return {float(x / n), float(y / n), float(z / n)};
}

}  // namespace

std::vector<Point2> cappedCylinder(double radius, double z0, double z1) {
  return asFloats({{0, z0}, {radius, z0}, {radius, z1}, {0, z1}});
}

std::vector<Point2> sphereLike(double radius, int segments) {
  std::vector<Point2> points;
  for (int i = 0; i <= segments; ++i) {
    const double theta = kPi * i / segments;
    points.push_back({i == 0 || i == segments ? 0.0 : radius * std::sin(theta), -radius * std::cos(theta)});
  }
  return asFloats(points);
}

std::vector<Point2> torusLike(double major, double minor, int segments) {
  std::vector<Point2> points;
  for (int i = 0; i < segments; ++i) {
    const double theta = 2 * kPi * i / segments;
    points.push_back({major + minor * std::cos(theta), minor * std::sin(theta)});
  }
  points = asFloats(points);
  points.push_back(points.front());  // exactly the first point: a closed loop
  return points;
}

std::vector<Point2> hollowVase() {
  std::vector<Point2> outer;
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 40.0;
    const double bulge = std::sin(kPi * (0.15 + 0.85 * s));
    outer.push_back({0.28 + 0.22 * bulge * bulge - 0.12 * s + 0.04 * std::cos(6 * s), 1.2 * s});
  }
  std::vector<Point2> points{{0.0, 0.0}};
  points.insert(points.end(), outer.begin(), outer.end());
  points.push_back({outer.back().r - 0.015, 1.21});  // the lip
  for (int i = 40; i >= 3; --i) points.push_back({outer[i].r - 0.03, outer[i].z});
  points.push_back({0.0, outer[3].z});
  return asFloats(points);
}

std::vector<Point2> cup() {
  return asFloats({{0, 0}, {0.3, 0}, {0.3, 0.02}, {0.4, 0.02}, {0.4, 0.6}, {0.38, 0.6}, {0.38, 0.05}, {0, 0.05}});
}

std::vector<Point2> hourglass() { return asFloats({{0, -1}, {0.8, -1}, {0, 0}, {0.8, 1}, {0, 1}}); }

std::vector<Point2> zigzagColumn(int teeth) {
  std::vector<Point2> points{{0.0, 0.0}, {0.35, 0.0}};
  for (int i = 0; i <= 2 * teeth; ++i) points.push_back({0.3 + 0.1 * (i % 2), 0.05 + 0.04 * i});
  points.push_back({0.0, points.back().z});
  return asFloats(points);
}

std::vector<Point2> spindle(int segments) {
  std::vector<Point2> points;
  for (int i = 0; i <= segments; ++i) {
    const double s = double(i) / segments;
    points.push_back({i == 0 || i == segments ? 0.0 : 0.3 * std::sin(kPi * s), s});
  }
  return asFloats(points);
}

std::vector<Point2> openCone() { return asFloats({{0.0, 1.0}, {0.5, 0.0}}); }

std::vector<Point2> annulus() { return asFloats({{0.2, 0.0}, {0.6, 0.0}}); }

std::vector<Point2> starShaped(std::mt19937_64& random, int count) {
  std::vector<double> angles;
  for (int i = 0; i < count; ++i) angles.push_back(uniform(random, 0.0, 2 * kPi));
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  std::vector<Point2> points;
  for (double angle : angles) {
    const double radius = uniform(random, 0.3, 1.2);
    points.push_back({1.5 + radius * std::cos(angle), radius * std::sin(angle)});
  }
  points = asFloats(points);
  points.push_back(points.front());
  return points;
}

std::vector<NamedProfile> standardProfiles() {
  std::mt19937_64 random(20261121);
  return {
      {"capped cylinder", cappedCylinder(0.5, -0.75, 0.75)},
      {"sphere, 64 segments", sphereLike(1.0, 64)},
      {"sphere, 1000 segments", sphereLike(1.0, 1000)},
      {"torus", torusLike(1.0, 0.35, 48)},
      {"hollow vase", hollowVase()},
      {"cup", cup()},
      {"hourglass", hourglass()},
      {"zigzag column, 60 intervals", zigzagColumn(30)},
      {"spindle", spindle(200)},
      {"open cone", openCone()},
      {"annulus", annulus()},
      {"star-shaped, 40 points", starShaped(random, 40)},
  };
}

std::vector<Ray> incoherentRays(const Shape& shape, std::mt19937_64& random, std::size_t count, double spread) {
  const Bounds box = shape.bounds();
  const double cx = 0.5 * (box.lower.x + box.upper.x), cy = 0.5 * (box.lower.y + box.upper.y),
               cz = 0.5 * (box.lower.z + box.upper.z);
  const double radius =
      0.5 * std::hypot(box.upper.x - box.lower.x, box.upper.y - box.lower.y, box.upper.z - box.lower.z);
  std::vector<Ray> rays;
  rays.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 u = randomUnit(random);
    const Vec3 origin{float(cx + spread * radius * u.x), float(cy + spread * radius * u.y),
                      float(cz + spread * radius * u.z)};
    const Vec3 target{uniform(random, box.lower.x, box.upper.x), uniform(random, box.lower.y, box.upper.y),
                      uniform(random, box.lower.z, box.upper.z)};
    const float scale = uniform(random, 0.5, 2.0);  // directions need not be unit length
    rays.push_back(
        {origin, {(target.x - origin.x) * scale, (target.y - origin.y) * scale, (target.z - origin.z) * scale}});
  }
  return rays;
}

std::vector<Ray> axisAlignedRays(const Shape& shape, std::mt19937_64& random, std::size_t count) {
  const Bounds box = shape.bounds();
  const std::span<const Point2> points = shape.profile().points();
  const float reach = 2.0f * std::max(box.upper.x, box.upper.z - box.lower.z);
  const auto randomHeight = [&] {
    // Half of the heights are exactly a vertex's: rays in a vertex plane, or through an apex.
    if (random() % 2 == 0) return float(points[random() % points.size()].z);
    return uniform(random, box.lower.z, box.upper.z);
  };
  std::vector<Ray> rays;
  rays.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const float phi = uniform(random, 0.0, 2 * kPi);
    const float c = std::cos(phi), s = std::sin(phi);
    switch (i % 4) {
      case 0: {  // along the axis, on it or near it
        const float offset = random() % 3 == 0 ? 0.0f : uniform(random, 0.0, box.upper.x);
        const float sign = random() % 2 == 0 ? 1.0f : -1.0f;
        rays.push_back({{offset * c, offset * s, sign > 0 ? box.lower.z - reach : box.upper.z + reach}, {0, 0, sign}});
        break;
      }
      case 1: {  // through the axis: origin + direction lands exactly on it
        const Vec3 origin{reach * c, reach * s, randomHeight() + uniform(random, -reach, reach)};
        rays.push_back({origin, {-origin.x, -origin.y, randomHeight() - origin.z}});
        break;
      }
      case 2: {  // perpendicular to the axis (dz = 0), often in a vertex's plane
        const float offset = uniform(random, -box.upper.x, box.upper.x);
        rays.push_back({{reach * c - offset * s, reach * s + offset * c, randomHeight()}, {-c, -s, 0.0f}});
        break;
      }
      default: {  // perpendicular and through the axis
        rays.push_back({{reach * c, reach * s, randomHeight()}, {-c, -s, 0.0f}});
        break;
      }
    }
  }
  return rays;
}

}  // namespace revolve::testing
