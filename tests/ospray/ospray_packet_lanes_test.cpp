// The module's intersect entry (revolveOsprayIntersect) called directly with Embree's packets of
// 4, 8 and 16 lanes, as OSPRay's SSE4, AVX/AVX2 and AVX-512 kernels hand them, some lanes
// switched off. This host runs OSPRay's 16-wide kernels only, so the other widths are met here.
// Expected: rays from y = -5 along +y at a cylinder of radius 1 (z in [0, 2]) hit at t = 4 with
// Ng = (0, -1, 0) exactly where a lane is on and its height z lies in [0, 2]; a lane off is untouched.
#include "RevolutionsShared.h"
#include "revolution_hits.h"
#include "revolution_set.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace revolve::ospray_test {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Packet {
  RTCRayHit16 storage{};  // room for any width up to 16, laid out for the width N used
  std::array<int, 16> valid{};
};

// Lane i: on when i % 3 != 1; height z = 0.5 i - 0.75 (some lanes pass below or above the can, none
// along its rims, where revolve's boundary rule decides).
void fill(Packet& packet, unsigned n) {
  auto* rayhit = reinterpret_cast<RTCRayHitN*>(&packet.storage);
  RTCRayN* ray = RTCRayHitN_RayN(rayhit, n);
  RTCHitN* hit = RTCRayHitN_HitN(rayhit, n);
  for (unsigned i = 0; i < n; ++i) {
    packet.valid[i] = i % 3 != 1 ? -1 : 0;
    RTCRayN_org_x(ray, n, i) = 0.0f, RTCRayN_org_y(ray, n, i) = -5.0f, RTCRayN_org_z(ray, n, i) = 0.5f * i - 0.75f;
    RTCRayN_dir_x(ray, n, i) = 0.0f, RTCRayN_dir_y(ray, n, i) = 1.0f, RTCRayN_dir_z(ray, n, i) = 0.0f;
    RTCRayN_tnear(ray, n, i) = 0.0f;
    RTCRayN_tfar(ray, n, i) = kInfinity;
    RTCHitN_geomID(hit, n, i) = RTC_INVALID_GEOMETRY_ID;
  }
}

TEST(OsprayPacketLanes, EveryWidthAndMaskHitsTheCylinderExactly) {
  const std::vector<ospray_module::Revolution> revolutions = ospray_module::buildRevolutions(
      ospray_module::RevolutionParameters{{{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 2.0f}, {0.0f, 2.0f}}}, {}, {}});
  ispc::Revolutions shared;
  shared.host = const_cast<std::vector<ospray_module::Revolution>*>(&revolutions);
  RTCRayQueryContext context{};
  context.instID[0] = 7;
  for (const unsigned n : {4u, 8u, 16u}) {
    for (const int occlusion : {0, 1}) {
      Packet packet;
      fill(packet, n);
      auto* rayhit = reinterpret_cast<RTCRayHitN*>(&packet.storage);
      RTCIntersectFunctionNArguments args{packet.valid.data(), &shared, 0, &context, rayhit, n, 3};
      revolveOsprayIntersect(&args, occlusion);
      RTCRayN* ray = RTCRayHitN_RayN(rayhit, n);
      RTCHitN* hit = RTCRayHitN_HitN(rayhit, n);
      for (unsigned i = 0; i < n; ++i) {
        const float z = 0.5f * float(i) - 0.75f;
        const bool hits = packet.valid[i] != 0 && z > 0.0f && z < 2.0f;
        SCOPED_TRACE(testing::Message() << n << " lanes, lane " << i << (occlusion ? ", occlusion" : ""));
        if (!hits) {
          EXPECT_EQ(RTCRayN_tfar(ray, n, i), kInfinity);
          EXPECT_EQ(RTCHitN_geomID(hit, n, i), RTC_INVALID_GEOMETRY_ID);
        } else if (occlusion) {
          EXPECT_EQ(RTCRayN_tfar(ray, n, i), -kInfinity);  // Embree's mark of an occluded ray
        } else {
          EXPECT_EQ(RTCRayN_tfar(ray, n, i), 4.0f);
          EXPECT_EQ(RTCHitN_Ng_x(hit, n, i), 0.0f);
          EXPECT_EQ(RTCHitN_Ng_y(hit, n, i), -1.0f);
          EXPECT_EQ(RTCHitN_Ng_z(hit, n, i), 0.0f);
          EXPECT_EQ(RTCHitN_primID(hit, n, i), 0u);
          EXPECT_EQ(RTCHitN_geomID(hit, n, i), 3u);
          EXPECT_EQ(RTCHitN_instID(hit, n, i, 0), 7u);
        }
      }
    }
  }
}

}  // namespace
}  // namespace revolve::ospray_test
