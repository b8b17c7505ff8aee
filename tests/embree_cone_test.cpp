// Embree's linear cone curve as the benchmark's baseline (ConeCurveGeometry): which profiles it
// refuses and why, and that on those it takes it traces the same surface as MIBIT, so that the
// benchmark compares like with like. The verdicts come from the long-double oracle
// (support/reference.h), independent of both.
#include "support/reference.h"
#include "support/test_scale.h"

#include "embree/embree_handles.h"

#include <revolve/embree_baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

using app::DeviceRelease;  // the applications' owning handles (common/embree_handles.h)
using app::SceneRelease;

std::string limitationOf(std::vector<Point2> points) { return coneCurveLimitation(Profile(points)).value_or(""); }

TEST(ConeCurveLimitationTest, RefusesWhatACurveCannotExpressAndSaysWhere) {
  // A step: the horizontal segment between points 2 and 3 is a ring between two cones.
  const std::string step = limitationOf({{0, 0}, {1, 0}, {1, 1}, {0.5, 1}, {0.5, 2}, {0, 2}});
  EXPECT_NE(step.find("profile point 2 (r = 1, z = 1) to profile point 3 (r = 0.5, z = 1) is horizontal"),
            std::string::npos)
      << step;
  // An open end off the axis: Embree would close it with a disc.
  const std::string open = limitationOf({{0, 0}, {1, 0}, {1, 1}});
  EXPECT_NE(open.find("ends at profile point 2 (r = 1, z = 1), off the axis"), std::string::npos) << open;
  // A flat ring as an end: a curve's end disc is whole.
  const std::string ring = limitationOf({{0.5, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_NE(ring.find("profile point 0 (r = 0.5, z = 0) to profile point 1 (r = 1, z = 0) is horizontal"),
            std::string::npos)
      << ring;
  // A loop's flat chord has no end to be a disc at.
  const std::string loop = limitationOf({{1, 0}, {2, 0}, {2, 1}, {1, 0}});
  EXPECT_NE(loop.find("is horizontal"), std::string::npos) << loop;
  // Heights that differ in double but not in float: a ring to Embree.
  const std::string flat = limitationOf({{0, 0}, {1, 0}, {1, 1}, {0.5, 1 + 1e-12}, {0.5, 2}, {0, 2}});
  EXPECT_NE(flat.find("is horizontal in single precision"), std::string::npos) << flat;
  // Nothing but discs.
  EXPECT_NE(limitationOf({{0, 0}, {1, 0}}).find("only flat discs"), std::string::npos);
  EXPECT_NE(limitationOf({{0, 0}, {1, 0}, {2, 0}}).find("only flat discs"), std::string::npos);

  const std::unique_ptr<RTCDeviceTy, DeviceRelease> device(rtcNewDevice(nullptr));
  try {
    ConeCurveGeometry refused(device.get(), Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}}));
    ADD_FAILURE() << "an open end was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), open);
  }
}

