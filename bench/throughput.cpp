// Throughput of MIBIT against Wang's linear scan through Embree: rtcIntersect1, one thread,
// incoherent rays, a vase profile sampled at 16 to 16384 points; and MIBIT by shell kind. Both methods trace the same
// rays in the same run (Google Benchmark, repetitions randomly interleaved, medians reported),
// and each method's error is printed beside its speed: the largest meridian residual of its hit
// points (distance from the exact profile, in float ulps of the object's radius) and its hit count.
//
//   build/bin/revolve-bench-throughput [--rays N] [--benchmark_repetitions=9 ...]
#include <revolve/revolve.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <tuple>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace revolve;

std::size_t gRayCount = 16384;
const std::vector<int> kPointCounts = {16, 256, 1024, 4096, 16384};

// A closed vase: the foot on the axis, a smooth outer wall (bulge, neck, flared lip), the top on the axis.
std::vector<Point2> vase(int points) {
  std::vector<Point2> profile{{0.0, 0.0}};
  const int wall = points - 2;
  for (int i = 0; i < wall; ++i) {
    const double s = double(i) / (wall - 1);
    const double bulge = std::sin(std::numbers::pi * (0.1 + 0.8 * s));
    profile.push_back({0.25 + 0.25 * bulge * bulge - 0.15 * s + 0.1 * s * s * s * s, 1.5 * s});
  }
  profile.push_back({0.0, 1.5});
  return profile;
}

std::vector<Ray> incoherentRays(const Bounds& box, std::size_t count) {
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  const double c[3] = {0.5 * (box.lower.x + box.upper.x), 0.5 * (box.lower.y + box.upper.y), 0.5 * (box.lower.z + box.upper.z)};
  const double radius = 0.5 * std::hypot(box.upper.x - box.lower.x, box.upper.y - box.lower.y, box.upper.z - box.lower.z);
  std::vector<Ray> rays;
  for (std::size_t i = 0; i < count; ++i) {
    double u[3] = {normal(random), normal(random), normal(random)};
    const double n = std::hypot(u[0], u[1], u[2]);
    Vec3 origin{float(c[0] + 3 * radius * u[0] / n), float(c[1] + 3 * radius * u[1] / n), float(c[2] + 3 * radius * u[2] / n)};
    // Aim at uniform points of the box: about three quarters of the rays hit.
    Vec3 target{float(box.lower.x + unit(random) * (box.upper.x - box.lower.x)),
                float(box.lower.y + unit(random) * (box.upper.y - box.lower.y)),
                float(box.lower.z + unit(random) * (box.upper.z - box.lower.z))};
    rays.push_back({origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}});
  }
  return rays;
}

