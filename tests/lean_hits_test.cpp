// Lean hits (Geometry::Options::normal, ::uv) and revolve::surfaceAttributes: a geometry asked for
// fewer attributes writes the same t and primID as the pure query, zeros for what it was not asked
// for and the pure query's values bit for bit for what it was; surfaceAttributes, from the traced
// ray, primID and t, gives back the pure query's whole Hit bit for bit. The pure query itself is
// checked against independent references elsewhere (reference_agreement_test, spline_tracing_test).
#include "embree/embree_handles.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"

#include <revolve/embree_baselines.h>
#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <memory>
#include <random>
#include <string>

namespace revolve {
namespace {

using DevicePtr = app::Device;  // the applications' owning handles (common/embree_handles.h)
using ScenePtr = app::Scene;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameHit(const Hit& a, const Hit& b) {
  return sameBits(a.t, b.t) && sameBits(a.u, b.u) && sameBits(a.v, b.v) && a.segment == b.segment &&
         sameBits(a.normal.x, b.normal.x) && sameBits(a.normal.y, b.normal.y) && sameBits(a.normal.z, b.normal.z) &&
         sameBits(a.point.x, b.point.x) && sameBits(a.point.y, b.point.y) && sameBits(a.point.z, b.point.z);
}

// One shape behind four geometries, one per choice of attributes, each in a scene of its own.
struct LeanScenes {
  DevicePtr device{rtcNewDevice(nullptr)};
  Shape shape;
  std::vector<std::unique_ptr<Geometry>> geometries;
  std::vector<ScenePtr> scenes;

  explicit LeanScenes(Shape s) : shape(std::move(s)) {
    for (int choice = 0; choice < 4; ++choice) {
      Geometry::Options options;
      options.normal = (choice & 1) != 0;
      options.uv = (choice & 2) != 0;
      geometries.push_back(std::make_unique<Geometry>(device.get(), shape, options));
      scenes.emplace_back(rtcNewScene(device.get()));
      rtcAttachGeometry(scenes.back().get(), geometries.back()->handle());
      rtcCommitScene(scenes.back().get());
    }
  }
};

// What a geometry with `choice` (bit 0 normal, bit 1 uv) must have written for the hit `full`.
void expectLeanHit(const Hit& full, int choice, float tfar, float nx, float ny, float nz, float u, float v,
                   unsigned primID) {
  EXPECT_TRUE(sameBits(tfar, full.t));
  EXPECT_EQ(primID, full.segment);
  const bool normal = (choice & 1) != 0, uv = (choice & 2) != 0;
  EXPECT_TRUE(sameBits(nx, normal ? full.normal.x : 0.0f) && sameBits(ny, normal ? full.normal.y : 0.0f) &&
              sameBits(nz, normal ? full.normal.z : 0.0f))
      << "choice " << choice;
  EXPECT_TRUE(sameBits(u, uv ? full.u : 0.0f) && sameBits(v, uv ? full.v : 0.0f)) << "choice " << choice;
}

// rtcIntersect1 and rtcIntersect8 (some lanes off) through every choice; surfaceAttributes on each hit.
void checkShape(LeanScenes& s, const std::vector<Ray>& rays, const std::string& name, std::size_t& hits) {
  SCOPED_TRACE(name);
  for (const Ray& ray : rays) {
    const std::optional<Hit> full = intersect(s.shape, ray);
    for (int choice = 0; choice < 4; ++choice) {
      RTCRayHit rh{};
      rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
      rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
      rh.ray.tnear = ray.tnear, rh.ray.tfar = ray.tfar, rh.ray.mask = ~0u;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      embree::RayQuery query;
      query.intersect(s.scenes[choice].get(), rh);
      ASSERT_EQ(rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, full.has_value());
      if (!full) continue;
      expectLeanHit(*full, choice, rh.ray.tfar, rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z, rh.hit.u, rh.hit.v,
                    rh.hit.primID);
    }
    if (!full) continue;
    ++hits;
    const std::optional<Hit> again = surfaceAttributes(s.shape, ray, full->segment, full->t);
    ASSERT_TRUE(again.has_value());
    EXPECT_TRUE(sameHit(*again, *full)) << "t " << again->t << " vs " << full->t;
  }
  std::mt19937_64 random(17);
  for (std::size_t first = 0; first + 8 <= rays.size(); first += 8) {
    for (int choice = 0; choice < 4; ++choice) {
      alignas(32) int valid[8];
      alignas(32) RTCRayHit8 packet{};
      for (int i = 0; i < 8; ++i) {
        valid[i] = random() % 5 == 0 ? 0 : -1;
        const Ray& ray = rays[first + i];
        packet.ray.org_x[i] = ray.origin.x, packet.ray.org_y[i] = ray.origin.y, packet.ray.org_z[i] = ray.origin.z;
        packet.ray.dir_x[i] = ray.direction.x, packet.ray.dir_y[i] = ray.direction.y;
        packet.ray.dir_z[i] = ray.direction.z;
        packet.ray.tnear[i] = ray.tnear, packet.ray.tfar[i] = ray.tfar, packet.ray.mask[i] = ~0u;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      }
      embree::RayQuery query;
      query.intersect(valid, s.scenes[choice].get(), packet);
      for (int i = 0; i < 8; ++i) {
        const std::optional<Hit> full = valid[i] == -1 ? intersect(s.shape, rays[first + i]) : std::nullopt;
        ASSERT_EQ(packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID, full.has_value());
        if (!full) continue;
        expectLeanHit(*full, choice, packet.ray.tfar[i], packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i],
                      packet.hit.u[i], packet.hit.v[i], packet.hit.primID[i]);
      }
    }
  }
}

TEST(LeanHitsTest, PolylineShapesWriteWhatTheyAreAskedForAndSurfaceAttributesGiveTheRest) {
  std::mt19937_64 random(4101);
  std::size_t hits = 0;
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    for (const BuildOptions options :
         {BuildOptions{}, BuildOptions{Method::mibit, ShellKind::hybrid}, BuildOptions{Method::kajiya}}) {
      LeanScenes s(Shape(Profile(named.points), options));
      std::vector<Ray> rays = testing::incoherentRays(s.shape, random, 800);
      const std::vector<Ray> awkward = testing::axisAlignedRays(s.shape, random, 200);
      rays.insert(rays.end(), awkward.begin(), awkward.end());
      checkShape(s, rays, named.name, hits);
    }
  }
  EXPECT_GT(hits, 10000u);
}

