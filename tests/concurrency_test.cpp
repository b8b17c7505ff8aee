// Tracing the same shapes from every thread at once gives bit-identical answers to one thread, and
// the counters of a counting geometry add up to exactly the single-threaded totals.
#include "support/test_profiles.h"
#include "support/test_scale.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cstring>
#include <thread>

namespace revolve {
namespace {

struct HitRecord {
  float t, ngx, ngy, ngz, u, v;
  unsigned primID, geomID;
  bool operator==(const HitRecord& other) const { return std::memcmp(this, &other, sizeof *this) == 0; }
};

HitRecord traceEmbree(RTCScene scene, const Ray& ray) {
  embree::RayQuery query;
  RTCRayHit rh{};
  rh.ray = {
      ray.origin.x, ray.origin.y, ray.origin.z, ray.tnear, ray.direction.x, ray.direction.y, ray.direction.z, 0.0f,
      ray.tfar,     ~0u,          0u,           0u};
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.intersect(scene, rh);
  return {rh.ray.tfar, rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z, rh.hit.u, rh.hit.v, rh.hit.primID, rh.hit.geomID};
}

// With one hardware thread nothing runs at once: there is nothing to compare, so the tests skip.
constexpr const char* kOneThread = "needs at least two hardware threads: with one, no two queries run at once";

TEST(ConcurrencyTest, AllThreadsGiveBitIdenticalAnswersToOneThread) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << kOneThread;
  std::mt19937_64 random(31);
  std::vector<Shape> shapes;
  for (const testing::NamedProfile& named : testing::standardProfiles()) shapes.emplace_back(Profile(named.points));

  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  std::vector<std::unique_ptr<Geometry>> geometries;
  for (const Shape& shape : shapes) {
    geometries.push_back(std::make_unique<Geometry>(device, shape, Geometry::Options{.countStats = true}));
    rtcAttachGeometry(scene, geometries.back()->handle());
  }
  rtcCommitScene(scene);

  std::vector<Ray> rays;
  for (const Shape& shape : shapes) {
    const std::vector<Ray> some = testing::incoherentRays(shape, random, 20000);
    rays.insert(rays.end(), some.begin(), some.end());
  }

  // One thread first: the pure query on every shape, and Embree on the scene holding them all.
  std::vector<std::optional<Hit>> pureOne(rays.size() * shapes.size());
  std::vector<HitRecord> embreeOne(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    for (std::size_t k = 0; k < shapes.size(); ++k) pureOne[i * shapes.size() + k] = intersect(shapes[k], rays[i]);
    embreeOne[i] = traceEmbree(scene, rays[i]);
  }
  std::vector<Stats> countedOne;
  for (const auto& geometry : geometries) countedOne.push_back(geometry->stats());

  // Then all threads, twice over, the rays shuffled between them by TBB's work stealing.
  std::vector<std::optional<Hit>> pureAll(pureOne.size());
  std::vector<HitRecord> embreeAll(rays.size());
  tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < shapes.size(); ++k) pureAll[i * shapes.size() + k] = intersect(shapes[k], rays[i]);
    embreeAll[i] = traceEmbree(scene, rays[i]);
  });

  std::size_t pureDifferences = 0, embreeDifferences = 0;
  for (std::size_t i = 0; i < pureOne.size(); ++i) {
    const bool same = pureOne[i].has_value() == pureAll[i].has_value() &&
                      (!pureOne[i] || std::memcmp(&*pureOne[i], &*pureAll[i], sizeof(Hit)) == 0);
    pureDifferences += !same;
  }
  for (std::size_t i = 0; i < rays.size(); ++i) embreeDifferences += !(embreeOne[i] == embreeAll[i]);
  EXPECT_EQ(pureDifferences, 0u);
  EXPECT_EQ(embreeDifferences, 0u);

  // The counters saw exactly the same work a second time: totals are exactly twice the first.
  // (A shape hidden behind the others' surfaces may never be called: only the total must be > 0.)
  std::uint64_t calledRays = 0;
  for (std::size_t k = 0; k < geometries.size(); ++k) {
    calledRays += countedOne[k].rays;
    const Stats twice = geometries[k]->stats();
    EXPECT_EQ(twice.rays, 2 * countedOne[k].rays);
    EXPECT_EQ(twice.nodesVisited, 2 * countedOne[k].nodesVisited);
    EXPECT_EQ(twice.shellTests, 2 * countedOne[k].shellTests);
    EXPECT_EQ(twice.quadratics, 2 * countedOne[k].quadratics);
  }
  EXPECT_GT(calledRays, rays.size());
  rtcReleaseScene(scene);
  geometries.clear();
  rtcReleaseDevice(device);
}

TEST(ConcurrencyTest, CountersOfOneGeometryLoseNoUpdatesUnderContention) {
  // Every thread updates the same geometry's counters: a lost update shows as a total short of the
  // single-threaded one. Cheap rays (a 4-segment shape) make the updates as frequent as possible.
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << kOneThread;
  std::mt19937_64 random(32);
  const Shape shape{Profile(testing::cappedCylinder(0.5, -0.75, 0.75))};
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  Geometry geometry(device, shape, Geometry::Options{.countStats = true});
  rtcAttachGeometry(scene, geometry.handle());
  rtcCommitScene(scene);
  const std::vector<Ray> rays = testing::incoherentRays(shape, random, testing::scaledRays(200000));
  for (const Ray& ray : rays) traceEmbree(scene, ray);
  const Stats once = geometry.stats();
  for (int round = 0; round < 4; ++round) {
    tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) { traceEmbree(scene, rays[i]); });
  }
  const Stats total = geometry.stats();
  EXPECT_EQ(total.rays, 5 * once.rays);
  EXPECT_EQ(total.nodesVisited, 5 * once.nodesVisited);
  EXPECT_EQ(total.shellTests, 5 * once.shellTests);
  EXPECT_EQ(total.quadratics, 5 * once.quadratics);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}

}  // namespace
}  // namespace revolve
