// A vase traced exactly through Embree 3 with revolve: a profile, its Shape, an Embree user
// geometry in a scene of its own, that scene instanced twice into the scene rays are traced in,
// and each hit read back from RTCRayHit. Prints one line a ray; exits 1 if a hit disagrees with
// revolve's own query (revolve::intersect, no Embree), so it also serves as a test.
#include <revolve/revolve.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace {

// A column-major 3 x 4 affine transform for rtcSetGeometryTransform: scale s, then translate.
struct Placement {
  float scale, x, y, z;
  void apply(RTCGeometry instance) const {
    const float matrix[12] = {scale, 0, 0, 0, scale, 0, 0, 0, scale, x, y, z};
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, matrix);
  }
};

RTCRayHit rayHit(revolve::Vec3 origin, revolve::Vec3 direction) {
  RTCRayHit rh{};
  rh.ray.org_x = origin.x, rh.ray.org_y = origin.y, rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x, rh.ray.dir_y = direction.y, rh.ray.dir_z = direction.z;
  rh.ray.tnear = 0;
  rh.ray.tfar = INFINITY;
  rh.ray.mask = ~0u;  // Debian's Embree is built with ray masks: 0 would hit nothing
  rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace

int main() {
  // A closed vase, listed from the axis at the bottom up the outside and back to the axis at the
  // top, so that its normals point outwards. A Profile validates the points (ProfileError names
  // the offending point otherwise); a Shape builds the MIBIT tree over it.
  const std::vector<revolve::Point2> points{{0, 0},     {0.5, 0},    {0.55, 0.1}, {0.8, 0.6},
                                            {0.7, 1.2}, {0.35, 1.6}, {0.4, 1.8},  {0, 1.8}};
  const revolve::Shape vase{revolve::Profile(points)};

  RTCDevice device = rtcNewDevice(nullptr);
  int failures = 0;
  {
    // The Geometry registers the shape with Embree. Keep both it and the Shape alive while any
    // scene holding it is traced: Embree calls back into them.
    revolve::Geometry geometry(device, vase);
    RTCScene object = rtcNewScene(device);
    rtcAttachGeometry(object, geometry.handle());
    rtcCommitScene(object);

    // Two instances of the vase (Debian's Embree allows one level of instancing).
    const Placement placements[2] = {{1.0f, -1.5f, 0, 0}, {0.5f, 1.5f, 0, 0}};
    RTCScene world = rtcNewScene(device);
    for (const Placement& placement : placements) {
      RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(instance, object);
      placement.apply(instance);
      rtcCommitGeometry(instance);
      rtcAttachGeometry(world, instance);  // ids 0 and 1, in this order
      rtcReleaseGeometry(instance);
    }
    rtcCommitScene(world);

    // Rays from the front (y = -5) at each vase's height 0.6, and one between them.
    const revolve::Vec3 direction{0, 1, 0};
    for (const float x : {-1.5f, -1.0f, 0.0f, 1.5f}) {
      RTCRayHit rh = rayHit({x, -5, 0.6f}, direction);
#if RTC_VERSION_MAJOR >= 4
      rtcIntersect1(world, &rh);
#else  // Embree 3 takes an intersect context
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      rtcIntersect1(world, &context, &rh);
#endif
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        std::printf("x = %5.2f: no hit\n", x);
        continue;
      }
      // instID[0] is the instance's id in `world`; geomID the geometry's in `object`; primID the
      // profile segment hit; u = phi / 2 pi; v = arc length along the profile, from 0 to 1; Ng is
      // in the vase's own space (Embree does not transform it): scale by the inverse transpose of
      // the instance's transform for world space (here a uniform scale: the direction is unchanged).
      const unsigned id = rh.hit.instID[0];
      const float length = std::sqrt(rh.hit.Ng_x * rh.hit.Ng_x + rh.hit.Ng_y * rh.hit.Ng_y + rh.hit.Ng_z * rh.hit.Ng_z);
      std::printf("x = %5.2f: instance %u, t = %.6f, segment %u, u = %.4f, v = %.4f, normal (%.3f, %.3f, %.3f)\n", x,
                  id, rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v, rh.hit.Ng_x / length, rh.hit.Ng_y / length,
                  rh.hit.Ng_z / length);

      // The same ray in the vase's space, asked of revolve directly: the same segment, and the
      // same distance once scaled back (the local ray keeps the world direction's length, so its t
      // is the world t divided by the scale).
      const Placement& p = placements[id];
      const revolve::Ray local{{(x - p.x) / p.scale, (-5 - p.y) / p.scale, (0.6f - p.z) / p.scale}, direction};
      const std::optional<revolve::Hit> hit = revolve::intersect(vase, local);
      if (!hit || hit->segment != rh.hit.primID || std::abs(hit->t * p.scale - rh.ray.tfar) > 1e-5f * rh.ray.tfar) {
        std::fprintf(stderr, "x = %.2f: Embree and revolve::intersect disagree\n", x);
        ++failures;
      }
    }
    rtcReleaseScene(world);
    rtcReleaseScene(object);
  }  // the Geometry goes before the device it was made on
  rtcReleaseDevice(device);
  return failures == 0 ? 0 : 1;
}
