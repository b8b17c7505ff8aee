// An Embree 4 application, written as Embree 4's tutorials are, using an installed revolve: a
// capped cylinder (radius 1, height 2) instanced at x = 10 beside a triangle quad at x = 8, traced
// with rtcIntersect1 (with and without arguments), rtcIntersect8 and rtcOccluded1/4 under valid
// masks, a filter passed in the query's arguments, and a point query. Every answer is a closed form.
#include <revolve/revolve.h>

#include <embree4/rtcore.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  failures += !ok;
}

bool near(float a, double b, double tolerance = 1e-5) { return std::abs(double(a) - b) <= tolerance; }

RTCRayHit rayHit(float ox, float oy, float oz, float dx, float dy, float dz) {
  RTCRayHit rh{};
  rh.ray.org_x = ox, rh.ray.org_y = oy, rh.ray.org_z = oz;
  rh.ray.dir_x = dx, rh.ray.dir_y = dy, rh.ray.dir_z = dz;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// The argument filter: rejects every candidate nearer than t = 5 (Embree sets the ray's tfar to the
// candidate's distance before calling it), whichever geometry it lies on.
void rejectNearerThan5(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != 0 && RTCRayN_tfar(args->ray, args->N, i) < 5.0f) args->valid[i] = 0;
  }
}

const revolve::Geometry* lookup(void* user, unsigned instID, unsigned geomID) {
  return instID == 0 && geomID == 0 ? static_cast<const revolve::Geometry*>(user) : nullptr;
}

}  // namespace

