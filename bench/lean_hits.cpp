// revolve-lean-hits: what a hit's attributes cost. One shape behind four revolve::Geometry objects,
// one per choice of Geometry::Options::normal and ::uv, each timed on the benchmark's incoherent
// rays (rtcIntersect1) and its camera's packets (rtcIntersect8), the cost of asking
// revolve::surfaceAttributes afterwards for every hit a lean geometry found, and rtcOccluded1 on the
// same incoherent rays.
//
//   revolve-lean-hits SHAPE POINTS|spline REPETITIONS
//
// SHAPE: sphere torus vase goblet bottle; POINTS: the polyline's profile points (MIBIT), or
// "spline" for the shape's Bezier spline traced exactly. Prints one line per configuration:
// "SHAPE RAYS CONFIG ns/ray ratio": the median over the repetitions of thread CPU time a ray (every
// ray, hit or not), and the median over the repetitions of its ratio to "normal+uv" (the default). The
// configurations are interleaved: each repetition times every one once, so that a slow spell of
// the shared machine falls on all of them.
#include "cli/command_line.h"
#include "ray_batches.h"
#include "ray_sets.h"
#include "smooth_spline.h"
#include "test_shapes.h"

#include <revolve/revolve.h>
#include <CLI/CLI.hpp>
#include <optional>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace revolve;
using namespace revolve::bench;

double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

struct Choice {
  const char* name;
  bool normal, uv;
};
constexpr Choice kChoices[] = {
    {"normal+uv", true, true}, {"normal", true, false}, {"uv", false, true}, {"t-only", false, false}};

volatile float keep = 0.0f;  // the attributes asked for, kept so that the compiler computes them

// rtcIntersect1 on every ray of a lean geometry, then surfaceAttributes for each hit: the cost of
// asking afterwards, for a caller that needs the attributes of every hit after all.
std::function<std::size_t()> onDemandBatch(RTCScene scene, const Shape& shape, const std::vector<Ray>& rays) {
  auto next = std::make_shared<std::size_t>(0);
  return [scene, &shape, &rays, next]() {
    constexpr std::size_t kBatch = 1024;
    embree::RayQuery query;
    float sink = 0.0f;
    for (std::size_t j = 0; j < kBatch; ++j) {
      const Ray& ray = rays[*next];
      *next = (*next + 1) % rays.size();
      RTCRayHit rh{};
      rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
      rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
      rh.ray.tnear = ray.tnear, rh.ray.tfar = ray.tfar, rh.ray.mask = ~0u;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      query.intersect(scene, rh);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
      const std::optional<Hit> hit = surfaceAttributes(shape, ray, rh.hit.primID, rh.ray.tfar);
      if (hit) sink += hit->normal.x + hit->u;
    }
    keep = keep + sink;
    return kBatch;
  };
}

}  // namespace

int main(int argc, char** argv) {
  std::string shapeName, resolution;
  int repetitions = 0;
  CLI::App cli{"what a hit's attributes cost: each choice of Geometry::Options timed side by side"};
  cli.add_option("SHAPE", shapeName, "the test shape")
      ->required()
      ->check(CLI::IsMember({"sphere", "torus", "vase", "goblet", "bottle"}));
  cli.add_option("RESOLUTION", resolution, "the polyline's profile points (2 or more), or 'spline' for the exact curve")
      ->required()
      ->check(CLI::IsMember({"spline"}) | CLI::Range(2, 1 << 20));
  cli.add_option("REPETITIONS", repetitions, "timed repetitions (the median is reported)")
      ->required()
      ->check(CLI::Range(1, 1000));
  if (const std::optional<int> status = app::parseCommandLine(cli, argc, argv, "revolve-lean-hits")) return *status;
  const std::vector<SmoothProfile> shapes = testShapes();
  const auto profile =
      std::find_if(shapes.begin(), shapes.end(), [&](const SmoothProfile& s) { return s.name() == shapeName; });
  const int points = resolution == "spline" ? 0 : std::stoi(resolution);
  // The benchmark's own spline (revolve-bench: within 1e-9 of the size) or polyline.
  const Shape shape = resolution == "spline"
                          ? Shape(Spline(SplineKind::bezier, bezierOf(*profile, 1e-9 * profile->size()).bezier))
                          : Shape(Profile(profile->sample(points)));

  RTCDevice device = rtcNewDevice("threads=1");
  {
    const SmoothProfile::Extent e = profile->extent();
    const Box box{{-e.rMax, -e.rMax, e.zLow}, {e.rMax, e.rMax, e.zHigh}};
    const std::vector<Ray> incoherent = incoherentRays(box, 200000, 1), camera = cameraRays(box, 512, 512);
    const auto packets = packetsOf(camera);

    std::vector<std::unique_ptr<Geometry>> geometries;
    std::vector<RTCScene> scenes;
    for (const Choice& choice : kChoices) {
      Geometry::Options options;
      options.normal = choice.normal, options.uv = choice.uv;
      geometries.push_back(std::make_unique<Geometry>(device, shape, options));
      scenes.push_back(rtcNewScene(device));
      rtcAttachGeometry(scenes.back(), geometries.back()->handle());
      rtcCommitScene(scenes.back());
    }
    struct Config {
      std::string rays, name;
      std::function<std::size_t()> batch;
      std::size_t count;
    };
    std::vector<Config> configs;
    for (std::size_t c = 0; c < scenes.size(); ++c) {
      configs.push_back({"incoherent1", kChoices[c].name, singleRayBatch(scenes[c], incoherent), incoherent.size()});
    }
    configs.push_back({"incoherent1", "t-only+surfaceAttributes", onDemandBatch(scenes.back(), shape, incoherent),
                       incoherent.size()});
    // Shadow rays along the same rays, for scale: rtcOccluded1 computes no attributes and stops at
    // the first hit.
    configs.push_back({"incoherent1", "occluded", occludedBatch(scenes[0], incoherent), incoherent.size()});
    for (std::size_t c = 0; c < scenes.size(); ++c) {
      configs.push_back({"camera8", kChoices[c].name, packetBatch(scenes[c], packets), camera.size()});
    }

    std::vector<std::vector<double>> nanoseconds(configs.size());
    for (int r = 0; r < repetitions; ++r) {
      for (std::size_t i = 0; i < configs.size(); ++i) {
        const double start = threadSeconds();
        std::size_t traced = 0;
        while (traced < configs[i].count) traced += configs[i].batch();
        nanoseconds[i].push_back((threadSeconds() - start) / double(traced) * 1e9);
      }
    }
    // The ratio to today's default within each repetition (the same spell of the machine), then
    // its median; the base is the configuration of the same rays with every attribute.
    for (std::size_t i = 0; i < configs.size(); ++i) {
      std::size_t base = 0;
      while (configs[base].rays != configs[i].rays || configs[base].name != "normal+uv") ++base;
      std::vector<double> ratios;
      for (int r = 0; r < repetitions; ++r) ratios.push_back(nanoseconds[i][r] / nanoseconds[base][r]);
      std::sort(ratios.begin(), ratios.end());
      std::vector<double> v = nanoseconds[i];
      std::sort(v.begin(), v.end());
      std::printf("%s %s %s %.2f %.3f\n", shapeName.c_str(), configs[i].rays.c_str(), configs[i].name.c_str(),
                  v[v.size() / 2], ratios[ratios.size() / 2]);
    }
    for (RTCScene scene : scenes) rtcReleaseScene(scene);
  }
  rtcReleaseDevice(device);
  return 0;
}
