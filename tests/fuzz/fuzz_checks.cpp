#include "fuzz_checks.h"
#include <revolve/baselines.h>
#include <revolve/embree_baselines.h>

#include "embree/tessellation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace revolve::fuzz {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Bit for bit (a NaN equals the same NaN: the checks below report NaNs for what they are).
bool sameHit(const std::optional<Hit>& a, const std::optional<Hit>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  const auto bits = [](const Hit& h) {
    const auto b = [](float x) { return std::bit_cast<std::uint32_t>(x); };
    return std::array<std::uint32_t, 7>{b(h.t), h.segment, b(h.normal.x), b(h.normal.y), b(h.normal.z), b(h.u), b(h.v)};
  };
  return bits(*a) == bits(*b);
}

// The promises of revolve.h for one ray: intersect's hit lies in [tnear, tfar] on a real segment
// with a unit normal and u, v in range; occluded agrees with it; counting statistics (a separate
// instantiation of the search) changes nothing.
void checkRay(const Shape& shape, const Ray& ray, std::mt19937_64& random) {
  const std::optional<Hit> hit = intersect(shape, ray);
  // On failure, the ray and the answer, as a reproducer needs them (%a: exact).
  const auto require = [&](bool condition, const char* what) {
    if (condition) return;
    std::fprintf(stderr, "method %d; ray o = (%a, %a, %a) d = (%a, %a, %a) [%a, %a]: ", int(shape.options().method),
                 ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z, ray.tnear,
                 ray.tfar);
    if (hit) {
      std::fprintf(stderr, "hit t = %a segment %u n = (%a, %a, %a) u = %a v = %a\n", hit->t, hit->segment,
                   hit->normal.x, hit->normal.y, hit->normal.z, hit->u, hit->v);
    } else {
      std::fprintf(stderr, "miss\n");
    }
    fail(what, __FILE__, __LINE__);
  };
  Stats stats;
  require(sameHit(hit, intersect(shape, ray, &stats)), "counting stats changes the answer");
  require(occluded(shape, ray) == hit.has_value(), "occluded disagrees with intersect");
  require(occluded(shape, ray, &stats) == hit.has_value(), "occluded (counting) disagrees with intersect");
  if (!hit) return;
  require(ray.tnear <= hit->t && hit->t <= ray.tfar, "t outside [tnear, tfar]");
  require(hit->segment < shape.profile().segmentCount(), "no such segment");
  require(finite(hit->normal), "normal not finite");
  const double length = std::sqrt(double(hit->normal.x) * hit->normal.x + double(hit->normal.y) * hit->normal.y +
                                  double(hit->normal.z) * hit->normal.z);
  require(std::abs(length - 1.0) < 1e-3, "normal not unit");
  require(hit->u >= 0.0f && hit->u < 1.0f, "u outside [0, 1)");
  require(hit->v >= 0.0f && hit->v <= 1.0f, "v outside [0, 1]");

  // A secondary ray from the hit: only that it runs (its promise needs a geometric judgement).
  std::normal_distribution<float> normal;
  const Vec3 direction{normal(random), normal(random), normal(random)};
  Ray secondary{offsetRayOrigin(ray, hit->t, hit->normal, direction), direction};
  (void)intersect(shape, secondary);
}

Vec3 randomDirection(std::mt19937_64& random) {
  std::normal_distribution<double> normal;
  for (;;) {
    const Vec3 d{float(normal(random)), float(normal(random)), float(normal(random))};
    if (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f) return d;
  }
}

// Rays aimed at `target` from outside the box, or starting on it, with assorted lengths of
// direction and windows.
void raysThrough(const Shape& shape, Vec3 target, float reach, std::mt19937_64& random) {
  Vec3 d = randomDirection(random);
  // Directions need not be unit length: scale by 2^k.
  const float scale = std::ldexp(1.0f, int(random() % 41) - 20);
  d = {d.x * scale, d.y * scale, d.z * scale};
  const double back = double(reach) / scale;
  const Vec3 origin{float(target.x - back * d.x), float(target.y - back * d.y), float(target.z - back * d.z)};
  checkRay(shape, {origin, d}, random);
  // A window around the target: [t - e, t + e] with t = back.
  const float t = float(back), e = float(back * std::ldexp(1.0, -int(random() % 30)));
  if (std::isfinite(t) && std::isfinite(e)) {
    checkRay(shape, {origin, d, std::max(0.0f, t - e), t + e}, random);
    checkRay(shape, {origin, d, t, t}, random);
  }
  // From the target itself: a hit at t = 0 or the surface elsewhere.
  checkRay(shape, {target, d}, random);
  checkRay(shape, {target, {-d.x, -d.y, -d.z}, 0.0f, kInf}, random);
}

