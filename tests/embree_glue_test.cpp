// Every Embree path must answer what the pure C++ query answers for the same object-space ray:
// rtcIntersect1/4/8/16 and rtcOccluded1/4/8/16 with valid masks, instances, filter functions,
// point queries. The pure query is itself checked against independent references elsewhere.
#include "support/curve_reference.h"
#include "support/reference.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"

#include "embree/embree_handles.h"

#include <revolve/embree_baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>

namespace revolve {
namespace {

using app::DeviceRelease;  // the applications' owning handles (common/embree_handles.h)
using app::SceneRelease;
using DevicePtr = std::unique_ptr<RTCDeviceTy, DeviceRelease>;
using ScenePtr = std::unique_ptr<RTCSceneTy, SceneRelease>;

DevicePtr newDevice() {
  DevicePtr device(rtcNewDevice(nullptr));
  rtcSetDeviceErrorFunction(
      device.get(),
      [](void*, RTCError code, const char* message) { ADD_FAILURE() << "Embree error " << code << ": " << message; },
      nullptr);
  return device;
}

// One shape in a scene of its own.
struct SingleShapeScene {
  DevicePtr device = newDevice();
  Shape shape;
  Geometry geometry;
  ScenePtr scene;
  unsigned geomID;

  explicit SingleShapeScene(Shape s, Geometry::Options options = {})
      : shape(std::move(s)), geometry(device.get(), shape, options), scene(rtcNewScene(device.get())) {
    geomID = rtcAttachGeometry(scene.get(), geometry.handle());
    rtcCommitScene(scene.get());
  }
};

RTCRayHit toRayHit(const Ray& ray) {
  RTCRayHit rh{};
  rh.ray = {
      ray.origin.x, ray.origin.y, ray.origin.z, ray.tnear, ray.direction.x, ray.direction.y, ray.direction.z, 0.0f,
      ray.tfar,     ~0u,          0u,           0u};
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// Exact comparison of an Embree answer with the pure query's.
void expectSameHit(const std::optional<Hit>& expected, float tfar, float ngx, float ngy, float ngz, float u, float v,
                   unsigned primID, unsigned geomID, unsigned expectedGeomID, const Ray& ray) {
  SCOPED_TRACE(::testing::Message() << "ray o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z
                                    << ") d=(" << ray.direction.x << "," << ray.direction.y << "," << ray.direction.z
                                    << ")");
  if (!expected) {
    EXPECT_EQ(geomID, RTC_INVALID_GEOMETRY_ID);
    EXPECT_EQ(tfar, ray.tfar);
    return;
  }
  ASSERT_EQ(geomID, expectedGeomID);
  EXPECT_EQ(tfar, expected->t);
  EXPECT_EQ(ngx, expected->normal.x);
  EXPECT_EQ(ngy, expected->normal.y);
  EXPECT_EQ(ngz, expected->normal.z);
  EXPECT_EQ(u, expected->u);
  EXPECT_EQ(v, expected->v);
  EXPECT_EQ(primID, expected->segment);
}

class EmbreeGlueTest : public ::testing::TestWithParam<Method> {};

TEST_P(EmbreeGlueTest, Intersect1MatchesThePureQuery) {
  std::mt19937_64 random(101);
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    SCOPED_TRACE(named.name);
    SingleShapeScene s(Shape(Profile(named.points), {GetParam()}));
    std::vector<Ray> rays = testing::incoherentRays(s.shape, random, 2000);
    const std::vector<Ray> awkward = testing::axisAlignedRays(s.shape, random, 500);
    rays.insert(rays.end(), awkward.begin(), awkward.end());
    for (const Ray& ray : rays) {
      embree::RayQuery query;
      RTCRayHit rh = toRayHit(ray);
      query.intersect(s.scene.get(), rh);
      expectSameHit(intersect(s.shape, ray), rh.ray.tfar, rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z, rh.hit.u, rh.hit.v,
                    rh.hit.primID, rh.hit.geomID, s.geomID, ray);
      EXPECT_EQ(rh.hit.instID[0], RTC_INVALID_GEOMETRY_ID);
    }
  }
}

template <int N, class RayHitN>
void checkPackets(Method method) {
  std::mt19937_64 random(202 + N);
  SingleShapeScene s(Shape(Profile(testing::hollowVase()), {method}));
  const std::vector<Ray> rays = testing::incoherentRays(s.shape, random, 64 * N);
  for (std::size_t first = 0; first < rays.size(); first += N) {
    alignas(64) int valid[N];
    alignas(64) RayHitN packet{};
    for (int i = 0; i < N; ++i) {
      valid[i] = random() % 4 == 0 ? 0 : -1;  // some lanes off: they must stay untouched
      const Ray& ray = rays[first + i];
      packet.ray.org_x[i] = ray.origin.x, packet.ray.org_y[i] = ray.origin.y, packet.ray.org_z[i] = ray.origin.z;
      packet.ray.dir_x[i] = ray.direction.x, packet.ray.dir_y[i] = ray.direction.y,
      packet.ray.dir_z[i] = ray.direction.z;
      packet.ray.tnear[i] = ray.tnear, packet.ray.tfar[i] = ray.tfar, packet.ray.mask[i] = ~0u;
      packet.ray.time[i] = 0.0f, packet.ray.flags[i] = 0u;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    embree::RayQuery query;
    if constexpr (N == 4) query.intersect(valid, s.scene.get(), packet);
    if constexpr (N == 8) query.intersect(valid, s.scene.get(), packet);
    if constexpr (N == 16) query.intersect(valid, s.scene.get(), packet);
    for (int i = 0; i < N; ++i) {
      const Ray& ray = rays[first + i];
      if (valid[i] == 0) {
        EXPECT_EQ(packet.hit.geomID[i], RTC_INVALID_GEOMETRY_ID);
        EXPECT_EQ(packet.ray.tfar[i], ray.tfar);
        continue;
      }
      expectSameHit(intersect(s.shape, ray), packet.ray.tfar[i], packet.hit.Ng_x[i], packet.hit.Ng_y[i],
                    packet.hit.Ng_z[i], packet.hit.u[i], packet.hit.v[i], packet.hit.primID[i], packet.hit.geomID[i],
                    s.geomID, ray);
    }
    // Occlusion packets: tfar becomes -inf exactly for the occluded active lanes.
    alignas(64) decltype(packet.ray) shadow = packet.ray;
    for (int i = 0; i < N; ++i) shadow.tfar[i] = rays[first + i].tfar;
    if constexpr (N == 4) query.occluded(valid, s.scene.get(), shadow);
    if constexpr (N == 8) query.occluded(valid, s.scene.get(), shadow);
    if constexpr (N == 16) query.occluded(valid, s.scene.get(), shadow);
    for (int i = 0; i < N; ++i) {
      const bool expected = valid[i] != 0 && occluded(s.shape, rays[first + i]);
      EXPECT_EQ(shadow.tfar[i] == -std::numeric_limits<float>::infinity(), expected);
    }
  }
}

TEST_P(EmbreeGlueTest, Packets4And8And16MatchThePureQueryAndRespectTheValidMask) {
  checkPackets<4, RTCRayHit4>(GetParam());
  checkPackets<8, RTCRayHit8>(GetParam());
  checkPackets<16, RTCRayHit16>(GetParam());
}

TEST_P(EmbreeGlueTest, Occluded1MatchesThePureQuery) {
  std::mt19937_64 random(303);
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    SCOPED_TRACE(named.name);
    SingleShapeScene s(Shape(Profile(named.points), {GetParam()}));
    for (const Ray& ray : testing::incoherentRays(s.shape, random, 1000)) {
      embree::RayQuery query;
      RTCRay shadow = toRayHit(ray).ray;
      query.occluded(s.scene.get(), shadow);
      EXPECT_EQ(shadow.tfar == -std::numeric_limits<float>::infinity(), occluded(s.shape, ray));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllMethods, EmbreeGlueTest, ::testing::Values(Method::mibit, Method::linear, Method::kajiya), [](const auto& info) {
      return std::string(info.param == Method::mibit ? "mibit" : info.param == Method::linear ? "linear" : "kajiya");
    });

// Instancing. One shape, one geometry, one object scene, instanced several times. The instances
// without translation (power-of-two scales, quarter turns) map rays exactly in float, so Embree's
// object-space ray is the one computed here and the answers must be identical; translated ones
// round, so their t may differ by the rounding of the ray (bounded below).
struct Placement {
  float scale;       // uniform, a power of two
  int quarterTurns;  // about z
  Vec3 offset;
};

Vec3 placeVector(const Placement& p, Vec3 v, bool point) {
  const float c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
  const float cs = c[p.quarterTurns], sn = s[p.quarterTurns];
  return {(cs * v.x - sn * v.y) * p.scale + (point ? p.offset.x : 0.0f),
          (sn * v.x + cs * v.y) * p.scale + (point ? p.offset.y : 0.0f), v.z * p.scale + (point ? p.offset.z : 0.0f)};
}

void checkInstances(const std::vector<Placement>& placements, bool exact) {
  DevicePtr device = newDevice();
  const Shape shape{Profile(testing::hollowVase())};
  Geometry geometry(device.get(), shape);
  ScenePtr object(rtcNewScene(device.get()));
  rtcAttachGeometry(object.get(), geometry.handle());
  rtcCommitScene(object.get());
  ScenePtr world(rtcNewScene(device.get()));
  std::vector<unsigned> ids;
  for (const Placement& p : placements) {
    RTCGeometry instance = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, object.get());
    const Vec3 x = placeVector(p, {1, 0, 0}, false), y = placeVector(p, {0, 1, 0}, false),
               z = placeVector(p, {0, 0, 1}, false);
    const float xfm[12] = {x.x, x.y, x.z, y.x,        y.y,        y.z,
                           z.x, z.y, z.z, p.offset.x, p.offset.y, p.offset.z};  // column-major 3x4
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    rtcCommitGeometry(instance);
    ids.push_back(rtcAttachGeometry(world.get(), instance));
    rtcReleaseGeometry(instance);
  }
  rtcCommitScene(world.get());

  std::mt19937_64 random(404);
  std::size_t answered = 0;
  for (std::size_t k = 0; k < placements.size(); ++k) {
    for (const Ray& objectRay : testing::incoherentRays(shape, random, 2000, 2.0)) {
      const Ray worldRay{placeVector(placements[k], objectRay.origin, true),
                         placeVector(placements[k], objectRay.direction, false)};
      embree::RayQuery query;
      RTCRayHit rh = toRayHit(worldRay);
      query.intersect(world.get(), rh);
      const std::optional<Hit> expected = intersect(shape, objectRay);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.instID[0] != ids[k]) {
        // Missed everything, or another instance lies nearer: then this one's hit cannot be nearer.
        if (exact && expected && rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
          EXPECT_LE(rh.ray.tfar, expected->t);
        }
        if (exact && rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
          EXPECT_FALSE(expected.has_value());
        }
        continue;
      }
      ++answered;
      ASSERT_TRUE(expected.has_value());
      if (exact) {
        EXPECT_EQ(rh.ray.tfar, expected->t);
        EXPECT_EQ(rh.hit.primID, expected->segment);
        EXPECT_EQ(rh.hit.Ng_z, expected->normal.z);  // object-space normal, as Embree's contract says
      } else {
        // The translated ray is off by a float ulp of the world coordinates (|offset| + reach <= 8),
        // which moves the hit along the ray by at most that over the cosine of incidence; rays
        // within 1/16 of grazing are left out.
        const double length = std::hypot(objectRay.direction.x, objectRay.direction.y, objectRay.direction.z);
        const double cosine =
            std::abs(expected->normal.x * objectRay.direction.x + expected->normal.y * objectRay.direction.y +
                     expected->normal.z * objectRay.direction.z) /
            length;
        if (cosine < 1.0 / 16) continue;
        EXPECT_NEAR(rh.ray.tfar * length, expected->t * length, 8 * 0x1p-21 / cosine);
      }
    }
  }
  EXPECT_GT(answered, 1000u * placements.size());
}

TEST(EmbreeInstancingTest, ExactInstancesAnswerBitForBitLikeThePureQuery) {
  checkInstances({{2, 1, {0, 0, 0}}}, true);
  checkInstances({{0.5f, 2, {0, 0, 0}}}, true);
  checkInstances({{1, 3, {0, 0, 0}}}, true);
}

TEST(EmbreeInstancingTest, OneShapeSharedByTranslatedInstancesReportsEachInstance) {
  checkInstances({{1, 0, {0, 0, 0}}, {2, 1, {3, 0, 0}}, {0.5f, 2, {0, 3, 1}}, {1, 3, {-3, -2, 0.5f}}}, false);
}

// Filters: reject every hit with u < 1/2 (the half y > 0 of the object). The expected answer
// comes from the long-double reference's list of all hits along the ray.
void rejectLowerHalf(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == -1 && RTCHitN_u(args->hit, args->N, i) < 0.5f) args->valid[i] = 0;
  }
}

