// A filter passed with the query (Embree 4's argument filter, Embree 3's context filter) must treat
// a revolve shape as Embree treats a triangle mesh in the same scene, in every query: rtcIntersect1,
// rtcIntersect4/8/16 and rtcOccluded1/4/8/16. The scene: a capped cylinder (radius 1, height 2) at
// the origin behind a triangle quad in the plane x = -2, rays from x = -5 along +x; the answers are closed
// forms. Also: Geometry moves as an owning handle does.
#include "embree/embree_handles.h"

#include <revolve/revolve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace revolve {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

using app::DeviceRelease;  // the applications' owning handles (common/embree_handles.h)
using app::SceneRelease;

// Rejects every candidate nearer than t = 5 (the ray's tfar holds the candidate's distance), on
// whatever geometry; counts its calls by geometry.
int gCalls[2];
void rejectNearerThan5(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const unsigned geomID = RTCHitN_geomID(args->hit, args->N, i);
    if (geomID < 2) ++gCalls[geomID];
    if (RTCRayN_tfar(args->ray, args->N, i) < 5.0f) args->valid[i] = 0;
  }
}

class QueryFilterScene : public ::testing::Test {
 protected:
  void SetUp() override {
    device_.reset(rtcNewDevice(nullptr));
    rtcSetDeviceErrorFunction(
        device_.get(),
        [](void*, RTCError code, const char* message) { ADD_FAILURE() << "Embree error " << code << ": " << message; },
        nullptr);
    shape_ = std::make_unique<Shape>(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 2}, {0, 2}}));
    cylinder_ = std::make_unique<Geometry>(device_.get(), *shape_);
    scene_.reset(rtcNewScene(device_.get()));
    rtcSetSceneFlags(scene_.get(), embree::kQueryFilterSceneFlag);
    rtcAttachGeometryByID(scene_.get(), cylinder_->handle(), 0);
    RTCGeometry quad = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 4));
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, 2));
    const float corners[12] = {-2, -0.5f, -1, -2, 0.5f, -1, -2, 0.5f, 3, -2, -0.5f, 3};  // the plane x = -2
    const unsigned triangles[6] = {0, 1, 2, 0, 2, 3};
    std::copy(corners, corners + 12, v);
    std::copy(triangles, triangles + 6, t);
    rtcCommitGeometry(quad);
    rtcAttachGeometryByID(scene_.get(), quad, 1);
    rtcReleaseGeometry(quad);
    rtcCommitScene(scene_.get());
    gCalls[0] = gCalls[1] = 0;
  }

  // A ray from x = -5 along +x at height z: the quad at t = 3, the cylinder's near side at t = 4,
  // its far side at t = 6.
  static RTCRayHit ray(float z) { return embree::newRayHit(-5, 0, z, 1, 0, 0, 0, kInf); }

  std::unique_ptr<RTCDeviceTy, DeviceRelease> device_;
  std::unique_ptr<Shape> shape_;
  std::unique_ptr<Geometry> cylinder_;
  std::unique_ptr<RTCSceneTy, SceneRelease> scene_;
};

TEST_F(QueryFilterScene, WithoutAFilterTheQuadIsHitFirst) {
  embree::RayQuery query;
  RTCRayHit rh = ray(1);
  query.intersect(scene_.get(), rh);
  EXPECT_EQ(rh.hit.geomID, 1u);
  EXPECT_EQ(rh.ray.tfar, 3.0f);
}

TEST_F(QueryFilterScene, Intersect1RejectsTheQuadAndTheNearSideAlike) {
  embree::RayQuery query({.filter = rejectNearerThan5});
  RTCRayHit rh = ray(1);
  query.intersect(scene_.get(), rh);
  ASSERT_TRUE(Geometry::argumentFiltersSupported(device_.get()));
  EXPECT_EQ(rh.hit.geomID, 0u);
  EXPECT_EQ(rh.ray.tfar, 6.0f);
  EXPECT_EQ(rh.hit.Ng_x, 1.0f);  // the far side faces +x
  EXPECT_EQ(rh.hit.primID, 1u);
  EXPECT_GE(gCalls[1], 1);  // Embree offered the quad's hit
  EXPECT_EQ(gCalls[0], 2);  // revolve offered both of the cylinder's, nearest first
}

template <int N, class Packet>
void tracePacket(embree::RayQuery& query, RTCScene scene, Packet& packet, const int* valid) {
  for (int i = 0; i < N; ++i) {
    const RTCRayHit one = embree::newRayHit(-5, 0, 0.1f + 0.2f * float(i % 10), 1, 0, 0, 0, kInf);
    packet.ray.org_x[i] = one.ray.org_x, packet.ray.org_y[i] = one.ray.org_y, packet.ray.org_z[i] = one.ray.org_z;
    packet.ray.dir_x[i] = one.ray.dir_x, packet.ray.dir_y[i] = one.ray.dir_y, packet.ray.dir_z[i] = one.ray.dir_z;
    packet.ray.tnear[i] = 0, packet.ray.tfar[i] = kInf, packet.ray.mask[i] = ~0u;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
  }
  query.intersect(valid, scene, packet);
}

