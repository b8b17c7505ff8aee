// The per-ray code is compiled once per instruction set (src/util/isa.h): every copy must give the
// same answers bit for bit, whichever one the CPU picks. Each copy this CPU runs is held against the
// baseline (SSE2): the pure queries, and the Embree callbacks through every packet width.
#include <revolve/baselines.h>
#include <revolve/revolve.h>
#include "embree/callback_kernels.h"
#include "embree/embree_handles.h"
#include "shape/query_kernels.h"
#include "support/spline_profiles.h"
#include "support/test_profiles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameHit(const Hit& a, const Hit& b) {
  return sameBits(a.t, b.t) && sameBits(a.u, b.u) && sameBits(a.v, b.v) && a.segment == b.segment &&
         sameBits(a.normal.x, b.normal.x) && sameBits(a.normal.y, b.normal.y) && sameBits(a.normal.z, b.normal.z);
}

// The copies beyond the baseline that this CPU runs (none on a CPU without AVX2).
std::vector<detail::Isa> widerIsas() {
  std::vector<detail::Isa> isas;
  for (const detail::Isa isa : detail::kIsas)
    if (isa != detail::Isa::sse2 && detail::cpuRuns(isa)) isas.push_back(isa);
  return isas;
}

std::vector<Ray> raysFor(const Shape& shape, std::mt19937_64& random, std::size_t incoherent, std::size_t awkward) {
  std::vector<Ray> rays = testing::incoherentRays(shape, random, incoherent);
  const std::vector<Ray> aligned = testing::axisAlignedRays(shape, random, awkward);
  rays.insert(rays.end(), aligned.begin(), aligned.end());
  return rays;
}

// `wide`'s answers against the baseline's on every ray; returns the number of hits.
std::size_t expectSameAnswers(const detail::QueryKernels& baseline, const detail::QueryKernels& wide,
                              const Shape& shape, const std::vector<Ray>& rays, const std::string& name) {
  SCOPED_TRACE(name + ", " + wide.isa);
  std::size_t hits = 0;
  for (const Ray& ray : rays) {
    Stats statsA, statsB;
    const std::optional<Hit> a = baseline.intersect(detail::implOf(shape), ray, &statsA);
    const std::optional<Hit> b = wide.intersect(detail::implOf(shape), ray, &statsB);
    EXPECT_EQ(a.has_value(), b.has_value());
    if (a.has_value() != b.has_value()) return hits;
    EXPECT_EQ(baseline.occluded(detail::implOf(shape), ray, nullptr),
              wide.occluded(detail::implOf(shape), ray, nullptr));
    EXPECT_EQ(statsA.quadratics, statsB.quadratics);
    if (!a) continue;
    ++hits;
    EXPECT_TRUE(sameHit(*a, *b)) << "t " << a->t << " vs " << b->t;
    const std::optional<Hit> c = baseline.attributes(detail::implOf(shape), ray, a->segment, a->t);
    const std::optional<Hit> d = wide.attributes(detail::implOf(shape), ray, a->segment, a->t);
    EXPECT_TRUE(c && d && sameHit(*c, *d)) << "surfaceAttributes";
    if (::testing::Test::HasFailure()) return hits;
  }
  return hits;
}

TEST(IsaTest, EveryInstructionSetGivesTheSameHitsBitForBit) {
  const detail::QueryKernels* baseline = detail::queryKernelsFor(detail::Isa::sse2);
  ASSERT_NE(baseline, nullptr);
  const std::vector<detail::Isa> isas = widerIsas();
  if (isas.empty()) GTEST_SKIP() << "this CPU has no AVX2: only the baseline copy runs here";
  std::mt19937_64 random(20240);
  std::size_t hits = 0;
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    for (const BuildOptions options :
         {BuildOptions{}, BuildOptions{.method = Method::linear}, BuildOptions{.method = Method::kajiya},
          BuildOptions{.method = Method::mibit, .shell = ShellKind::hybrid}}) {
      const Shape shape(Profile(named.points), options);
      const std::vector<Ray> rays = raysFor(shape, random, 3000, 1000);
      for (const detail::Isa isa : isas)
        hits += expectSameAnswers(*baseline, *detail::queryKernelsFor(isa), shape, rays, named.name);
    }
  }
  EXPECT_GT(hits, 10000u * isas.size());
}

TEST(IsaTest, SplineShapesGiveTheSameHitsBitForBit) {
  const detail::QueryKernels* baseline = detail::queryKernelsFor(detail::Isa::sse2);
  ASSERT_NE(baseline, nullptr);
  const std::vector<detail::Isa> isas = widerIsas();
  if (isas.empty()) GTEST_SKIP() << "this CPU has no AVX2: only the baseline copy runs here";
  std::mt19937_64 random(20241);
  std::size_t hits = 0;
  for (const testing::NamedSpline& named : testing::closedSplines()) {
    const Shape shape(Spline(named.kind, named.points));
    const std::vector<Ray> rays = raysFor(shape, random, 2000, 500);
    for (const detail::Isa isa : isas)
      hits += expectSameAnswers(*baseline, *detail::queryKernelsFor(isa), shape, rays, named.name);
  }
  EXPECT_GT(hits, 10000u * isas.size());
}