std::optional<long double> firstAcceptedReferenceHit(const std::vector<Point2>& points, const Ray& ray,
                                                     bool& ambiguous) {
  const reference::RefRay refRay{ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
                                 ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
  ambiguous = false;
  for (const reference::RefHit& hit : reference::allHits(points, refRay)) {
    const long double y = refRay.oy + hit.t * refRay.dy, x = refRay.ox + hit.t * refRay.dx;
    const long double phi = std::atan2(y, x);
    const long double u =
        (phi < 0 ? phi + 2 * std::numbers::pi_v<long double> : phi) / (2 * std::numbers::pi_v<long double>);
    if (std::abs(y) < 1e-4L * std::abs(x) + 1e-6L) ambiguous = true;  // on the filter's edge
    if (u >= 0.5L) return hit.t;                                      // the filter keeps these
  }
  return std::nullopt;
}

TEST(EmbreeFilterTest, IntersectionFilterRejectionFindsTheNextHit) {
  std::mt19937_64 random(505);
  const std::vector<Point2> points = testing::hollowVase();
  for (bool viaQuery : {false, true}) {
    SCOPED_TRACE(viaQuery ? "query filter" : "geometry filter");
    SingleShapeScene s{Shape(Profile(points))};
    if (viaQuery) {
      rtcSetSceneFlags(s.scene.get(), embree::kQueryFilterSceneFlag);
    } else {
      s.geometry.setIntersectFilter(rejectLowerHalf);
      rtcCommitGeometry(s.geometry.handle());
    }
    rtcCommitScene(s.scene.get());
    std::size_t checked = 0, secondHits = 0;
    for (const Ray& ray : testing::incoherentRays(s.shape, random, 3000)) {
      bool ambiguous;
      const std::optional<long double> expected = firstAcceptedReferenceHit(points, ray, ambiguous);
      if (ambiguous) continue;
      embree::RayQuery query({.filter = viaQuery ? rejectLowerHalf : nullptr});
      RTCRayHit rh = toRayHit(ray);
      query.intersect(s.scene.get(), rh);
      ++checked;
      ASSERT_EQ(rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, expected.has_value());
      if (!expected) continue;
      EXPECT_GE(rh.hit.u, 0.5f);
      EXPECT_NEAR(rh.ray.tfar, double(*expected), 1e-5 * (1.0 + double(*expected)));
      const std::optional<Hit> unfiltered = intersect(s.shape, ray);
      secondHits += unfiltered && unfiltered->t < rh.ray.tfar;
    }
    EXPECT_GT(checked, 2500u);
    EXPECT_GT(secondHits, 100u);  // the filter really did push hits further along
  }
}

TEST(EmbreeFilterTest, SplineShapesOfferEachCrossingToTheFilters) {
  // A spline shape through the filtered paths (rtcIntersect1, rtcIntersect4 and rtcOccluded1 with
  // a filter rejecting the lower half): the first accepted hit is the curve oracle's first with u >= 0.5.
  std::mt19937_64 random(506);
  const testing::NamedSpline named = testing::closedSplines()[4];  // the Catmull-Rom vase
  const Spline spline(named.kind, named.points);
  SingleShapeScene s{Shape(spline)};
  s.geometry.setIntersectFilter(rejectLowerHalf);
  s.geometry.setOcclusionFilter(rejectLowerHalf);
  rtcCommitGeometry(s.geometry.handle());
  rtcCommitScene(s.scene.get());
  std::size_t checked = 0;
  for (const Ray& ray : testing::incoherentRays(s.shape, random, 2000)) {
    const reference::RefRay refRay{ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
                                   ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
    std::optional<long double> expected;
    bool ambiguous = false;
    for (const reference::RefHit& hit : reference::allCurveHits(spline.bezier(), refRay)) {
      const long double y = refRay.oy + hit.t * refRay.dy, x = refRay.ox + hit.t * refRay.dx;
      if (std::abs(y) < 1e-4L * std::abs(x) + 1e-6L) ambiguous = true;
      if (std::atan2(y, x) >= 0 || y == 0) continue;  // u < 0.5: rejected
      expected = hit.t;
      break;
    }
    if (ambiguous) continue;
    ++checked;
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(ray);
    query.intersect(s.scene.get(), rh);
    ASSERT_EQ(rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, expected.has_value());
    if (expected) {
      EXPECT_NEAR(rh.ray.tfar, double(*expected), 1e-5 * (1.0 + double(*expected)));
    }
    // The same ray in lane 2 of a packet of four, the other lanes off.
    alignas(16) int valid[4] = {0, 0, -1, 0};
    alignas(16) RTCRayHit4 packet{};
    packet.ray.org_x[2] = ray.origin.x, packet.ray.org_y[2] = ray.origin.y, packet.ray.org_z[2] = ray.origin.z;
    packet.ray.dir_x[2] = ray.direction.x, packet.ray.dir_y[2] = ray.direction.y, packet.ray.dir_z[2] = ray.direction.z;
    packet.ray.tnear[2] = ray.tnear, packet.ray.tfar[2] = ray.tfar, packet.ray.mask[2] = ~0u;
    packet.hit.geomID[2] = RTC_INVALID_GEOMETRY_ID;
    query.intersect(valid, s.scene.get(), packet);
    EXPECT_EQ(packet.hit.geomID[2], rh.hit.geomID);
    EXPECT_EQ(packet.ray.tfar[2], rh.ray.tfar);
    RTCRay shadow = toRayHit(ray).ray;
    query.occluded(s.scene.get(), shadow);
    EXPECT_EQ(shadow.tfar == -INFINITY, expected.has_value());
  }
  EXPECT_GT(checked, 1500u);
}

TEST(EmbreeFilterTest, OcclusionFilterIsHonoured) {
  std::mt19937_64 random(606);
  const std::vector<Point2> points = testing::hollowVase();
  SingleShapeScene s{Shape(Profile(points))};
  s.geometry.setOcclusionFilter(rejectLowerHalf);
  rtcCommitGeometry(s.geometry.handle());
  rtcCommitScene(s.scene.get());
  std::size_t flipped = 0;
  for (const Ray& ray : testing::incoherentRays(s.shape, random, 3000)) {
    bool ambiguous;
    const bool expected = firstAcceptedReferenceHit(points, ray, ambiguous).has_value();
    if (ambiguous) continue;
    embree::RayQuery query;
    RTCRay shadow = toRayHit(ray).ray;
    query.occluded(s.scene.get(), shadow);
    EXPECT_EQ(shadow.tfar == -std::numeric_limits<float>::infinity(), expected);
    flipped += occluded(s.shape, ray) && !expected;
  }
  EXPECT_GT(flipped, 50u);
}

TEST(EmbreeFilterTest, FiltersWorkInPackets) {
  std::mt19937_64 random(707);
  const std::vector<Point2> points = testing::hollowVase();
  SingleShapeScene s{Shape(Profile(points))};
  s.geometry.setIntersectFilter(rejectLowerHalf);
  rtcCommitGeometry(s.geometry.handle());
  rtcCommitScene(s.scene.get());
  const std::vector<Ray> rays = testing::incoherentRays(s.shape, random, 8 * 200);
  for (std::size_t first = 0; first < rays.size(); first += 8) {
    alignas(32) int valid[8];
    alignas(32) RTCRayHit8 packet{};
    for (int i = 0; i < 8; ++i) {
      valid[i] = -1;
      const Ray& ray = rays[first + i];
      packet.ray.org_x[i] = ray.origin.x, packet.ray.org_y[i] = ray.origin.y, packet.ray.org_z[i] = ray.origin.z;
      packet.ray.dir_x[i] = ray.direction.x, packet.ray.dir_y[i] = ray.direction.y,
      packet.ray.dir_z[i] = ray.direction.z;
      packet.ray.tnear[i] = 0.0f, packet.ray.tfar[i] = ray.tfar, packet.ray.mask[i] = ~0u;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    embree::RayQuery query;
    query.intersect(valid, s.scene.get(), packet);
    for (int i = 0; i < 8; ++i) {
      bool ambiguous;
      const std::optional<long double> expected = firstAcceptedReferenceHit(points, rays[first + i], ambiguous);
      if (ambiguous) continue;
      ASSERT_EQ(packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID, expected.has_value());
      if (expected) {
        EXPECT_NEAR(packet.ray.tfar[i], double(*expected), 1e-5 * (1.0 + double(*expected)));
      }
    }
  }
}

// A hit's t is a float. A direction of subnormal length (1e-40) puts the can's side, one unit
// away, at t = 1e40, beyond float's range: no hit, by the pure query, rtcIntersect1, rtcOccluded1
// and a packet alike (it was reported at t = inf with the segment's id). At 1e-30 the side lies at
// t = 1e30, within range, and is hit there.
TEST(EmbreeFloatRangeTest, AHitBeyondFloatsRangeIsNoneAndOneWithinIt) {
  for (const Method method : {Method::mibit, Method::linear, Method::kajiya}) {
    SCOPED_TRACE(methodName(method));
    SingleShapeScene s(
        Shape(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}), BuildOptions{.method = method}));
    for (const float dx : {1e-40f, 1e-30f}) {
      const Ray ray{{0, 0, 0.5f}, {dx, 0, 0}};
      const bool within = dx > 1e-35f;
      const std::optional<Hit> pure = intersect(s.shape, ray);
      ASSERT_EQ(pure.has_value(), within);
      if (within) EXPECT_NEAR(pure->t, 1.0 / dx, 1e-6 / dx);
      EXPECT_EQ(occluded(s.shape, ray), within);
      embree::RayQuery query;
      RTCRayHit rh = toRayHit(ray);
      query.intersect(s.scene.get(), rh);
      EXPECT_EQ(rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, within);
      EXPECT_EQ(std::isfinite(rh.ray.tfar), within);
      RTCRay shadow = toRayHit(ray).ray;
      query.occluded(s.scene.get(), shadow);
      EXPECT_EQ(shadow.tfar == -std::numeric_limits<float>::infinity(), within);
      alignas(32) RTCRayHit8 packet{};
      alignas(32) int valid[8] = {-1, 0, 0, 0, 0, 0, 0, 0};
      for (int k = 0; k < 8; ++k) {
        packet.ray.org_z[k] = 0.5f, packet.ray.dir_x[k] = dx, packet.ray.tfar[k] = INFINITY, packet.ray.mask[k] = ~0u;
        packet.hit.geomID[k] = packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
      }
      query.intersect(valid, s.scene.get(), packet);
      EXPECT_EQ(packet.hit.geomID[0] != RTC_INVALID_GEOMETRY_ID, within);
    }
  }
}

TEST(EmbreeStatsTest, CountingGeometryAccumulatesWork) {
  std::mt19937_64 random(808);
  SingleShapeScene s(Shape(Profile(testing::sphereLike(1.0, 256))), Geometry::Options{.countStats = true});
  const std::vector<Ray> rays = testing::incoherentRays(s.shape, random, 1000);
  Stats pure;
  for (const Ray& ray : rays) {
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(ray);
    query.intersect(s.scene.get(), rh);
    (void)intersect(s.shape, ray, &pure);  // for its counters only
  }
  const Stats embree = s.geometry.stats();
  // Embree calls the geometry only for rays that reach its box; each such call counts like the pure query.
  EXPECT_GT(embree.rays, 900u);
  EXPECT_LE(embree.rays, pure.rays);
  EXPECT_GT(embree.quadratics, 0u);
  EXPECT_LE(embree.quadratics, pure.quadratics);
  EXPECT_LE(embree.nodesVisited, pure.nodesVisited);
}

// closestPoint's lookup for a scene of one revolve geometry (under geomID, in any instance).
struct OneGeometryLookup {
  const Geometry* geometry;
  unsigned geomID;
  static const Geometry* find(void* user, unsigned, unsigned id) {
    const auto* lookup = static_cast<const OneGeometryLookup*>(user);
    return id == lookup->geomID ? lookup->geometry : nullptr;
  }
};

// Point queries: the closest surface point through Embree (also through a similarity instance)
// against the long-double meridian distance.
TEST(EmbreePointQueryTest, ClosestPointMatchesTheReferenceDistance) {
  DevicePtr device = newDevice();
  const std::vector<Point2> points = testing::hollowVase();
  const Shape shape{Profile(points)};
  Geometry geometry(device.get(), shape);
  ScenePtr object(rtcNewScene(device.get()));
  const unsigned geomID = rtcAttachGeometry(object.get(), geometry.handle());
  rtcCommitScene(object.get());
  ScenePtr world(rtcNewScene(device.get()));
  RTCGeometry instance = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, object.get());
  const float xfm[12] = {0, 2, 0, -2, 0, 0, 0, 0, 2, 5, 0, 0};  // quarter turn, scale 2, shift x by 5
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  rtcCommitGeometry(instance);
  const unsigned instID = rtcAttachGeometry(world.get(), instance);
  rtcReleaseGeometry(instance);
  rtcCommitScene(world.get());

  OneGeometryLookup lookup{&geometry, geomID};

  std::mt19937_64 random(909);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.5f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
    const double expected = double(reference::meridianDistance(points, p.x, p.y, p.z));
    const std::optional<ScenePoint> direct =
        closestPoint(object.get(), p, std::numeric_limits<float>::infinity(), OneGeometryLookup::find, &lookup);
    ASSERT_TRUE(direct.has_value());
    EXPECT_NEAR(direct->distance, expected, 1e-6 * (1.0 + expected));
    EXPECT_EQ(direct->instID, RTC_INVALID_GEOMETRY_ID);
    EXPECT_NEAR(double(reference::meridianDistance(points, direct->point.x, direct->point.y, direct->point.z)), 0.0,
                1e-6);
    // The same point seen through the instance: world = 2 R p + (5, 0, 0), distances double.
    const Vec3 w{-2 * p.y + 5, 2 * p.x, 2 * p.z};
    const std::optional<ScenePoint> viaInstance =
        closestPoint(world.get(), w, std::numeric_limits<float>::infinity(), OneGeometryLookup::find, &lookup);
    ASSERT_TRUE(viaInstance.has_value());
    EXPECT_EQ(viaInstance->instID, instID);
    EXPECT_NEAR(viaInstance->distance, 2 * expected, 4e-6 * (1.0 + expected));
  }
}