template <int N, class RayHitN, class RayN>
void expectPacketsFiltered(RTCScene scene) {
  embree::RayQuery query({.filter = rejectNearerThan5});
  alignas(64) int valid[N];
  for (int i = 0; i < N; ++i) valid[i] = i % 3 == 1 ? 0 : -1;
  alignas(64) RayHitN packet{};
  tracePacket<N>(query, scene, packet, valid);
  for (int i = 0; i < N; ++i) {
    SCOPED_TRACE(::testing::Message() << "rtcIntersect" << N << " lane " << i);
    if (valid[i] == 0) {
      EXPECT_EQ(packet.hit.geomID[i], RTC_INVALID_GEOMETRY_ID);
      EXPECT_EQ(packet.ray.tfar[i], kInf);
    } else {
      EXPECT_EQ(packet.hit.geomID[i], 0u);
      EXPECT_EQ(packet.ray.tfar[i], 6.0f);
    }
  }
  // Occlusion: every candidate before t = 5 rejected, the far side still blocks; up to t = 5.5,
  // nothing does.
  alignas(64) RayN shadow{};
  for (int i = 0; i < N; ++i) {
    shadow.org_x[i] = -5, shadow.org_z[i] = 1, shadow.dir_x[i] = 1, shadow.mask[i] = ~0u;
    shadow.tfar[i] = i % 2 == 0 ? kInf : 5.5f;
  }
  query.occluded(valid, scene, shadow);
  for (int i = 0; i < N; ++i) {
    SCOPED_TRACE(::testing::Message() << "rtcOccluded" << N << " lane " << i);
    if (valid[i] == 0) {
      EXPECT_EQ(shadow.tfar[i], i % 2 == 0 ? kInf : 5.5f);
    } else {
      EXPECT_EQ(shadow.tfar[i], i % 2 == 0 ? -kInf : 5.5f);
    }
  }
}

TEST_F(QueryFilterScene, PacketsAndOcclusionRejectAlike) {
  expectPacketsFiltered<4, RTCRayHit4, RTCRay4>(scene_.get());
  expectPacketsFiltered<8, RTCRayHit8, RTCRay8>(scene_.get());
  expectPacketsFiltered<16, RTCRayHit16, RTCRay16>(scene_.get());
  embree::RayQuery query({.filter = rejectNearerThan5});
  RTCRay blocked = ray(1).ray, clear = ray(1).ray;
  clear.tfar = 5.5f;
  query.occluded(scene_.get(), blocked);
  query.occluded(scene_.get(), clear);
  EXPECT_EQ(blocked.tfar, -kInf);
  EXPECT_EQ(clear.tfar, 5.5f);
}

TEST_F(QueryFilterScene, TheGeometrysOwnFilterRunsFirst) {
  // The geometry's filter rejects everything; the query's is then never offered the cylinder's
  // hits, as Embree does for its own primitives (kernels/geometry/filter.h).
  cylinder_->setIntersectFilter([](const RTCFilterFunctionNArguments* args) {
    for (unsigned i = 0; i < args->N; ++i) args->valid[i] = 0;
  });
  rtcCommitGeometry(cylinder_->handle());
  rtcCommitScene(scene_.get());
  embree::RayQuery query({.filter = rejectNearerThan5});
  RTCRayHit rh = ray(1);
  query.intersect(scene_.get(), rh);
  EXPECT_EQ(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(gCalls[0], 0);
  EXPECT_GE(gCalls[1], 1);
}

TEST(EmbreeGeometryMove, AMovedGeometryKeepsTracingAndTheMovedFromOneIsEmpty) {
  std::unique_ptr<RTCDeviceTy, DeviceRelease> device(rtcNewDevice(nullptr));
  const Shape shape(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 2}, {0, 2}}));
  Geometry first(device.get(), shape);
  const RTCGeometry handle = first.handle();
  Geometry second(std::move(first));
  EXPECT_EQ(first.handle(), nullptr);  // NOLINT(bugprone-use-after-move): the moved-from state is the point
  EXPECT_EQ(second.handle(), handle);

  Geometry third(device.get(), shape);
  third = std::move(second);  // releases third's own geometry
  EXPECT_EQ(third.handle(), handle);

  std::unique_ptr<RTCSceneTy, SceneRelease> scene(rtcNewScene(device.get()));
  rtcAttachGeometry(scene.get(), third.handle());
  rtcCommitScene(scene.get());
  RTCRayHit rh = embree::newRayHit(-5, 0, 1, 1, 0, 0, 0, kInf);
  embree::RayQuery query;
  query.intersect(scene.get(), rh);
  EXPECT_EQ(rh.hit.geomID, 0u);
  EXPECT_EQ(rh.ray.tfar, 4.0f);

  std::vector<Geometry> many;  // a vector of geometries: possible now that they move
  for (int i = 0; i < 3; ++i) many.emplace_back(device.get(), shape);
  many.erase(many.begin());
  EXPECT_EQ(many.size(), 2u);
  EXPECT_NE(many[0].handle(), nullptr);
}

}  // namespace
}  // namespace revolve
