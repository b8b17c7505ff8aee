#include "support/hard_profiles.h"

#include "support/reference.h"
#include "support/test_profiles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::testing {

std::vector<Point2> stairs(int steps) {
  // A ziggurat: each step a horizontal tread then a vertical riser, so every vertex joins a
  // horizontal and a vertical segment.
  // Heights are computed once per level, so that treads are exactly horizontal (0.1 * i + 0.1 and
  // 0.1 * (i + 1) can differ by an ulp).
  std::vector<Point2> points{{0.0, 0.0}};
  for (int i = 0; i < steps; ++i) {
    const double r = 1.0 - 0.08 * i;
    points.push_back({r, 0.1 * i});
    points.push_back({r, 0.1 * (i + 1)});
  }
  points.push_back({0.0, points.back().z});
  return points;
}

std::vector<Point2> tinySegments(double tiny) {
  // A capped cylinder (r = 1, z in [0, 2]) whose four corners are cut by segments of length ~tiny,
  // and whose side has a tiny kink in the middle.
  return {{0.0, 0.0},        {1.0 - tiny, 0.0},        {1.0, tiny},
          {1.0, 1.0},        {1.0 + tiny, 1.0 + tiny}, {1.0, 1.0 + 2 * tiny},
          {1.0, 2.0 - tiny}, {1.0 - tiny, 2.0},        {0.0, 2.0}};
}

std::vector<Point2> nearDuplicates(std::mt19937_64& random) {
  // A sphere-like outline where every vertex is a cluster of three points 1e-9 apart along the
  // circle: segments of length 1e-9 next to segments of length 0.05.
  std::uniform_real_distribution<double> jitter(0.5, 1.5);
  std::vector<Point2> points{{0.0, -1.0}};
  for (int i = 1; i < 64; ++i) {
    const double theta = std::numbers::pi * i / 64;
    for (int k = -1; k <= 1; ++k) {
      const double t = theta + k * 1e-9 * jitter(random);
      points.push_back({std::sin(t), -std::cos(t)});
    }
  }
  points.push_back({0.0, 1.0});
  return points;
}

std::vector<Point2> nearlyFlatCaps() {
  // A short cylinder whose caps are cones of slope 1e-6 and 1e-7: segments of length 1 that are
  // horizontal to within 1e-6, where a quadratic set up far from the segment loses its digits.
  return {{0.0, 0.0}, {1.0, 1e-6}, {1.0, 0.2}, {0.0, 0.2 + 1e-7}};
}

std::vector<Point2> manyPointVase(int count) {
  std::vector<Point2> points{{0.0, 0.0}};
  for (int i = 0; i < count - 2; ++i) {
    const double s = double(i) / (count - 3);
    const double bulge = std::sin(std::numbers::pi * (0.1 + 0.8 * s));
    points.push_back({0.25 + 0.25 * bulge * bulge - 0.15 * s + 0.1 * std::pow(s, 4), 1.5 * s});
  }
  points.push_back({0.0, 1.5});
  return points;
}

std::vector<ClosedProfile> closedProfiles() {
  std::mt19937_64 random(77);
  std::vector<ClosedProfile> profiles;
  for (const NamedProfile& named : standardProfiles()) {
    const Profile profile(named.points);
    if (profile.closed()) profiles.push_back({named.name, named.points});
  }
  profiles.push_back({"stairs: horizontal and vertical runs", stairs(10)});
  profiles.push_back({"tiny segments (1e-6)", tinySegments(1e-6)});
  profiles.push_back({"near-duplicate points (1e-9)", nearDuplicates(random)});
  profiles.push_back({"vase, 20001 points", manyPointVase(20001)});
  profiles.push_back({"nearly flat caps (slopes 1e-6, 1e-7)", nearlyFlatCaps()});
  return profiles;
}

bool insideMeridianRegion(std::span<const Point2> profile, long double rho, long double z) {
  bool inside = false;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const long double r0 = profile[k].r, z0 = profile[k].z, r1 = profile[k + 1].r, z1 = profile[k + 1].z;
    if ((z0 > z) == (z1 > z)) continue;  // half-open: a vertex counts for one side only
    const long double crossing = r0 + (z - z0) * (r1 - r0) / (z1 - z0);
    if (crossing > rho) inside = !inside;
  }
  return inside;  // a closing segment on the axis (r = 0) is never to the right of rho >= 0
}

std::vector<Vec3> interiorPoints(std::span<const Point2> profile, std::mt19937_64& random, std::size_t count,
                                 double margin) {
  double rMax = 0.0, zMin = profile[0].z, zMax = profile[0].z;
  for (const Point2& p : profile) {
    rMax = std::max(rMax, p.r);
    zMin = std::min(zMin, p.z);
    zMax = std::max(zMax, p.z);
  }
  std::uniform_real_distribution<double> x(-rMax, rMax), z(zMin, zMax);
  std::vector<Vec3> points;
  while (points.size() < count) {
    const Vec3 p{float(x(random)), float(x(random)), float(z(random))};
    const long double rho = std::hypot((long double)p.x, (long double)p.y);
    if (!insideMeridianRegion(profile, rho, p.z)) continue;
    if (reference::meridianDistance(profile, p.x, p.y, p.z) < margin) continue;
    points.push_back(p);
  }
  return points;
}

}  // namespace revolve::testing