// The Embree callbacks of one instruction set: a geometry made while the choice is limited to it.
struct CallbackScene {
  app::Scene scene;
  std::unique_ptr<Geometry> geometry;

  CallbackScene(RTCDevice device, const Shape& shape, detail::Isa isa) : scene(app::newScene(device)) {
    detail::limitIsa(isa);
    EXPECT_STREQ(detail::callbackKernels().isa, detail::isaName(isa));
    geometry = std::make_unique<Geometry>(device, shape);
    detail::limitIsa(detail::Isa::avx512);  // no limit again: avx512 is the widest copy
    rtcAttachGeometry(scene.get(), geometry->handle());
    rtcCommitScene(scene.get());
  }
};

// What a packet of 16 (some lanes off) answers: per lane, tfar, primID, normal, u, v and occlusion.
struct Answers {
  float tfar[16], nx[16], ny[16], nz[16], u[16], v[16], occludedTfar[16];
  unsigned primID[16];
};

Answers trace16(RTCScene scene, const Ray* rays, const int* valid) {
  alignas(64) RTCRayHit16 packet{};
  alignas(64) RTCRay16 shadow{};
  alignas(64) int lanes[16];
  for (int i = 0; i < 16; ++i) {
    lanes[i] = valid[i];
    const Ray& ray = rays[i];
    packet.ray.org_x[i] = shadow.org_x[i] = ray.origin.x;
    packet.ray.org_y[i] = shadow.org_y[i] = ray.origin.y;
    packet.ray.org_z[i] = shadow.org_z[i] = ray.origin.z;
    packet.ray.dir_x[i] = shadow.dir_x[i] = ray.direction.x;
    packet.ray.dir_y[i] = shadow.dir_y[i] = ray.direction.y;
    packet.ray.dir_z[i] = shadow.dir_z[i] = ray.direction.z;
    packet.ray.tnear[i] = shadow.tnear[i] = ray.tnear;
    packet.ray.tfar[i] = shadow.tfar[i] = ray.tfar;
    packet.ray.mask[i] = shadow.mask[i] = ~0u;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
  }
  embree::RayQuery query;
  query.intersect(lanes, scene, packet);
  query.occluded(lanes, scene, shadow);
  Answers answers;
  for (int i = 0; i < 16; ++i) {
    answers.tfar[i] = packet.ray.tfar[i], answers.primID[i] = packet.hit.primID[i];
    answers.nx[i] = packet.hit.Ng_x[i], answers.ny[i] = packet.hit.Ng_y[i], answers.nz[i] = packet.hit.Ng_z[i];
    answers.u[i] = packet.hit.u[i], answers.v[i] = packet.hit.v[i], answers.occludedTfar[i] = shadow.tfar[i];
  }
  return answers;
}

// rtcIntersect16 and rtcOccluded16 through each copy's callbacks, against the baseline's (the
// packet suites hold the baseline's packets against the single-ray queries).
TEST(IsaTest, EmbreeCallbacksOfEveryInstructionSetAnswerPacketsBitForBit) {
  const std::vector<detail::Isa> isas = widerIsas();
  if (isas.empty()) GTEST_SKIP() << "this CPU has no AVX2: only the baseline copy runs here";
  const app::Device device = app::newDevice();
  std::mt19937_64 random(20242);
  std::size_t hits = 0;
  for (const testing::NamedProfile& named : testing::standardProfiles()) {
    const Shape shape{Profile(named.points)};
    const std::vector<Ray> rays = raysFor(shape, random, 768, 256);
    const CallbackScene baseline(device.get(), shape, detail::Isa::sse2);
    for (const detail::Isa isa : isas) {
      SCOPED_TRACE(named.name + ", " + detail::isaName(isa));
      const CallbackScene wide(device.get(), shape, isa);
      for (std::size_t first = 0; first + 16 <= rays.size(); first += 16) {
        int valid[16];
        for (int& lane : valid) lane = random() % 7 == 0 ? 0 : -1;
        const Answers a = trace16(baseline.scene.get(), &rays[first], valid);
        const Answers b = trace16(wide.scene.get(), &rays[first], valid);
        for (int i = 0; i < 16; ++i) {
          ASSERT_TRUE(sameBits(a.tfar[i], b.tfar[i]) && sameBits(a.occludedTfar[i], b.occludedTfar[i])) << i;
          if (valid[i] != -1 || a.tfar[i] == rays[first + std::size_t(i)].tfar) continue;
          ++hits;
          ASSERT_EQ(a.primID[i], b.primID[i]);
          ASSERT_TRUE(sameBits(a.nx[i], b.nx[i]) && sameBits(a.ny[i], b.ny[i]) && sameBits(a.nz[i], b.nz[i]) &&
                      sameBits(a.u[i], b.u[i]) && sameBits(a.v[i], b.v[i]));
        }
      }
    }
  }
  EXPECT_GT(hits, 1000u * isas.size());
}

}  // namespace
}  // namespace revolve