// The tessellated baseline: normals agree with the exact surface's, and hits lie within its
// Hausdorff error bound of the exact ones (for non-grazing rays).
TEST(TessellationTest, MeshNormalsAndHitsAgreeWithTheExactSurface) {
  DevicePtr device = newDevice();
  const Profile profile(testing::sphereLike(1.0, 32));
  const std::uint32_t slices = 64;
  ScenePtr scene(rtcNewScene(device.get()));
  RTCGeometry mesh = newTessellatedGeometry(device.get(), profile, slices);
  rtcAttachGeometry(scene.get(), mesh);
  rtcReleaseGeometry(mesh);
  rtcCommitScene(scene.get());
  const Shape shape(profile);
  const double error = tessellationError(profile, slices);
  EXPECT_NEAR(error, 1.0 - std::cos(std::numbers::pi / slices), 1e-15);

  std::mt19937_64 random(1010);
  std::size_t compared = 0;
  for (const Ray& ray : testing::incoherentRays(shape, random, 4000)) {
    const std::optional<Hit> exact = intersect(shape, ray);
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(ray);
    query.intersect(scene.get(), rh);
    if (!exact || rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    const double length = std::hypot(ray.direction.x, ray.direction.y, ray.direction.z);
    const double cosine =
        -(exact->normal.x * ray.direction.x + exact->normal.y * ray.direction.y + exact->normal.z * ray.direction.z) /
        length;
    if (cosine < 0.3) continue;  // grazing: the mesh may hit a different facet or miss
    const double ngLength = std::hypot(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const double agreement =
        (rh.hit.Ng_x * exact->normal.x + rh.hit.Ng_y * exact->normal.y + rh.hit.Ng_z * exact->normal.z) / ngLength;
    EXPECT_GT(agreement, 0.9) << "mesh normal points the other way";
    // Each surface lies within `error` of the other (Hausdorff). Between the two hits both are
    // locally planes, so the hits are at most error / cosine apart along the ray, with the
    // smaller of the two surfaces' cosines of incidence (plus float rounding of both t values).
    const double facetCosine =
        -(rh.hit.Ng_x * ray.direction.x + rh.hit.Ng_y * ray.direction.y + rh.hit.Ng_z * ray.direction.z) /
        (ngLength * length);
    EXPECT_NEAR(rh.ray.tfar * length, exact->t * length, error / std::min(cosine, facetCosine) + 1e-5);
    ++compared;
  }
  EXPECT_GT(compared, 1000u);
}

// Where the surface touches its box (a cap lying on the box's top face, the widest circle on a side
// face), Embree's single-precision box test must not cull hits: the bounds are padded.
TEST(EmbreeBoundsTest, HitsWhereTheSurfaceTouchesItsBoxAreNotCulled) {
  const std::vector<Point2> points = testing::cappedCylinder(0.5, -0.75, 0.75);
  SingleShapeScene s{Shape(Profile(points))};
  std::mt19937_64 random(1111);
  std::uniform_real_distribution<double> jitter(-4.0, 4.0);
  std::size_t tested = 0, missed = 0;
  for (int i = 0; i < 20000; ++i) {
    // Aim at the top cap's rim near a point where it touches the box (phi = 0, 90, 180, 270
    // degrees), a few float ulps inside, from above at a random slant.
    const double phi = std::numbers::pi / 2 * (i % 4) + jitter(random) * 1e-7;
    const double r = 0.5 - std::abs(jitter(random)) * 6e-8;
    const Vec3 target{float(r * std::cos(phi)), float(r * std::sin(phi)), 0.75f};
    const Vec3 origin{target.x + float(jitter(random) * 0.1), target.y + float(jitter(random) * 0.1), 3.0f};
    const Ray ray{origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}};
    // The float ray may pass beside the target: the long-double reference says whether it truly
    // hits the cap, and rays within 1e-9 of the rim either way are left out.
    const std::optional<reference::RefHit> truth =
        reference::intersectProfile(points, {ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                                             ray.direction.z, 0.0L, std::numeric_limits<long double>::infinity()});
    if (!truth || truth->segment != 2) continue;
    const long double x = ray.origin.x + truth->t * ray.direction.x, y = ray.origin.y + truth->t * ray.direction.y;
    if (std::hypot(x, y) > 0.5L * (1 - 1e-9L)) continue;
    ++tested;
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(ray);
    query.intersect(s.scene.get(), rh);
    missed += rh.hit.geomID == RTC_INVALID_GEOMETRY_ID;
  }
  EXPECT_GT(tested, 5000u);
  EXPECT_EQ(missed, 0u);
}

// A filter that counts its calls and rejects everything, so that every candidate is offered.
std::atomic<int> gFilterCalls{0};
void countAndReject(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == -1) ++gFilterCalls, args->valid[i] = 0;
  }
}
void acceptAll(const RTCFilterFunctionNArguments*) {}