// Every query on `shape` (a profile's or a spline's; `profile` is shape.profile()).
void exerciseShape(const Shape& shape, const Profile& profile, std::mt19937_64& random) {
  const std::span<const Point2> points = profile.points();
  FUZZ_CHECK(shape.memoryBytes() > 0);
  (void)shape.treeNodeCount();
  const Bounds box = shape.bounds();
  const float reach = 2.0f * std::max({std::abs(box.lower.x), std::abs(box.upper.x), std::abs(box.lower.z),
                                       std::abs(box.upper.z), 1.0f});

  // Vertices and segment midpoints, at a random azimuth; at most 6 of each (first, last, random).
  const std::size_t n = points.size();
  for (int k = 0; k < 6; ++k) {
    const std::size_t i = k == 0 ? 0 : k == 1 ? n - 1 : random() % n;
    const double phi = std::uniform_real_distribution<double>(0.0, 2 * std::numbers::pi)(random);
    const Point2 p = points[i];
    const Point2 q = points[std::min(i + 1, n - 1)];
    const Point2 m{0.5 * p.r + 0.5 * q.r, 0.5 * p.z + 0.5 * q.z};
    for (const Point2 at : {p, m}) {
      const Vec3 target{float(at.r * std::cos(phi)), float(at.r * std::sin(phi)), float(at.z)};
      raysThrough(shape, target, reach, random);
      if (std::isfinite(target.x) && std::isfinite(target.y) && std::isfinite(target.z)) {
        const SurfacePoint closest = closestPoint(shape, target);
        FUZZ_CHECK(closest.segment < profile.segmentCount());
        FUZZ_CHECK(!(closest.distance < 0.0f));
      }
    }
    // Across the axis in the vertex's plane, and along the axis from above and below.
    checkRay(shape, {{-reach, 0.0f, float(p.z)}, {1.0f, 0.0f, 0.0f}}, random);
    checkRay(shape, {{0.0f, 0.0f, box.upper.z + reach}, {0.0f, 0.0f, -1.0f}}, random);
    checkRay(shape, {{0.0f, 0.0f, box.lower.z - reach}, {0.0f, 0.0f, 1.0f}}, random);
  }
}

BuildOptions randomMibit(std::mt19937_64& random) {
  BuildOptions mibit;
  mibit.shell = static_cast<ShellKind>(random() % 3);
  mibit.subdivisions = static_cast<std::uint32_t>(random() % 4);
  mibit.monotoneSplit = random() % 4 != 0;
  mibit.rangeSearch = random() % 4 != 0;
  return mibit;
}

}  // namespace

void exerciseShapes(const Profile& profile, std::mt19937_64& random) {
  const std::span<const Point2> points = profile.points();
  FUZZ_CHECK(points.size() >= 2);
  FUZZ_CHECK(profile.arcLength().size() == points.size());
  FUZZ_CHECK(profile.sourceIndex().size() == points.size());
  FUZZ_CHECK(std::is_sorted(profile.sourceIndex().begin(), profile.sourceIndex().end()));

  BuildOptions linear;
  linear.method = Method::linear;
  BuildOptions kajiya;
  kajiya.method = Method::kajiya;
  for (const BuildOptions& options : {randomMibit(random), linear, kajiya})
    exerciseShape(Shape(profile, options), profile, random);

  // The tessellated baseline, while small: indices stay inside the vertex array.
  const std::uint32_t slices = 3 + static_cast<std::uint32_t>(random() % 6);
  if (profile.segmentCount() * slices <= 4096) {
    const detail::TriangleMesh mesh = detail::tessellate(profile, slices);
    FUZZ_CHECK(mesh.indices.size() == 6 * profile.segmentCount() * slices);
    for (const std::uint32_t index : mesh.indices) FUZZ_CHECK(3 * std::size_t{index} < mesh.vertices.size());
    FUZZ_CHECK(!(tessellationError(profile, slices) < 0.0));
  }
}

void exerciseSplineShapes(const Spline& spline, std::mt19937_64& random) {
  FUZZ_CHECK(spline.pieceCount() >= 1);
  FUZZ_CHECK(spline.bezier().size() == 3 * spline.pieceCount() + 1);
  BuildOptions linear;
  linear.method = Method::linear;
  for (const BuildOptions& options : {randomMibit(random), linear}) {
    const Shape shape(spline, options);
    const Profile& profile = shape.profile();
    FUZZ_CHECK(profile.points().size() >= 2);
    FUZZ_CHECK(profile.arcLength().size() == profile.points().size());
    if (spline.kind() != SplineKind::linear) {
      FUZZ_CHECK(shape.spline() != nullptr);
      for (std::uint32_t k = 0; k < profile.segmentCount(); ++k) FUZZ_CHECK(shape.splinePiece(k) < spline.pieceCount());
    }
    exerciseShape(shape, profile, random);
  }
}

}  // namespace revolve::fuzz