int main() {
  const std::vector<revolve::Point2> points{{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  const revolve::Shape shape{revolve::Profile(points)};
  RTCDevice device = rtcNewDevice(nullptr);

  RTCScene object = rtcNewScene(device);
  revolve::Geometry cylinder(device, shape);
  rtcAttachGeometryByID(object, cylinder.handle(), 0);
  rtcCommitScene(object);

  RTCScene world = rtcNewScene(device);
  rtcSetSceneFlags(world, RTC_SCENE_FLAG_FILTER_FUNCTION_IN_ARGUMENTS);
  RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, object);
  const float transform[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 10, 0, 0};  // column-major 3x4: x + 10
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, transform);
  rtcCommitGeometry(instance);
  rtcAttachGeometryByID(world, instance, 0);
  rtcReleaseGeometry(instance);
  // The quad x = 8, |y| <= 0.25, -1 <= z <= 3: in front of the cylinder for rays along y = 0.
  RTCGeometry quad = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(
      rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2));
  const float corners[12] = {8, -0.25f, -1, 8, 0.25f, -1, 8, 0.25f, 3, 8, -0.25f, 3};
  const unsigned triangles[6] = {0, 1, 2, 0, 2, 3};
  for (int i = 0; i < 12; ++i) vertices[i] = corners[i];
  for (int i = 0; i < 6; ++i) indices[i] = triangles[i];
  rtcCommitGeometry(quad);
  rtcAttachGeometryByID(world, quad, 1);
  rtcReleaseGeometry(quad);
  rtcCommitScene(world);

  // rtcIntersect1 without arguments, past the quad: the cylinder's side at x = 9, t = 4.
  {
    RTCRayHit rh = rayHit(5, 0.5f, 1, 1, 0, 0);
    rtcIntersect1(world, &rh);
    const double t = 5.0 - std::sqrt(0.75);  // x = 10 - sqrt(1 - 0.5^2)
    check(rh.hit.instID[0] == 0 && rh.hit.geomID == 0 && rh.hit.primID == 1 && near(rh.ray.tfar, t),
          "rtcIntersect1: the instanced cylinder's side at t = 5 - sqrt(3/4), segment 1");
    const double phi = std::atan2(0.5, -std::sqrt(0.75));
    check(near(rh.hit.Ng_x, -std::sqrt(0.75)) && near(rh.hit.Ng_y, 0.5) && near(rh.hit.Ng_z, 0) &&
              near(rh.hit.u, phi / (2 * M_PI)) && near(rh.hit.v, 0.5),
          "rtcIntersect1: Ng the outward radial direction, u = phi / 2pi, v = 1/2");
#if defined(RTC_GEOMETRY_INSTANCE_ARRAY)
    check(rh.hit.instPrimID[0] == 0, "rtcIntersect1: instPrimID 0 for a plain instance");
#endif
  }

  // The same query with arguments and a filter on them: the quad (t = 3) and the cylinder's near
  // side (t = 4) are rejected, the far side at x = 11 (t = 6, Ng +x) is kept.
  {
    RTCIntersectArguments args;
    rtcInitIntersectArguments(&args);
    args.filter = rejectNearerThan5;
    args.flags = RTC_RAY_QUERY_FLAG_INVOKE_ARGUMENT_FILTER;
    RTCRayHit rh = rayHit(5, 0, 1, 1, 0, 0);
    rtcIntersect1(world, &rh, &args);
    check(
        rh.hit.geomID == 0 && rh.hit.instID[0] == 0 && near(rh.ray.tfar, 6.0) && near(rh.hit.Ng_x, 1.0),
        "argument filter (RTC_RAY_QUERY_FLAG_INVOKE_ARGUMENT_FILTER): quad and near side rejected, far side at t = 6");
    RTCRayHit unfiltered = rayHit(5, 0, 1, 1, 0, 0);
    rtcIntersect1(world, &unfiltered);
    check(unfiltered.hit.geomID == 1 && near(unfiltered.ray.tfar, 3.0), "without the filter: the quad at t = 3");
    check(revolve::Geometry::argumentFiltersSupported(device), "Geometry::argumentFiltersSupported");
  }

  // rtcIntersect8 with every other lane valid: the side at t = 5 - sqrt(3/4) in valid lanes, the
  // other lanes untouched.
  {
    alignas(32) int valid[8];
    alignas(32) RTCRayHit8 packet{};
    for (int i = 0; i < 8; ++i) {
      valid[i] = i % 2 == 0 ? -1 : 0;
      packet.ray.org_x[i] = 5, packet.ray.org_y[i] = 0.5f, packet.ray.org_z[i] = 0.125f + 0.25f * float(i);
      packet.ray.dir_x[i] = 1;
      packet.ray.tfar[i] = std::numeric_limits<float>::infinity();
      packet.ray.mask[i] = ~0u;
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, world, &packet);
    bool ok = true;
    for (int i = 0; i < 8; ++i) {
      if (valid[i] != 0) {
        ok = ok && packet.hit.geomID[i] == 0 && packet.hit.instID[0][i] == 0 && packet.hit.primID[i] == 1 &&
             near(packet.ray.tfar[i], 5.0 - std::sqrt(0.75)) &&
             near(packet.hit.v[i], (1.0 + packet.ray.org_z[i]) / 4.0);
      } else {
        ok = ok && packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID && std::isinf(packet.ray.tfar[i]);
      }
    }
    check(ok,
          "rtcIntersect8 with a valid mask: valid lanes hit at t = 5 - sqrt(3/4), v = (1 + z) / 4; others untouched");
  }

  // rtcOccluded1 and rtcOccluded4: blocked when the segment reaches the side, not when it stops short.
  {
    RTCRay ray = rayHit(5, 0.5f, 1, 1, 0, 0).ray;
    rtcOccluded1(world, &ray);
    RTCRay shortRay = rayHit(5, 0.5f, 1, 1, 0, 0).ray;
    shortRay.tfar = 4.0f;
    rtcOccluded1(world, &shortRay);
    check(ray.tfar == -std::numeric_limits<float>::infinity() && shortRay.tfar == 4.0f,
          "rtcOccluded1: occluded up to t = inf, not up to t = 4");
    alignas(16) int valid[4] = {-1, -1, 0, -1};
    alignas(16) RTCRay4 rays{};
    const float tfar[4] = {10.0f, 4.0f, 10.0f, 4.2f};
    for (int i = 0; i < 4; ++i) {
      rays.org_x[i] = 5, rays.org_y[i] = 0.5f, rays.org_z[i] = 1, rays.dir_x[i] = 1, rays.tfar[i] = tfar[i],
      rays.mask[i] = ~0u;
    }
    rtcOccluded4(valid, world, &rays);
    const float inf = std::numeric_limits<float>::infinity();
    check(rays.tfar[0] == -inf && rays.tfar[1] == 4.0f && rays.tfar[2] == 10.0f && rays.tfar[3] == -inf,
          "rtcOccluded4 with a valid mask: lanes reaching t = 4.134 occluded, the short and the invalid lane not");
  }

  // The closest surface point to (13, 0, 1): the side at (11, 0, 1), 2 away.
  {
    const std::optional<revolve::ScenePoint> closest =
        revolve::closestPoint(world, {13, 0, 1}, 100.0f, lookup, &cylinder);
    check(closest && closest->instID == 0 && near(closest->distance, 2.0) && near(closest->point.x, 11.0),
          "point query through the instance: distance 2 to (11, 0, 1)");
  }

  rtcReleaseScene(world);
  rtcReleaseScene(object);
  rtcReleaseDevice(device);
  std::printf("consumer_embree4: %d failure(s)\n", failures);
  return failures == 0 ? 0 : 1;
}