TEST(EmbreeFilterTest, EachCrossingIsOfferedOnce) {
  // A solid cone, apex (0, 0, 0) on top, base the disc z = -1. Down the axis a ray enters at the
  // apex and leaves through the base's centre: two crossings, so a filter that counts and rejects
  // must be called exactly twice (a review found the apex offered twice, an odd count).
  SingleShapeScene s{Shape(Profile(std::vector<Point2>{{0.0, -1.0}, {1.0, -1.0}, {0.0, 0.0}}))};
  s.geometry.setIntersectFilter(countAndReject);
  rtcCommitGeometry(s.geometry.handle());
  rtcCommitScene(s.scene.get());
  gFilterCalls = 0;
  embree::RayQuery query;
  RTCRayHit rh = toRayHit({{0, 0, 2}, {0, 0, -1}});
  query.intersect(s.scene.get(), rh);
  EXPECT_EQ(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(gFilterCalls.load(), 2);
}

TEST(EmbreeFilterTest, FilteredTiesGoToTheLowerSegmentAsUnfilteredOnes) {
  // Rays through the hourglass's pinch hit both cones at the same t; with a filter that accepts
  // everything the answer must be the unfiltered one, the lower segment.
  SingleShapeScene plain{Shape(Profile(testing::hourglass()))};
  SingleShapeScene filtered{Shape(Profile(testing::hourglass()))};
  filtered.geometry.setIntersectFilter(acceptAll);
  rtcCommitGeometry(filtered.geometry.handle());
  rtcCommitScene(filtered.scene.get());
  std::mt19937_64 random(1212);
  std::uniform_int_distribution<int> sixteenths(-32, 32);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d{sixteenths(random) / 16.0f, sixteenths(random) / 16.0f, sixteenths(random) / 16.0f};
    if (d.x == 0 && d.y == 0 && d.z == 0) continue;
    const Ray ray{{-2 * d.x, -2 * d.y, -2 * d.z}, d};  // through the pinch (0, 0, 0) at t = 2
    embree::RayQuery query;
    RTCRayHit a = toRayHit(ray), b = toRayHit(ray);
    query.intersect(plain.scene.get(), a);
    query.intersect(filtered.scene.get(), b);
    ASSERT_EQ(a.hit.geomID != RTC_INVALID_GEOMETRY_ID, b.hit.geomID != RTC_INVALID_GEOMETRY_ID);
    EXPECT_EQ(a.ray.tfar, b.ray.tfar);
    EXPECT_EQ(a.hit.primID, b.hit.primID);
  }
}

