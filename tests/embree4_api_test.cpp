// What only Embree 4 has, used as Embree 4's tutorials use it (built only against Embree 4):
// rtcIntersect1 without arguments, argument filters enabled per geometry with
// rtcSetGeometryEnableFilterFunctionFromArguments (no query flag), and instance arrays' instPrimID.
// A capped cylinder (radius 1, height 2) at the origin behind a triangle quad in the plane x = -2;
// rays from x = -5 along +x meet the quad at t = 3 and the cylinder at t = 4 and 6.
#include <revolve/revolve.h>

#include <embree4/rtcore.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace revolve {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

void rejectNearerThan5(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (RTCRayN_tfar(args->ray, args->N, i) < 5.0f) args->valid[i] = 0;
  }
}

RTCRayHit rayAt(float y, float z) {
  RTCRayHit rh{};
  rh.ray.org_x = -5, rh.ray.org_y = y, rh.ray.org_z = z;
  rh.ray.dir_x = 1;
  rh.ray.tfar = kInf;
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

struct Scene4 {
  RTCDevice device = rtcNewDevice(nullptr);
  Shape shape{Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 2}, {0, 2}})};
  Geometry cylinder{device, shape};
  RTCGeometry quad = nullptr;
  RTCScene scene = rtcNewScene(device);

  Scene4() {
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_FILTER_FUNCTION_IN_ARGUMENTS);
    rtcAttachGeometryByID(scene, cylinder.handle(), 0);
    quad = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 4));
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, 2));
    const float corners[12] = {-2, -0.5f, -1, -2, 0.5f, -1, -2, 0.5f, 3, -2, -0.5f, 3};
    const unsigned triangles[6] = {0, 1, 2, 0, 2, 3};
    std::copy(corners, corners + 12, v);
    std::copy(triangles, triangles + 6, t);
    rtcCommitGeometry(quad);
    rtcAttachGeometryByID(scene, quad, 1);
    rtcCommitScene(scene);
  }
  ~Scene4() {
    rtcReleaseGeometry(quad);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  // The argument filter with no query flag: Embree calls it for the geometries enabled by
  // rtcSetGeometryEnableFilterFunctionFromArguments only.
  RTCRayHit trace() {
    RTCIntersectArguments args;
    rtcInitIntersectArguments(&args);
    args.filter = rejectNearerThan5;
    RTCRayHit rh = rayAt(0, 1);
    rtcIntersect1(scene, &rh, &args);
    return rh;
  }
};

TEST(Embree4Api, Intersect1WithoutArguments) {
  Scene4 s;
  RTCRayHit rh = rayAt(0, 1);
  rtcIntersect1(s.scene, &rh);
  EXPECT_EQ(rh.hit.geomID, 1u);
  EXPECT_EQ(rh.ray.tfar, 3.0f);
  RTCRayHit beside = rayAt(0.75f, 1);  // misses the quad: the cylinder at x = -sqrt(1 - 0.75^2)
  rtcIntersect1(s.scene, &beside);
  EXPECT_EQ(beside.hit.geomID, 0u);
  EXPECT_NEAR(beside.ray.tfar, 5.0 - std::sqrt(1.0 - 0.5625), 1e-6);
}

TEST(Embree4Api, ArgumentFiltersFollowEachGeometrysSwitch) {
  Scene4 s;
  ASSERT_TRUE(Geometry::argumentFiltersSupported(s.device));
  // Enabled on neither: nothing filtered, the quad at t = 3.
  EXPECT_EQ(s.trace().ray.tfar, 3.0f);
  // On the quad only: the quad's hit rejected, the cylinder's near side (not enabled) kept.
  rtcSetGeometryEnableFilterFunctionFromArguments(s.quad, true);
  rtcCommitGeometry(s.quad);
  rtcCommitScene(s.scene);
  RTCRayHit quadOnly = s.trace();
  EXPECT_EQ(quadOnly.hit.geomID, 0u);
  EXPECT_EQ(quadOnly.ray.tfar, 4.0f);
  // On both: the near side rejected too, the far side at t = 6.
  s.cylinder.enableFilterFunctionFromArguments(true);
  rtcCommitGeometry(s.cylinder.handle());
  rtcCommitScene(s.scene);
  RTCRayHit both = s.trace();
  EXPECT_EQ(both.hit.geomID, 0u);
  EXPECT_EQ(both.ray.tfar, 6.0f);
  // On the cylinder only.
  rtcSetGeometryEnableFilterFunctionFromArguments(s.quad, false);
  rtcCommitGeometry(s.quad);
  rtcCommitScene(s.scene);
  EXPECT_EQ(s.trace().ray.tfar, 3.0f);
}

#if defined(RTC_GEOMETRY_INSTANCE_ARRAY)
TEST(Embree4Api, InstanceArraysReportInstPrimID) {
  // Three copies of the cylinder in one instance array, at y = 0, 10 and 20: a ray at each reports
  // the array's instID and the copy's instPrimID.
  RTCDevice device = rtcNewDevice(nullptr);
  {
    const Shape shape(Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 2}, {0, 2}}));
    Geometry cylinder(device, shape);
    RTCScene object = rtcNewScene(device);
    rtcAttachGeometry(object, cylinder.handle());
    rtcCommitScene(object);
    RTCGeometry array = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE_ARRAY);
    rtcSetGeometryInstancedScene(array, object);
    auto* transforms = static_cast<float*>(rtcSetNewGeometryBuffer(
        array, RTC_BUFFER_TYPE_TRANSFORM, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, 12 * sizeof(float), 3));
    for (int i = 0; i < 3; ++i) {
      const float m[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 10.0f * float(i), 0};
      std::copy(m, m + 12, transforms + 12 * i);
    }
    rtcCommitGeometry(array);
    RTCScene world = rtcNewScene(device);
    const unsigned arrayID = rtcAttachGeometry(world, array);
    rtcReleaseGeometry(array);
    rtcCommitScene(world);
    for (unsigned copy = 0; copy < 3; ++copy) {
      RTCRayHit rh = rayAt(10.0f * float(copy), 1);
      rtcIntersect1(world, &rh);
      EXPECT_EQ(rh.hit.instID[0], arrayID);
      EXPECT_EQ(rh.hit.instPrimID[0], copy);
      EXPECT_EQ(rh.ray.tfar, 4.0f);
    }
    rtcReleaseScene(world);
    rtcReleaseScene(object);
  }
  rtcReleaseDevice(device);
}
#endif

}  // namespace
}  // namespace revolve