TEST(LeanHitsTest, SplineShapesWriteWhatTheyAreAskedForAndSurfaceAttributesGiveTheRest) {
  std::mt19937_64 random(4102);
  std::size_t hits = 0;
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    LeanScenes s(Shape(Spline(named.kind, named.points)));
    std::vector<Ray> rays = testing::incoherentRays(s.shape, random, 1000);
    const std::vector<Ray> awkward = testing::axisAlignedRays(s.shape, random, 200);
    rays.insert(rays.end(), awkward.begin(), awkward.end());
    checkShape(s, rays, named.name, hits);
  }
  EXPECT_GT(hits, 2000u);
}

TEST(LeanHitsTest, SurfaceAttributesRefusesASegmentTheRayDoesNotMeet) {
  const Shape shape(Profile(testing::cappedCylinder(1.0, -1.0, 1.0)));  // bottom disc, side, top disc
  const Ray down{{0.25f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}};             // through both discs, not the side
  const std::optional<Hit> top = intersect(shape, down);
  ASSERT_TRUE(top.has_value());
  EXPECT_EQ(top->segment, 2u);
  EXPECT_FALSE(surfaceAttributes(shape, down, 1, top->t).has_value());  // the side: never met
  EXPECT_FALSE(surfaceAttributes(shape, down, 3, top->t).has_value());  // no segment 3
  const std::optional<Hit> bottom = surfaceAttributes(shape, down, 0, 4.0f);
  ASSERT_TRUE(bottom.has_value());
  EXPECT_EQ(bottom->t, 4.0f);  // z = -1, exactly
  EXPECT_EQ(bottom->normal.z, -1.0f);
}

// Accepts every candidate, and counts the ones offered without a normal or without u, v.
std::atomic<int> offeredLean{0};
void acceptAndCheck(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const bool noNormal = RTCHitN_Ng_x(args->hit, args->N, i) == 0.0f && RTCHitN_Ng_y(args->hit, args->N, i) == 0.0f &&
                          RTCHitN_Ng_z(args->hit, args->N, i) == 0.0f;
    if (noNormal) ++offeredLean;
  }
}

// Keeps the upper half of the azimuths only: the hit found is often not the nearest of its segment.
void rejectLowerHalf(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == -1 && RTCHitN_u(args->hit, args->N, i) < 0.5f) args->valid[i] = 0;
  }
}

TEST(LeanHitsTest, FiltersSeeEveryAttributeAndFilteredHitsCarryThem) {
  std::mt19937_64 random(4103);
  for (RTCFilterFunctionN filter : {acceptAndCheck, rejectLowerHalf}) {
    LeanScenes s{Shape(Profile(testing::hollowVase()))};
    for (auto& geometry : s.geometries) {
      geometry->setIntersectFilter(filter);
      rtcCommitGeometry(geometry->handle());
    }
    for (auto& scene : s.scenes) rtcCommitScene(scene.get());
    offeredLean = 0;
    std::size_t hits = 0, notNearest = 0;
    for (const Ray& ray : testing::incoherentRays(s.shape, random, 1000)) {
      const std::optional<Hit> unfiltered = intersect(s.shape, ray);
      std::optional<Hit> first;
      for (int choice = 0; choice < 4; ++choice) {
        RTCRayHit rh{};
        rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
        rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
        rh.ray.tnear = ray.tnear, rh.ray.tfar = ray.tfar, rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        embree::RayQuery query;
        query.intersect(s.scenes[choice].get(), rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
          EXPECT_FALSE(first.has_value());
          continue;
        }
        // Every choice writes the whole hit the filter accepted, and surfaceAttributes finds it again.
        const std::optional<Hit> again = surfaceAttributes(s.shape, ray, rh.hit.primID, rh.ray.tfar);
        ASSERT_TRUE(again.has_value());
        EXPECT_TRUE(sameBits(again->t, rh.ray.tfar) && sameBits(again->normal.x, rh.hit.Ng_x) &&
                    sameBits(again->normal.y, rh.hit.Ng_y) && sameBits(again->normal.z, rh.hit.Ng_z) &&
                    sameBits(again->u, rh.hit.u) && sameBits(again->v, rh.hit.v));
        if (choice == 0) {
          first = again;
          ++hits;
          notNearest += unfiltered && !sameHit(*unfiltered, *again);
        } else {
          EXPECT_TRUE(first && sameHit(*first, *again));
        }
      }
    }
    EXPECT_EQ(offeredLean.load(), 0);
    EXPECT_GT(hits, 300u);
    if (filter == rejectLowerHalf) {
      EXPECT_GT(notNearest, 50u);
    }
  }
}

}  // namespace
}  // namespace revolve