TEST(EmbreeGeometryTest, AMovedShapeStillServesItsGeometry) {
  // A Geometry holds the Shape's heap part, which a move leaves in place (a review found a crash
  // when a vector of shapes grew).
  DevicePtr device = newDevice();
  std::vector<Shape> shapes;
  shapes.emplace_back(Profile(testing::cappedCylinder(0.5, -0.75, 0.75)));
  Geometry geometry(device.get(), shapes[0]);
  for (int i = 0; i < 64; ++i) shapes.emplace_back(Profile(testing::cappedCylinder(0.5, -0.75, 0.75)));  // reallocates
  ScenePtr scene(rtcNewScene(device.get()));
  rtcAttachGeometry(scene.get(), geometry.handle());
  rtcCommitScene(scene.get());
  embree::RayQuery query;
  RTCRayHit rh = toRayHit({{-5, 0, 0}, {1, 0, 0}});
  query.intersect(scene.get(), rh);
  ASSERT_NE(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(rh.ray.tfar, 4.5f);  // the side at x = -0.5
}

TEST(EmbreeBoundsTest, CamerasFarAwayStillHitWhereTheSurfaceTouchesItsBox) {
  // Embree's box-test error grows with the ray's coordinates: from 10^4 object sizes away, 45-degree
  // rays at the top cap's rim, where the cap touches its box, must not be culled. A second
  // geometry gives the BVH an inner node.
  const std::vector<Point2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  DevicePtr device = newDevice();
  const Shape shape{Profile(points)};
  const Shape other{Profile(std::vector<Point2>{{0, 10}, {1, 10}, {1, 11}, {0, 11}})};
  Geometry a(device.get(), shape), b(device.get(), other);
  ScenePtr scene(rtcNewScene(device.get()));
  rtcAttachGeometry(scene.get(), a.handle());
  rtcAttachGeometry(scene.get(), b.handle());
  rtcCommitScene(scene.get());
  std::mt19937_64 random(1313);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t hits = 0, lost = 0;
  for (const double distance : {1e3, 1e4}) {
    for (int i = 0; i < 20000; ++i) {
      const double jitter = 1e-7 * distance;
      const double tx = 1 + jitter * u(random), ty = 1e-3 * u(random), tz = 1 + jitter * u(random);
      Ray ray{{float(tx - distance / std::sqrt(2.0)), float(ty), float(tz + distance / std::sqrt(2.0))}, {0, 0, 0}};
      ray.direction = {float(tx - ray.origin.x), float(ty - ray.origin.y), float(tz - ray.origin.z)};
      if (!intersect(shape, ray)) continue;  // the exact answer decides which rays must hit
      ++hits;
      embree::RayQuery query;
      RTCRayHit rh = toRayHit(ray);
      query.intersect(scene.get(), rh);
      lost += rh.hit.geomID == RTC_INVALID_GEOMETRY_ID;
    }
  }
  EXPECT_GT(hits, 10000u);
  EXPECT_EQ(lost, 0u);
}

// ---------------------------------------------------------------------------------------------
// Placed geometries (Geometry's Placement): the shape placed by the geometry itself, attached to
// the scene that is traced, with no Embree instance.

namespace placed {

// world = L p + T with L = s R_z(quarterTurns), exact in float for power-of-two s and no T.
revolve::Placement quarterTurn(double s, int quarterTurns, Vec3 offset) {
  const double c[4] = {1, 0, -1, 0}, n[4] = {0, 1, 0, -1};
  revolve::Placement p;
  const double cs = c[quarterTurns], sn = n[quarterTurns];
  const double linear[3][3] = {{s * cs, -s * sn, 0}, {s * sn, s * cs, 0}, {0, 0, s}};
  std::memcpy(p.linear, linear, sizeof linear);
  p.translate[0] = offset.x, p.translate[1] = offset.y, p.translate[2] = offset.z;
  return p;
}

Vec3 apply(const revolve::Placement& p, Vec3 v, bool point) {
  const auto row = [&](int r) {
    return float(p.linear[r][0] * v.x + p.linear[r][1] * v.y + p.linear[r][2] * v.z + (point ? p.translate[r] : 0.0));
  };
  return {row(0), row(1), row(2)};
}

struct PlacedScene {
  DevicePtr device = newDevice();
  Shape shape;
  Geometry geometry;
  ScenePtr scene;
  unsigned geomID;
  PlacedScene(Shape s, const revolve::Placement& placement)
      : shape(std::move(s)), geometry(device.get(), shape, placement, {}), scene(rtcNewScene(device.get())) {
    geomID = rtcAttachGeometry(scene.get(), geometry.handle());
    rtcCommitScene(scene.get());
  }
};

}  // namespace placed

// Placements exact in float (power-of-two scales, quarter turns, no translation) map every ray
// exactly, so the answers are the pure query's on the object-space ray, bit for bit, for single
// rays and for packets of 4, 8 and 16 with lanes off.
TEST(PlacedGeometryTest, ExactPlacementsAnswerBitForBitLikeThePureQuery) {
  for (const auto& [scale, turns] : {std::pair{2.0, 1}, std::pair{0.5, 2}, std::pair{1.0, 3}}) {
    const revolve::Placement placement = placed::quarterTurn(scale, turns, {0, 0, 0});
    placed::PlacedScene s(Shape(Profile(testing::hollowVase())), placement);
    std::mt19937_64 random(505);
    const std::vector<Ray> objectRays = testing::incoherentRays(s.shape, random, 1600, 2.0);
    std::size_t hits = 0;
    for (const Ray& objectRay : objectRays) {
      const Ray worldRay{placed::apply(placement, objectRay.origin, true),
                         placed::apply(placement, objectRay.direction, false), objectRay.tnear, objectRay.tfar};
      embree::RayQuery query;
      RTCRayHit rh = toRayHit(worldRay);
      query.intersect(s.scene.get(), rh);
      const std::optional<Hit> expected = intersect(s.shape, objectRay);
      hits += expected.has_value();
      expectSameHit(expected, rh.ray.tfar, rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z, rh.hit.u, rh.hit.v, rh.hit.primID,
                    rh.hit.geomID, s.geomID, worldRay);
      EXPECT_EQ(rh.hit.instID[0], RTC_INVALID_GEOMETRY_ID);
      // The caller's ray is given back as it was.
      EXPECT_EQ(rh.ray.org_x, worldRay.origin.x);
      EXPECT_EQ(rh.ray.dir_z, worldRay.direction.z);
      RTCRay shadow = toRayHit(worldRay).ray;
      query.occluded(s.scene.get(), shadow);
      EXPECT_EQ(shadow.tfar == -std::numeric_limits<float>::infinity(), expected.has_value());
    }
    EXPECT_GT(hits, 400u);
    // Packets: lane k of packet j is ray 16 j + k, every third lane off.
    for (std::size_t first = 0; first + 16 <= objectRays.size(); first += 16) {
      alignas(64) RTCRayHit16 packet{};
      alignas(64) int valid[16];
      for (int k = 0; k < 16; ++k) {
        const Ray& o = objectRays[first + std::size_t(k)];
        const Ray w{placed::apply(placement, o.origin, true), placed::apply(placement, o.direction, false), o.tnear,
                    o.tfar};
        valid[k] = k % 3 == 2 ? 0 : -1;
        packet.ray.org_x[k] = w.origin.x, packet.ray.org_y[k] = w.origin.y, packet.ray.org_z[k] = w.origin.z;
        packet.ray.dir_x[k] = w.direction.x, packet.ray.dir_y[k] = w.direction.y, packet.ray.dir_z[k] = w.direction.z;
        packet.ray.tnear[k] = w.tnear, packet.ray.tfar[k] = w.tfar;
        packet.ray.mask[k] = ~0u, packet.ray.flags[k] = 0, packet.ray.time[k] = 0;
        packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
      }
      embree::RayQuery query;
      query.intersect(valid, s.scene.get(), packet);
      for (int k = 0; k < 16; ++k) {
        const Ray& o = objectRays[first + std::size_t(k)];
        if (valid[k] == 0) {
          EXPECT_EQ(packet.hit.geomID[k], RTC_INVALID_GEOMETRY_ID);
          continue;
        }
        const std::optional<Hit> expected = intersect(s.shape, o);
        expectSameHit(expected, packet.ray.tfar[k], packet.hit.Ng_x[k], packet.hit.Ng_y[k], packet.hit.Ng_z[k],
                      packet.hit.u[k], packet.hit.v[k], packet.hit.primID[k], packet.hit.geomID[k], s.geomID, o);
        EXPECT_EQ(packet.ray.org_y[k], placed::apply(placement, o.origin, true).y);
      }
    }
  }
}

// A general placement (a turn of 0.7 rad about a tilted axis, unequal scales, a translation): every
// hit agrees with the long-double oracle's on the exactly mapped object-space ray, within what
// rounding the mapped ray to float moves it (a float ulp of its coordinates, over the cosine of
// incidence; rays within 1/16 of grazing left out), and every such oracle hit is found (the
// placed bounds cull none).
TEST(PlacedGeometryTest, AGeneralPlacementAgreesWithTheOracle) {
  const double a = 0.7, ca = std::cos(a), sa = std::sin(a);
  // L = R_x(a) diag(1.5, 0.75, 1.25) R_z(a), T = (3, -2, 0.5).
  const double rz[3][3] = {{ca, -sa, 0}, {sa, ca, 0}, {0, 0, 1}}, rx[3][3] = {{1, 0, 0}, {0, ca, -sa}, {0, sa, ca}};
  const double scale[3] = {1.5, 0.75, 1.25};
  revolve::Placement placement;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int k = 0; k < 3; ++k) sum += rx[r][k] * scale[k] * rz[k][c];
      placement.linear[r][c] = sum;
    }
  }
  placement.translate[0] = 3, placement.translate[1] = -2, placement.translate[2] = 0.5;
  const std::vector<Point2> points = testing::hollowVase();
  placed::PlacedScene s(Shape(Profile(points)), placement);
  // The inverse in long double, for the oracle's object-space rays.
  long double inv[3][3];
  {
    const auto& m = placement.linear;
    const long double det = (long double)m[0][0] * (m[1][1] * (long double)m[2][2] - m[1][2] * (long double)m[2][1]) -
                            (long double)m[0][1] * (m[1][0] * (long double)m[2][2] - m[1][2] * (long double)m[2][0]) +
                            (long double)m[0][2] * (m[1][0] * (long double)m[2][1] - m[1][1] * (long double)m[2][0]);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
        inv[r][c] = ((long double)m[r1][c1] * m[r2][c2] - (long double)m[r1][c2] * m[r2][c1]) / det;
      }
    }
  }
  std::mt19937_64 random(606);
  std::size_t compared = 0;
  for (const Ray& objectRay : testing::incoherentRays(s.shape, random, 3000, 2.0)) {
    const Ray worldRay{placed::apply(placement, objectRay.origin, true),
                       placed::apply(placement, objectRay.direction, false)};
    long double o[3] = {worldRay.origin.x - (long double)placement.translate[0],
                        worldRay.origin.y - (long double)placement.translate[1],
                        worldRay.origin.z - (long double)placement.translate[2]};
    const long double d[3] = {worldRay.direction.x, worldRay.direction.y, worldRay.direction.z};
    reference::RefRay ref{};
    long double* out[6] = {&ref.ox, &ref.oy, &ref.oz, &ref.dx, &ref.dy, &ref.dz};
    for (int r = 0; r < 3; ++r) {
      *out[r] = inv[r][0] * o[0] + inv[r][1] * o[1] + inv[r][2] * o[2];
      *out[r + 3] = inv[r][0] * d[0] + inv[r][1] * d[1] + inv[r][2] * d[2];
    }
    ref.tnear = 0, ref.tfar = std::numeric_limits<long double>::infinity();
    const std::optional<reference::RefHit> expected = reference::intersectProfile(points, ref);
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(worldRay);
    query.intersect(s.scene.get(), rh);
    if (!expected) continue;  // a miss of the exact ray may be a grazing hit of the rounded one
    const long double length = std::sqrt(ref.dx * ref.dx + ref.dy * ref.dy + ref.dz * ref.dz);
    const long double cosine = std::abs(expected->nx * ref.dx + expected->ny * ref.dy + expected->nz * ref.dz) / length;
    if (cosine < 1.0L / 16) continue;
    ASSERT_NE(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
    ++compared;
    // The mapped ray's coordinates are within 2^-24 of their size (|o'| + |t d'| <= 8 here) plus
    // the double map's own rounding; the hit moves by that over the cosine, along the ray.
    EXPECT_NEAR(double(rh.ray.tfar * length), double(expected->t * length), double(8 * 0x1p-22 / cosine));
  }
  EXPECT_GT(compared, 800u);
}