TEST(ConeCurveLimitationTest, TakesDiscEndsApexesLoopsAndAxisPointsBetweenSegments) {
  EXPECT_EQ(limitationOf({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), "");                  // a closed can: two end discs
  EXPECT_EQ(limitationOf({{0, 0}, {1, 1}, {0, 2}}), "");                          // apexes at both ends
  EXPECT_EQ(limitationOf({{0, 0}, {0.5, 0.5}, {0, 1}, {0.4, 1.5}, {0, 2}}), "");  // touching the axis between
  EXPECT_EQ(limitationOf({{1, 0}, {2, 1}, {1, 2}, {0.5, 1}, {1, 0}}), "");        // a loop
  EXPECT_EQ(limitationOf({{0, 1}, {1, 1}, {1, 0}, {0, 0}}), "");                  // listed downwards
  EXPECT_EQ(limitationOf({{0, 0}, {1, 0}, {1, 1}, {0, 1 + 1e-12}}), "");          // flat to Embree: an end disc
}

struct NamedProfile {
  const char* name;
  std::vector<Point2> points;
};

std::vector<Point2> arcPoints(double centreR, double centreZ, double radius, double from, double to, int segments) {
  std::vector<Point2> points;
  for (int i = 0; i <= segments; ++i) {
    const double a = from + (to - from) * i / segments;
    points.push_back({std::max(0.0, centreR + radius * std::cos(a)), centreZ + radius * std::sin(a)});
  }
  return points;
}

std::vector<NamedProfile> expressibleProfiles() {
  constexpr double pi = std::numbers::pi;
  std::vector<NamedProfile> profiles;
  // A vase: flat bottom and top discs, a belly and a neck.
  profiles.push_back(
      {"vase", {{0, 0}, {0.3, 0}, {0.45, 0.2}, {0.5, 0.45}, {0.35, 0.75}, {0.3, 0.85}, {0.38, 1.0}, {0, 1.0}}});
  // A sphere polygon ending on the axis (apexes), 32 segments.
  std::vector<Point2> sphere = arcPoints(0, 0.5, 0.5, -pi / 2, pi / 2, 32);
  sphere.front().r = sphere.back().r = 0;
  profiles.push_back({"sphere", sphere});
  // A torus polygon of 16 segments (even: no horizontal chord), a loop.
  std::vector<Point2> torus = arcPoints(0.35, 0.15, 0.15, -pi / 2, 3 * pi / 2, 16);
  torus.back() = torus.front();
  profiles.push_back({"torus", torus});
  // Two double cones touching the axis between them.
  profiles.push_back({"axis point", {{0, 0}, {0.5, 0.5}, {0, 1}, {0.4, 1.5}, {0, 2}}});
  // A can listed from the top down: revolve's normals point into it, Embree's still out.
  profiles.push_back({"downwards", {{0, 1}, {0.5, 1}, {0.5, 0}, {0, 0}}});
  return profiles;
}

// On rays whose exact verdict (the oracle's) is robust, the cone curve and MIBIT both give it, and
// the cone curve's hit lies on the surface, on the segment it names, with revolve's normal once
// turned by normalSign. Robust: the same verdict for the ray's origin moved by +-delta along each
// axis. The cone kernel's answer is the exact one for a ray and cones perturbed by a few dozen
// float roundings (2^-24 each) of lengths up to ~4 sizes (the rays start 3 sizes away): below
// 2^-16 of the size. delta = 2^-12 of the size is 16 times that.
TEST(ConeCurveTest, AgreesWithMibitWhereTheVerdictIsCertain) {
  const std::unique_ptr<RTCDeviceTy, DeviceRelease> device(rtcNewDevice(nullptr));
  const std::size_t rayCount = testing::scaledRays(20000);
  for (const NamedProfile& named : expressibleProfiles()) {
    SCOPED_TRACE(named.name);
    const Profile profile(named.points);
    const Shape shape(profile);
    const ConeCurveGeometry cone(device.get(), profile);
    const std::unique_ptr<RTCSceneTy, SceneRelease> scene(rtcNewScene(device.get()));
    rtcAttachGeometry(scene.get(), cone.handle());
    rtcCommitScene(scene.get());

    double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
    for (const Point2& p : named.points)
      rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
    const double size = std::max(2 * rMax, zHigh - zLow), zMid = 0.5 * (zLow + zHigh);
    const long double delta = std::ldexp(size, -12);

    std::mt19937_64 random(18);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit(-0.5, 0.5);
    std::size_t certain = 0, certainHits = 0;
    for (std::size_t i = 0; i < rayCount; ++i) {
      double u[3] = {normal(random), normal(random), normal(random)};
      const double length = std::hypot(u[0], u[1], u[2]);
      const Vec3 origin{float(3 * size * u[0] / length), float(3 * size * u[1] / length),
                        float(zMid + 3 * size * u[2] / length)};
      const Vec3 target{float(2 * rMax * unit(random)), float(2 * rMax * unit(random)),
                        float(zMid + (zHigh - zLow) * unit(random))};
      // Unit directions: Embree's cone kernel assumes them (EmbreeConeKernelAssumesUnitDirections).
      const double d[3] = {double(target.x) - origin.x, double(target.y) - origin.y, double(target.z) - origin.z};
      const double dLength = std::hypot(d[0], d[1], d[2]);
      Ray ray;
      ray.origin = origin;
      ray.direction = {float(d[0] / dLength), float(d[1] / dLength), float(d[2] / dLength)};

      const reference::RefRay exact{origin.x,        origin.y,        origin.z, ray.direction.x,
                                    ray.direction.y, ray.direction.z, 0.0L,     INFINITY};
      const bool hit = reference::intersectProfile(named.points, exact).has_value();
      bool robust = true;
      for (int axis = 0; axis < 3 && robust; ++axis) {
        for (long double sign : {-1.0L, 1.0L}) {
          reference::RefRay moved = exact;
          (axis == 0 ? moved.ox : axis == 1 ? moved.oy : moved.oz) += sign * delta;
          robust = robust && reference::intersectProfile(named.points, moved).has_value() == hit;
        }
      }
      if (!robust) continue;
      ++certain;
      certainHits += hit;

      SCOPED_TRACE(::testing::Message() << "ray " << i);
      EXPECT_EQ(intersect(shape, ray).has_value(), hit);
      embree::RayQuery query;
      RTCRayHit rayHit{};
      rayHit.ray = {origin.x, origin.y, origin.z, 0.0f, ray.direction.x, ray.direction.y, ray.direction.z, 0.0f,
                    INFINITY, ~0u,      0u,       0u};
      rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      query.intersect(scene.get(), rayHit);
      ASSERT_EQ(rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID, hit);
      if (!hit) continue;
      const long double t = rayHit.ray.tfar;
      const long double p[3] = {origin.x + t * ray.direction.x, origin.y + t * ray.direction.y,
                                origin.z + t * ray.direction.z};
      EXPECT_LE(reference::meridianDistance(named.points, p[0], p[1], p[2]), delta);
      // On the segment it names, with revolve's side of that segment.
      const Vec3 ng{rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z};
      const std::uint32_t segment = cone.profileSegment(rayHit.hit.primID, rayHit.hit.u, ng);
      ASSERT_LT(segment, profile.segmentCount());
      const std::span<const Point2> pair(named.points.data() + segment, 2);
      EXPECT_LE(reference::meridianDistance(pair, p[0], p[1], p[2]), delta) << "segment " << segment;
      const Point2 a = named.points[segment], b = named.points[segment + 1];
      const long double rho = std::hypot(p[0], p[1]);
      const long double c = rho > 0 ? p[0] / rho : 1, s = rho > 0 ? p[1] / rho : 0;
      const long double truth[3] = {(b.z - a.z) * c, (b.z - a.z) * s, -(b.r - a.r)};  // right of travel
      const float sign = cone.normalSign(rayHit.hit.primID);
      EXPECT_GT(sign * (ng.x * truth[0] + ng.y * truth[1] + ng.z * truth[2]), 0) << "segment " << segment;
    }
    // Most rays are far from any silhouette, and both answers occur.
    EXPECT_GT(certain, rayCount * 9 / 10);
    EXPECT_GT(certainHits, certain / 10);
    EXPECT_GT(certain - certainHits, certain / 100);
  }
}

// Why the benchmark's rays and revolve-render's rays reach the cone curve with unit directions:
// Embree 3.13's kernel (kernels/geometry/coneline_intersector.h) forms the ray/cone quadratic with
// the leading coefficient of a unit direction, leaving out |d|^2. A can of radius 0.5, a ray along
// x towards its axis at mid-height: with d of length 1 it hits at x = -0.5 (t = 2.5), as it should;
// with d of length 3 the exact hit is t = 2.5 / 3, and Embree answers elsewhere. If a later Embree
// fixes this, this test fails, and the normalisation can go.
TEST(ConeCurveTest, EmbreeConeKernelAssumesUnitDirections) {
  const std::unique_ptr<RTCDeviceTy, DeviceRelease> device(rtcNewDevice(nullptr));
  const ConeCurveGeometry cone(device.get(), Profile(std::vector<Point2>{{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}}));
  const std::unique_ptr<RTCSceneTy, SceneRelease> scene(rtcNewScene(device.get()));
  rtcAttachGeometry(scene.get(), cone.handle());
  rtcCommitScene(scene.get());
  const auto trace = [&](float speed) {
    embree::RayQuery query;
    RTCRayHit rayHit{};
    rayHit.ray = {-3.0f, 0.1f, 0.5f, 0.0f, speed, 0.0f, 0.0f, 0.0f, INFINITY, ~0u, 0u, 0u};
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.intersect(scene.get(), rayHit);
    // The hit's distance from the axis, or -1 for a miss.
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1.0;
    return std::hypot(-3.0 + double(rayHit.ray.tfar) * speed, 0.1);
  };
  EXPECT_NEAR(trace(1.0f), 0.5, 1e-6);  // within float rounding of the radius
  EXPECT_GT(std::abs(trace(3.0f) - 0.5), 0.1);
}

}  // namespace
}  // namespace revolve
