// revolve-kernel-timing: MIBIT's cost a ray at given profile resolutions on the benchmark's test
// shapes, against the one-quadratic user primitive, in CPU time of this thread.
//
//   revolve-kernel-timing SHAPE POINTS,POINTS,... incoherent|camera8|camera16|shadow REPETITIONS [--isas LIST]
//                         [--spline]
//
// Prints one line per configuration: "SHAPE CONFIG ns/ray" (the median over the repetitions, each a
// pass over the rays). --isas (e.g. avx2,avx512) times revolve's copy for each instruction set in
// the same process, interleaved (CONFIG then ends in @ISA); Embree's device keeps its default. Thread CPU time, not
// wall time: on a shared machine a process that waits for a core is not charged for the wait, so two builds timed
// alternately compare fairly (scripts/compare-kernels.sh). It uses only the benchmark library's rays, shapes and
// scenes, which every revision of the benchmark has had, so it compiles against older builds too.
// --spline times, beside each polyline, the centripetal Catmull-Rom spline through the same points
// traced exactly (its curve parts solved at the leaves): the scale benchmark's spline objects.
#include "ray_batches.h"
#include "ray_sets.h"
#include "test_shapes.h"
#include "traced_scene.h"

#include <revolve/revolve.h>  // Embree 3 or 4, whichever the revision was built with
#include "shape/query_kernels.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <ctime>
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

}  // namespace

int main(int argc, char** argv) {
  std::string shapeName, mode;
  std::vector<int> points;
  int repetitions = 0;
  CLI::App cli{"MIBIT's cost a ray for each instruction-set copy, against the one-quadratic primitive"};
  cli.add_option("SHAPE", shapeName, "the test shape")
      ->required()
      ->check(CLI::IsMember({"sphere", "torus", "vase", "goblet", "bottle"}));
  std::string pointList;
  cli.add_option("POINTS", pointList, "profile resolutions, comma-separated (2 to 2^20 points each)")->required();
  cli.add_option("MODE", mode, "the rays")
      ->required()
      ->check(CLI::IsMember({"incoherent", "camera8", "camera16", "shadow"}));
  std::vector<std::string> isaNames;
  cli.add_option("--isas", isaNames, "revolve's copies to time, side by side (default avx2,avx512)")
      ->delimiter(',')
      ->check(CLI::IsMember({"sse2", "avx2", "avx512"}));
  bool splines = false;
  cli.add_flag("--spline", splines,
               "also time the catmull-rom spline through each resolution's points, traced exactly (spline@ISA)");
  cli.add_option("REPETITIONS", repetitions, "timed repetitions (the median is reported)")
      ->required()
      ->check(CLI::Range(1, 1000));
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return cli.exit(error) == 0 ? 0 : 2;  // --help is no error; a bad argument exits 2, as the other tools do
  }
  for (std::size_t at = 0; at <= pointList.size();) {
    const std::size_t end = std::min(pointList.find(',', at), pointList.size());
    int count = 0;
    const auto [stop, error] = std::from_chars(pointList.data() + at, pointList.data() + end, count);
    if (error != std::errc{} || stop != pointList.data() + end || count < 2 || count > (1 << 20)) {
      std::fprintf(stderr, "POINTS: '%s' in '%s' must be a whole number of points from 2 to 2^20\n",
                   pointList.substr(at, end - at).c_str(), pointList.c_str());
      return 2;
    }
    points.push_back(count);
    at = end + 1;
  }
  const std::vector<SmoothProfile> shapes = testShapes();
  const auto shape =
      std::find_if(shapes.begin(), shapes.end(), [&](const SmoothProfile& s) { return s.name() == shapeName; });
  if (shape == shapes.end()) {
    std::fprintf(stderr, "%s: no test shape '%s' in this revision\n", argv[0], shapeName.c_str());
    return 2;
  }

  RTCDevice device = rtcNewDevice("threads=1");
  {
    const MemoryMonitor monitor(device);
    const SmoothProfile::Extent e = shape->extent();
    const Box box{{-e.rMax, -e.rMax, e.zLow}, {e.rMax, e.rMax, e.zHigh}};
    // The benchmark's own rays: 200,000 incoherent ones (seed 1) or its 512 x 512 camera.
    const bool camera = mode == "camera8" || mode == "camera16";
    const std::vector<Ray> rays = camera ? cameraRays(box, 512, 512) : incoherentRays(box, 200000, 1);
    const auto packets = packetsOf(rays);
    const auto packets16 = packets16Of(rays);
    const AnalyticSphere sphere{{0.0, 0.0, 0.5 * (e.zLow + e.zHigh)}, std::min(e.rMax, 0.5 * (e.zHigh - e.zLow))};

    std::vector<std::pair<std::string, std::unique_ptr<TracedScene>>> scenes;
    scenes.emplace_back(
        "sphere_primitive",
        std::make_unique<TracedScene>(device, monitor, *shape, MethodConfig{.kind = MethodKind::sphere}, sphere));
    if (isaNames.empty()) isaNames = {"avx2", "avx512"};
    for (const std::string& isa : isaNames) {
      // A geometry takes the callbacks of the copy chosen when it is made.
      const detail::Isa chosen = isa == "sse2"   ? detail::Isa::sse2
                                 : isa == "avx2" ? detail::Isa::avx2
                                                 : detail::Isa::avx512;
      if (!detail::cpuRuns(chosen)) {
        std::fprintf(stderr, "--isas: this CPU does not run %s\n", isa.c_str());
        return 2;
      }
      detail::limitIsa(chosen);
      for (int n : points) {
        MethodConfig config;
        config.kind = MethodKind::mibit;
        config.points = n;
        scenes.emplace_back("mibit_" + std::to_string(n) + "@" + isa,
                            std::make_unique<TracedScene>(device, monitor, *shape, config, sphere));
        if (splines) {
          const Spline curve(SplineKind::catmullRom, shape->sample(n));
          scenes.emplace_back("spline_" + std::to_string(n) + "@" + isa,
                              std::make_unique<TracedScene>(device, monitor, *shape, curve,
                                                            MethodConfig{.kind = MethodKind::spline}, sphere));
        }
      }
    }
    detail::limitIsa(detail::Isa::avx512);
    // Interleaved: each repetition times every configuration once, so that a slow spell of the
    // machine falls on all of them.
    std::vector<std::vector<double>> nanoseconds(scenes.size());
    for (int r = 0; r < repetitions; ++r) {
      for (std::size_t i = 0; i < scenes.size(); ++i) {
        RTCScene scene = scenes[i].second->scene();
        auto batch = mode == "camera8"    ? packetBatch(scene, packets)
                     : mode == "camera16" ? packet16Batch(scene, packets16)
                     : mode == "shadow"   ? occludedBatch(scene, rays)
                                          : singleRayBatch(scene, rays);
        const double start = threadSeconds();
        std::size_t traced = 0;
        while (traced < rays.size()) traced += batch();
        nanoseconds[i].push_back((threadSeconds() - start) / double(traced) * 1e9);
      }
    }
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      std::vector<double>& v = nanoseconds[i];
      std::sort(v.begin(), v.end());
      std::printf("%s %s %.2f\n", shapeName.c_str(), scenes[i].first.c_str(), v[v.size() / 2]);
    }
  }
  rtcReleaseDevice(device);
  return 0;
}