// Point queries: the closest point in object space carried to the world (a similarity here: a
// quarter turn, scale 2, shifted by 5 in x), its distance twice the object-space one.
TEST(PlacedGeometryTest, ClosestPointIsTheObjectSpaceOneCarriedToTheWorld) {
  const std::vector<Point2> points = testing::hollowVase();
  const revolve::Placement placement = placed::quarterTurn(2, 1, {5, 0, 0});
  placed::PlacedScene s(Shape(Profile(points)), placement);
  OneGeometryLookup lookup{&s.geometry, s.geomID};
  std::mt19937_64 random(707);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.5f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
    const double expected = double(reference::meridianDistance(points, p.x, p.y, p.z));
    const Vec3 w{-2 * p.y + 5, 2 * p.x, 2 * p.z};  // rounded by 2.4e-7 at most (within the tolerance)
    const std::optional<ScenePoint> found =
        closestPoint(s.scene.get(), w, std::numeric_limits<float>::infinity(), OneGeometryLookup::find, &lookup);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->instID, RTC_INVALID_GEOMETRY_ID);
    EXPECT_EQ(found->geomID, s.geomID);
    EXPECT_NEAR(found->distance, 2 * expected, 4e-6 * (1.0 + expected));
    // The point lies on the placed surface: back in object space, on the profile's surface.
    const Vec3 q{(found->point.y) / 2, -(found->point.x - 5) / 2, found->point.z / 2};
    EXPECT_NEAR(double(reference::meridianDistance(points, q.x, q.y, q.z)), 0.0, 2e-6);
  }
}

