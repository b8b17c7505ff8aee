#include "scale/scale_family.h"

#include "random/counter_hash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace revolve::bench {
namespace {

// A uniform number in [0, 1) for object i's parameter k.
double uniform(std::uint64_t seed, std::size_t i, int k) {
  const std::uint64_t bits = app::mix64(app::mix64(app::mix64(seed) ^ std::uint64_t(i)) + std::uint64_t(k));
  return double(bits >> 11) * 0x1p-53;
}

}  // namespace

double ScaleFamily::smoothRadius(std::size_t i, double z) const {
  // A vase: a base radius, two waves of random frequency and phase, and a taper. Radius within
  // [0.05, 0.6]: 0.2..0.35 x (1 +- 0.35 +- 0.15) + 0.1 z at most.
  const double base = 0.2 + 0.15 * uniform(seed, i, 0);
  const double a1 = 0.35 * uniform(seed, i, 1), f1 = 0.5 + 2.0 * uniform(seed, i, 2), p1 = uniform(seed, i, 3);
  const double a2 = 0.15 * uniform(seed, i, 4), f2 = 2.0 + 4.0 * uniform(seed, i, 5), p2 = uniform(seed, i, 6);
  const double taper = 0.1 * (2.0 * uniform(seed, i, 7) - 1.0);
  const double wave =
      a1 * std::sin(2 * std::numbers::pi * (f1 * z + p1)) + a2 * std::sin(2 * std::numbers::pi * (f2 * z + p2));
  return std::max(0.05, base * (1.0 + wave) + taper * z);
}

std::vector<Point2> ScaleFamily::points(std::size_t i) const {
  // The bottom closes on the axis; the other 63 points sample r(z) evenly in z.
  std::vector<Point2> p;
  p.reserve(kPoints);
  p.push_back({0.0, 0.0});
  for (std::size_t k = 0; k + 1 < kPoints; ++k) {
    const double z = double(k) / double(kPoints - 2);
    p.push_back({smoothRadius(i, z), z});
  }
  return p;
}

std::size_t ScaleFamily::gridSide(std::size_t count) {
  auto side = std::size_t(std::ceil(std::sqrt(double(count))));
  while (side * side < count) ++side;
  return std::max<std::size_t>(side, 1);
}

app::Transform ScaleFamily::transform(std::size_t i, std::size_t count) const {
  const std::size_t side = gridSide(count);
  app::Transform t;
  const double s = 0.8 + 0.2 * uniform(seed, i, 8);
  t.scale = {s, s, s};
  t.translate = {kSpacing * double(i % side), kSpacing * double(i / side), 0.0};
  return t;
}

double ScaleFamily::polylineError(std::size_t objects) const {
  double worst = 0;
  for (std::size_t i = 0; i < objects; ++i) {
    const std::vector<Point2> p = points(i);
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      for (int j = 1; j < 16; ++j) {
        const double f = j / 16.0, z = p[k].z + f * (p[k + 1].z - p[k].z);
        // The horizontal gap bounds the distance to the chord from above.
        worst = std::max(worst, std::abs(smoothRadius(i, z) - (p[k].r + f * (p[k + 1].r - p[k].r))));
      }
    }
  }
  return worst;
}

io::SceneDescription familyDescription(const ScaleFamily& family, std::size_t count, const FamilyScene& how) {
  io::SceneDescription scene;
  scene.file = "revolve-bench scale (" + std::to_string(count) + " objects)";
  io::SceneMaterial clay;
  clay.name = "clay";
  scene.materials.push_back(clay);
  scene.profiles.reserve(count);
  scene.objects.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::vector<Point2> p = family.points(i);
    if (!family.isSpline(i) || !how.mesh) {
      // A polyline as it is; a spline traced exactly has none until a tool asks for one
      // (io::SceneProfile::polyline), as the scene reader makes it.
      io::SceneProfile profile{.name = {}};
      if (family.isSpline(i)) {
        profile.spline.emplace(SplineKind::catmullRom, p);
      } else {
        profile.profile = Profile(p);
      }
      scene.profiles.push_back(std::move(profile));
    } else {
      // Meshed as the scene file meshes a spline given a tolerance: its polyline, shaded by the curve.
      Spline curve(SplineKind::catmullRom, p);
      io::SceneProfile profile{.name = {}, .profile = Profile::fromCurve(curve, how.tolerance)};
      profile.curve = std::move(curve);
      scene.profiles.push_back(std::move(profile));
    }
    io::SceneObject object;
    object.profile = i;
    object.transform = family.transform(i, count);
    scene.objects.push_back(std::move(object));
  }
  return scene;
}

}  // namespace revolve::bench
