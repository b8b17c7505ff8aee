// Secondary rays spawned from hits with offsetRayOrigin must not re-hit the surface they leave,
// yet must find the same surface again where it really lies ahead (concave profiles). The verdict
// on every near hit comes from the long-double oracle on the very same float ray.
#include "support/hard_profiles.h"
#include "support/reference.h"
#include "support/test_profiles.h"
#include "support/test_scale.h"

#include <revolve/baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace revolve {
namespace {

double norm(Vec3 v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

reference::RefRay toRef(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

Vec3 scaled(Vec3 v, double s) { return {float(v.x * s), float(v.y * s), float(v.z * s)}; }

struct Counts {
  std::size_t spawned = 0, falseSelfHits = 0, legitimateNearHits = 0, reHits = 0, reHitsChecked = 0, reHitsWrong = 0;
};

// Spawns a ray leaving the hit of `ray` in `direction` and classifies its first hit.
void spawnAndCheck(const Shape& shape, std::span<const Point2> points, const Ray& ray, const Hit& hit, Vec3 direction,
                   double size, bool checkFarHit, Counts& counts) {
  const Vec3 origin = offsetRayOrigin(ray, hit.t, hit.normal, direction);
  const Ray spawned{origin, direction};
  ++counts.spawned;
  const std::optional<Hit> next = intersect(shape, spawned);
  if (!next) return;
  const double distance = next->t * norm(direction);
  if (distance < 1e-5 * size) {
    // So close, the hit is either the surface the ray leaves — a self-hit, whatever the oracle
    // says of the float ray, since a ray leaving a cone cannot meet it again this soon — or a
    // real corner with a neighbouring segment of a concave profile, which the oracle confirms.
    const auto truth = reference::intersectProfile(points, toRef(spawned));
    const bool corner =
        next->segment != hit.segment && truth && std::abs(double(truth->t) * norm(direction) - distance) <= 1e-6 * size;
    if (corner) {
      ++counts.legitimateNearHits;
    } else if (++counts.falseSelfHits <= 3) {
      ADD_FAILURE() << "false self-hit at distance " << distance << " from o=(" << origin.x << ", " << origin.y << ", "
                    << origin.z << ") d=(" << direction.x << ", " << direction.y << ", " << direction.z << ")";
    }
    return;
  }
  ++counts.reHits;
  if (!checkFarHit) return;
  // A sample of the far hits: the oracle agrees on where the same surface is met again.
  ++counts.reHitsChecked;
  const auto truth = reference::intersectProfile(points, toRef(spawned));
  if (!truth || std::abs(double(truth->t) - next->t) * norm(direction) > 1e-5 * size) ++counts.reHitsWrong;
}

struct Variant {
  const char* name;
  BuildOptions options;
  std::size_t primaries;  // primary rays a profile (fewer on the 20,001-point one)
};

TEST(SecondaryRaysTest, SpawnedRaysNeverReHitTheSurfaceTheyLeaveButFindItElsewhere) {
  constexpr std::uint64_t kSeed = 0x5ecd;
  const Variant variants[] = {
      {"mibit/cylinder",
       {.method = Method::mibit, .shell = ShellKind::cylinder},
       testing::scaledRays(60000)},  // the default (wide) carries the million
      {"mibit/cylinder/binary",
       {.method = Method::mibit, .shell = ShellKind::cylinder, .wideNodes = false},
       testing::scaledRays(6000)},
      {"mibit/cone", {.method = Method::mibit, .shell = ShellKind::cone}, testing::scaledRays(6000)},
      {"mibit/hybrid", {.method = Method::mibit, .shell = ShellKind::hybrid}, testing::scaledRays(6000)},
      {"linear", {.method = Method::linear}, testing::scaledRays(3000)},
      {"kajiya", {.method = Method::kajiya}, testing::scaledRays(6000)},
  };
  for (const Variant& variant : variants) {
    std::mt19937_64 random(kSeed);
    std::normal_distribution<double> gauss;
    Counts total;
    std::size_t concaveReHits = 0;
    for (const testing::ClosedProfile& closed : testing::closedProfiles()) {
      SCOPED_TRACE(std::string(variant.name) + ", " + closed.name + ", seed " + std::to_string(kSeed));
      const Shape shape(Profile(closed.points), variant.options);
      const double size = norm(shape.bounds().upper);
      Counts counts;
      const std::size_t primaries = closed.points.size() > 1000 ? variant.primaries / 3 : variant.primaries;
      for (const Ray& ray : testing::incoherentRays(shape, random, primaries)) {
        const std::optional<Hit> hit = intersect(shape, ray);
        if (!hit) continue;
        const double dn = norm(ray.direction);
        const Vec3 d = scaled(ray.direction, 1.0 / dn);
        const double dot = d.x * hit->normal.x + d.y * hit->normal.y + d.z * hit->normal.z;
        // Reflection: back to the side the ray came from.
        const Vec3 reflected{float(d.x - 2 * dot * hit->normal.x), float(d.y - 2 * dot * hit->normal.y),
                             float(d.z - 2 * dot * hit->normal.z)};
        // Shadow ray: towards a light outside the object, on either side of the surface.
        const double gx = gauss(random), gy = gauss(random), gz = gauss(random),
                     g = std::sqrt(gx * gx + gy * gy + gz * gz);
        const Vec3 light{float(3 * size * gx / g), float(3 * size * gy / g), float(3 * size * gz / g)};
        const Vec3 toLight{light.x - hit->point.x, light.y - hit->point.y, light.z - hit->point.z};
        // Transmission: straight on, through the surface.
        const bool sample = random() % 16 == 0;
        spawnAndCheck(shape, closed.points, ray, *hit, reflected, size, sample, counts);
        spawnAndCheck(shape, closed.points, ray, *hit, toLight, size, sample, counts);
        spawnAndCheck(shape, closed.points, ray, *hit, d, size, sample, counts);
      }
      if (closed.name == "hollow vase" || closed.name == "cup") concaveReHits += counts.reHits;
      total.spawned += counts.spawned;
      total.falseSelfHits += counts.falseSelfHits;
      total.legitimateNearHits += counts.legitimateNearHits;
      total.reHitsChecked += counts.reHitsChecked;
      total.reHitsWrong += counts.reHitsWrong;
    }
    std::printf(
        "hard case | secondary rays: false self-hits | %s | %zu rays | %zu wrong (%zu corner hits; %zu re-hits "
        "checked, %zu wrong)\n",
        variant.name, total.spawned, total.falseSelfHits, total.legitimateNearHits, total.reHitsChecked,
        total.reHitsWrong);
    EXPECT_EQ(total.falseSelfHits, 0u) << variant.name;
    // Legitimate re-hits of the same surface are found, where the oracle finds them.
    EXPECT_GT(concaveReHits, variant.primaries / 10) << variant.name;
    EXPECT_GT(total.reHitsChecked, variant.primaries / 10) << variant.name;
    EXPECT_EQ(total.reHitsWrong, 0u) << variant.name;
    if (variant.primaries == testing::scaledRays(60000)) {  // the default
      EXPECT_GE(total.spawned, testing::scaledRays(1'000'000));
    }
  }
}

}  // namespace
}  // namespace revolve