// Filters on a placed geometry see its hits as on an unplaced one (u, v in object space), and a
// rejection finds the next hit: the placement (scale 2, exact in float) maps the world ray onto the
// object-space ray whose first accepted hit the long-double reference gives.
TEST(PlacedGeometryTest, AFilterRejectionFindsTheNextHitAndTheRayComesBackUnchanged) {
  const std::vector<Point2> points = testing::hollowVase();
  const revolve::Placement placement = placed::quarterTurn(2, 0, {0, 0, 0});
  placed::PlacedScene s(Shape(Profile(points)), placement);
  s.geometry.setIntersectFilter(rejectLowerHalf);
  rtcCommitGeometry(s.geometry.handle());
  rtcCommitScene(s.scene.get());
  std::mt19937_64 random(808);
  std::size_t checked = 0, secondHits = 0;
  for (const Ray& objectRay : testing::incoherentRays(s.shape, random, 3000)) {
    bool ambiguous;
    const std::optional<long double> expected = firstAcceptedReferenceHit(points, objectRay, ambiguous);
    if (ambiguous) continue;
    const Ray worldRay{placed::apply(placement, objectRay.origin, true),
                       placed::apply(placement, objectRay.direction, false), objectRay.tnear, objectRay.tfar};
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(worldRay);
    query.intersect(s.scene.get(), rh);
    ++checked;
    EXPECT_EQ(rh.ray.org_x, worldRay.origin.x);
    EXPECT_EQ(rh.ray.dir_y, worldRay.direction.y);
    ASSERT_EQ(rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, expected.has_value());
    if (!expected) continue;
    EXPECT_GE(rh.hit.u, 0.5f);
    EXPECT_NEAR(rh.ray.tfar, double(*expected), 1e-5 * (1.0 + double(*expected)));
    const std::optional<Hit> unfiltered = intersect(s.shape, objectRay);
    secondHits += unfiltered && unfiltered->t < rh.ray.tfar;
  }
  EXPECT_GT(checked, 2500u);
  EXPECT_GT(secondHits, 100u);
}

