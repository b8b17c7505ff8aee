// Fuzz target: a rays CSV as revolve-trace reads it.
// Expected: InputError with a one-line message, or rays that keep the reader's promises: every
// value finite except tfar (which may be +inf), a non-zero direction, 0 <= tnear <= tfar, origin
// and direction within +-2^60; the rays, written back as shortest round-trip text, read back bit
// for bit; and every ray traced through Embree as revolve-trace traces it (rtcIntersect1 on a scene
// holding a revolve Geometry), where Embree aborts the process on a ray beyond its contract.
#include "embree/embree_handles.h"
#include "embree/embree_rays.h"
#include "fuzz_checks.h"
#include "geometry/ray_limits.h"
#include "io/text_files.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

using namespace revolve;

namespace {

std::array<float, 8> fieldsOf(const Ray& ray) {
  return {ray.origin.x,    ray.origin.y,    ray.origin.z, ray.direction.x,
          ray.direction.y, ray.direction.z, ray.tnear,    ray.tfar};
}

std::string toCsv(const std::vector<Ray>& rays) {
  std::string text;
  for (const Ray& ray : rays) {
    const std::array<float, 8> fields = fieldsOf(ray);
    for (std::size_t i = 0; i < fields.size(); ++i) {
      char buffer[32];
      text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, fields[i]).ptr);
      text += i + 1 < fields.size() ? ',' : '\n';
    }
  }
  return text;
}

// A capped cylinder of radius 1 from z = 0 to 1 in a scene of its own, built once.
RTCScene tracedScene() {
  static const app::Device device = app::newDevice();
  static const Shape shape{Profile(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}})};
  static const Geometry geometry(device.get(), shape);
  static const app::Scene scene = [] {
    app::Scene built = app::newScene(device.get());
    rtcAttachGeometry(built.get(), geometry.handle());
    rtcCommitScene(built.get());
    return built;
  }();
  return scene.get();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<Ray> rays;
  try {
    rays = io::parseRaysCsv(text, "fuzz.csv");
  } catch (const io::InputError& error) {
    fuzz::checkOneLineMessage(error.what());
    return 0;
  }
  for (const Ray& ray : rays) {
    const std::array<float, 8> fields = fieldsOf(ray);
    for (std::size_t i = 0; i < 7; ++i) FUZZ_CHECK(std::isfinite(fields[i]));
    FUZZ_CHECK(std::isfinite(ray.tfar) || ray.tfar == INFINITY);
    FUZZ_CHECK(ray.direction.x != 0.0f || ray.direction.y != 0.0f || ray.direction.z != 0.0f);
    FUZZ_CHECK(0.0f <= ray.tnear && ray.tnear <= ray.tfar);
    for (std::size_t i = 0; i < 6; ++i) FUZZ_CHECK(std::abs(double(fields[i])) <= Profile::kMaxCoordinate);
    FUZZ_CHECK(app::embreeAccepts(ray));
    revolve::embree::RayQuery query;
    RTCRayHit rayHit = app::embreeRayHit(ray);
    query.intersect(tracedScene(), rayHit);
    if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID)
      FUZZ_CHECK(rayHit.ray.tfar >= ray.tnear && rayHit.ray.tfar <= ray.tfar);
  }
  const std::vector<Ray> again = io::parseRaysCsv(toCsv(rays), "again.csv");
  FUZZ_CHECK(again.size() == rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::array<float, 8> a = fieldsOf(rays[i]), b = fieldsOf(again[i]);
    for (std::size_t k = 0; k < a.size(); ++k) {
      FUZZ_CHECK(std::bit_cast<std::uint32_t>(a[k]) == std::bit_cast<std::uint32_t>(b[k]));
    }
  }
  return 0;
}
