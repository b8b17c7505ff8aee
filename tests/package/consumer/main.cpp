// Traces one ray through Embree at a revolve shape, as a user's application would.
#include <revolve/revolve.h>

#include <cstdio>
#include <vector>

int main() {
  const std::vector<revolve::Point2> points{{0, 0}, {1, 0}, {1, 2}, {0, 2}};  // a capped cylinder
  const revolve::Shape shape{revolve::Profile(points)};
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  {
    revolve::Geometry geometry(device, shape);
    rtcAttachGeometry(scene, geometry.handle());
    rtcCommitScene(scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray = {-5, 0, 1, 0, 1, 0, 0, 0, 100, ~0u, 0, 0};
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    rtcReleaseScene(scene);
    // The side of the cylinder at x = -1 is 4 units along the ray.
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.ray.tfar != 4.0f) {
      std::fprintf(stderr, "expected a hit at t = 4, got geomID %u t %g\n", rh.hit.geomID, rh.ray.tfar);
      return 1;
    }
  }
  rtcReleaseDevice(device);
  std::puts("consumer: hit at t = 4");
  return 0;
}