// Shadow packets of 16 on a placed geometry (a placement exact in float): a lane on reports
// occlusion exactly when the pure query on its object-space ray hits; a lane off, and every lane's
// ray, come back as the caller gave them.
TEST(PlacedGeometryTest, OccludedPacketsAnswerAsThePureQueryAndLeaveLanesOffUntouched) {
  const revolve::Placement placement = placed::quarterTurn(2, 3, {0, 0, 0});
  placed::PlacedScene s(Shape(Spline(SplineKind::catmullRom, testing::hollowVase())), placement);
  std::mt19937_64 random(1212);
  const std::vector<Ray> objectRays = testing::incoherentRays(s.shape, random, 1600, 2.0);
  std::size_t occluded = 0;
  for (std::size_t first = 0; first + 16 <= objectRays.size(); first += 16) {
    alignas(64) RTCRay16 packet{};
    alignas(64) int valid[16];
    for (int k = 0; k < 16; ++k) {
      const Ray& o = objectRays[first + std::size_t(k)];
      const Vec3 origin = placed::apply(placement, o.origin, true),
                 direction = placed::apply(placement, o.direction, false);
      valid[k] = k % 3 == 1 ? 0 : -1;
      packet.org_x[k] = origin.x, packet.org_y[k] = origin.y, packet.org_z[k] = origin.z;
      packet.dir_x[k] = direction.x, packet.dir_y[k] = direction.y, packet.dir_z[k] = direction.z;
      packet.tnear[k] = o.tnear, packet.tfar[k] = o.tfar;
      packet.mask[k] = ~0u, packet.flags[k] = 0, packet.time[k] = 0;
    }
    const RTCRay16 given = packet;
    embree::RayQuery query;
    query.occluded(valid, s.scene.get(), packet);
    for (int k = 0; k < 16; ++k) {
      const Ray& o = objectRays[first + std::size_t(k)];
      // Every field as given but a blocked lane's tfar.
      EXPECT_EQ(packet.org_x[k], given.org_x[k]);
      EXPECT_EQ(packet.org_y[k], given.org_y[k]);
      EXPECT_EQ(packet.org_z[k], given.org_z[k]);
      EXPECT_EQ(packet.dir_x[k], given.dir_x[k]);
      EXPECT_EQ(packet.dir_y[k], given.dir_y[k]);
      EXPECT_EQ(packet.dir_z[k], given.dir_z[k]);
      EXPECT_EQ(packet.tnear[k], given.tnear[k]);
      EXPECT_EQ(packet.time[k], given.time[k]);
      EXPECT_EQ(packet.mask[k], given.mask[k]);
      EXPECT_EQ(packet.id[k], given.id[k]);
      EXPECT_EQ(packet.flags[k], given.flags[k]);
      if (valid[k] == 0) {
        EXPECT_EQ(packet.tfar[k], given.tfar[k]) << "lane " << k << " was off";
        continue;
      }
      const bool blocked = packet.tfar[k] == -std::numeric_limits<float>::infinity();
      EXPECT_EQ(blocked, intersect(s.shape, o).has_value()) << "ray " << first + std::size_t(k);
      if (!blocked) EXPECT_EQ(packet.tfar[k], given.tfar[k]);
      occluded += blocked;
    }
  }
  EXPECT_GT(occluded, 300u);
}

// A placed geometry counting its work counts it as the pure query on the object-space ray, ray by
// ray: a placement exact in float maps each ray exactly, and Embree calls the geometry once for a
// ray that reaches its box (its one primitive), not at all for one that misses it.
TEST(PlacedGeometryTest, CountingAccumulatesWorkAsThePureQuery) {
  const revolve::Placement placement = placed::quarterTurn(0.5, 1, {0, 0, 0});
  DevicePtr device = newDevice();
  const Shape shape{Profile(testing::sphereLike(1.0, 256))};
  Geometry geometry(device.get(), shape, placement, Geometry::Options{.countStats = true});
  ScenePtr scene(rtcNewScene(device.get()));
  rtcAttachGeometry(scene.get(), geometry.handle());
  rtcCommitScene(scene.get());
  std::mt19937_64 random(808);
  std::size_t called = 0;
  for (const Ray& objectRay : testing::incoherentRays(shape, random, 1000)) {
    const Ray worldRay{placed::apply(placement, objectRay.origin, true),
                       placed::apply(placement, objectRay.direction, false), objectRay.tnear, objectRay.tfar};
    const Stats before = geometry.stats();
    embree::RayQuery query;
    RTCRayHit rh = toRayHit(worldRay);
    query.intersect(scene.get(), rh);
    const Stats after = geometry.stats();
    if (after.rays == before.rays) continue;  // culled by the box
    ++called;
    ASSERT_EQ(after.rays, before.rays + 1);
    Stats pure;
    (void)intersect(shape, objectRay, &pure);
    EXPECT_EQ(after.nodesVisited - before.nodesVisited, pure.nodesVisited);
    EXPECT_EQ(after.shellTests - before.shellTests, pure.shellTests);
    EXPECT_EQ(after.quadratics - before.quadratics, pure.quadratics);
  }
  EXPECT_GT(called, 900u);
}

// A point query through an Embree instance (a translation by (0, 3, 0)) of a scene holding a placed
// geometry (a quarter turn, scale 2, a shift by (5, 0, 0)): both maps are carried, and the distance
// is twice the object-space one, as from the long-double meridian distance.
TEST(PlacedGeometryTest, ClosestPointThroughAnInstanceAbovePlacedGeometry) {
  const std::vector<Point2> points = testing::hollowVase();
  const revolve::Placement placement = placed::quarterTurn(2, 1, {5, 0, 0});
  placed::PlacedScene s(Shape(Profile(points)), placement);
  ScenePtr world(rtcNewScene(s.device.get()));
  RTCGeometry instance = rtcNewGeometry(s.device.get(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, s.scene.get());
  const float xfm[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0};
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  rtcCommitGeometry(instance);
  const unsigned instID = rtcAttachGeometry(world.get(), instance);
  rtcReleaseGeometry(instance);
  rtcCommitScene(world.get());
  OneGeometryLookup lookup{&s.geometry, s.geomID};
  std::mt19937_64 random(1313);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.5f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
    const double expected = double(reference::meridianDistance(points, p.x, p.y, p.z));
    const Vec3 w{-2 * p.y + 5, 2 * p.x + 3, 2 * p.z};  // rounded by 2.4e-7 at most
    const std::optional<ScenePoint> found =
        closestPoint(world.get(), w, std::numeric_limits<float>::infinity(), OneGeometryLookup::find, &lookup);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->instID, instID);
    EXPECT_EQ(found->geomID, s.geomID);
    EXPECT_NEAR(found->distance, 2 * expected, 4e-6 * (1.0 + expected));
    const Vec3 q{(found->point.y - 3) / 2, -(found->point.x - 5) / 2, found->point.z / 2};
    EXPECT_NEAR(double(reference::meridianDistance(points, q.x, q.y, q.z)), 0.0, 2e-6);
  }
}

TEST(PlacedGeometryTest, RefusesPlacementsThatAreNotFiniteOrSingular) {
  DevicePtr device = newDevice();
  const Shape shape{Profile(testing::hollowVase())};
  revolve::Placement nan = placed::quarterTurn(1, 0, {0, 0, 0});
  nan.linear[1][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Geometry(device.get(), shape, nan, {}), std::invalid_argument);
  revolve::Placement far = placed::quarterTurn(1, 0, {0, 0, 0});
  far.translate[2] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(Geometry(device.get(), shape, far, {}), std::invalid_argument);
  revolve::Placement flat = placed::quarterTurn(1, 0, {0, 0, 0});
  flat.linear[2][2] = 0;  // z squashed to nothing
  try {
    Geometry geometry(device.get(), shape, flat, {});
    ADD_FAILURE() << "a singular placement was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("singular"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace revolve