double meridianDistance(std::span<const Point2> profile, double x, double y, double z) {
  const double rho = std::hypot(x, y);
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const Point2 a = profile[k], b = profile[k + 1];
    const double er = b.r - a.r, ez = b.z - a.z;
    const double s = std::clamp(((rho - a.r) * er + (z - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
    best = std::min(best, std::hypot(rho - (a.r + s * er), z - (a.z + s * ez)));
  }
  return best;
}

struct Scene {
  RTCDevice device;
  std::unique_ptr<Shape> shape;
  std::unique_ptr<Geometry> geometry;
  RTCScene scene;
  std::vector<Ray> rays;
  double hits = 0;
  double maxResidualUlps = 0;  // in units of 2^-24 times the object's radius
};

RTCRayHit rayHit(const Ray& ray) {
  RTCRayHit rh{};
  rh.ray = {ray.origin.x, ray.origin.y, ray.origin.z, ray.tnear, ray.direction.x, ray.direction.y, ray.direction.z,
            0.0f, ray.tfar, ~0u, 0u, 0u};
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

Scene& sceneFor(const BuildOptions& options, int points) {
  static RTCDevice device = rtcNewDevice("threads=1");
  static std::map<std::tuple<int, int, int>, std::unique_ptr<Scene>> scenes;
  std::unique_ptr<Scene>& scene = scenes[{int(options.method), int(options.shell), points}];
  if (scene) return *scene;
  scene = std::make_unique<Scene>();
  scene->device = device;
  scene->shape = std::make_unique<Shape>(Profile(vase(points)), options);
  scene->geometry = std::make_unique<Geometry>(device, *scene->shape);
  scene->scene = rtcNewScene(device);
  rtcAttachGeometry(scene->scene, scene->geometry->handle());
  rtcCommitScene(scene->scene);
  scene->rays = incoherentRays(scene->shape->bounds(), gRayCount);
  // Error, measured once outside the timing: residual of every hit point against the exact profile.
  const double radius = scene->shape->bounds().upper.x;
  for (const Ray& ray : scene->rays) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = rayHit(ray);
    rtcIntersect1(scene->scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    scene->hits += 1;
    const double t = rh.ray.tfar;
    const double residual = meridianDistance(scene->shape->profile().points(), ray.origin.x + t * ray.direction.x,
                                             ray.origin.y + t * ray.direction.y, ray.origin.z + t * ray.direction.z);
    scene->maxResidualUlps = std::max(scene->maxResidualUlps, residual / (radius * 0x1p-24));
  }
  return *scene;
}

void traceRays(benchmark::State& state, const BuildOptions& options) {
  Scene& scene = sceneFor(options, int(state.range(0)));
  for (auto _ : state) {
    for (const Ray& ray : scene.rays) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rh = rayHit(ray);
      rtcIntersect1(scene.scene, &context, &rh);
      benchmark::DoNotOptimize(rh.hit.geomID);
    }
  }
  state.counters["Mrays/s"] = benchmark::Counter(double(scene.rays.size()) * double(state.iterations()) / 1e6,
                                                 benchmark::Counter::kIsRate);
  state.counters["hits"] = scene.hits;
  state.counters["residual_ulps"] = scene.maxResidualUlps;
}

// "mibit" is the default (cylinder shells); the paper's cone and hybrid shells are measured too.
void registerBenchmarks() {
  const std::pair<const char*, BuildOptions> runs[] = {
      {"mibit", {Method::mibit, ShellKind::cylinder}},
      {"linear", {Method::linear}},
      {"mibit_cone", {Method::mibit, ShellKind::cone}},
      {"mibit_hybrid", {Method::mibit, ShellKind::hybrid}},
  };
  for (const auto& [name, options] : runs) {
    auto* b = benchmark::RegisterBenchmark(name, [options = options](benchmark::State& state) { traceRays(state, options); });
    for (int points : kPointCounts) b->Arg(points);
    b->Unit(benchmark::kMillisecond)->MinTime(0.3);
  }
}

// Prints the usual report, then the medians side by side with their ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Aggregate || run.aggregate_name != "median") continue;
      const std::string name = run.run_name.function_name;
      const int points = std::stoi(run.run_name.args);
      medians_[{name, points}] = run;
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto value = [](const Run& run, const char* counter) { return double(run.counters.at(counter)); };
    std::printf("\nrtcIntersect1, 1 thread, %zu incoherent rays, medians:\n", gRayCount);
    std::printf("%8s | %12s %8s %9s | %12s %8s %9s | %8s | %10s\n", "points", "MIBIT Mray/s", "hits", "resid ulp",
                "linear Mray/s", "hits", "resid ulp", "speedup", "vs 16 pts");
    double base = 0;
    for (int points : kPointCounts) {
      const auto mibit = medians_.find({"mibit", points}), linear = medians_.find({"linear", points});
      if (mibit == medians_.end() || linear == medians_.end()) continue;
      const double m = value(mibit->second, "Mrays/s"), l = value(linear->second, "Mrays/s");
      if (points == kPointCounts.front()) base = m;
      std::printf("%8d | %12.2f %8.0f %9.2f | %12.3f %8.0f %9.2f | %7.1fx | %9.2f\n", points, m,
                  value(mibit->second, "hits"), value(mibit->second, "residual_ulps"), l, value(linear->second, "hits"),
                  value(linear->second, "residual_ulps"), m / l, base > 0 ? m / base : 0.0);
    }
    std::printf("\nMIBIT by shell kind (Mrays/s, medians; hits and residuals as above in every column):\n");
    std::printf("%8s | %9s %9s %9s\n", "points", "cylinder", "cone", "hybrid");
    for (int points : kPointCounts) {
      const auto cy = medians_.find({"mibit", points}), tc = medians_.find({"mibit_cone", points}),
                 hy = medians_.find({"mibit_hybrid", points});
      if (cy == medians_.end() || tc == medians_.end() || hy == medians_.end()) continue;
      std::printf("%8d | %9.2f %9.2f %9.2f\n", points, value(cy->second, "Mrays/s"), value(tc->second, "Mrays/s"),
                  value(hy->second, "Mrays/s"));
      if (value(tc->second, "hits") != value(cy->second, "hits") || value(hy->second, "hits") != value(cy->second, "hits")) {
        std::printf("         ! hit counts differ between shell kinds\n");
      }
    }
  }

 private:
  std::map<std::pair<std::string, int>, Run> medians_;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> args{argv[0]};
  std::string defaults[] = {"--benchmark_repetitions=5", "--benchmark_enable_random_interleaving=true",
                            "--benchmark_report_aggregates_only=true"};
  for (std::string& flag : defaults) args.push_back(flag.data());
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--rays") == 0 && i + 1 < argc) {
      gRayCount = std::stoul(argv[++i]);
    } else {
      args.push_back(argv[i]);  // later flags override the defaults above
    }
  }
  int count = int(args.size());
  benchmark::Initialize(&count, args.data());
  registerBenchmarks();
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
