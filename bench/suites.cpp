#include "suites.h"
#include <revolve/baselines.h>

#include "ray_batches.h"
#include "ray_sets.h"
#include "smooth_spline.h"
#include "test_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace revolve::bench {
namespace {

struct Ladders {
  std::vector<int> mibitPoints, baselinePoints, meshPoints, meshSlices;
  std::uint64_t maxTriangles;
  std::vector<int> roundSegments;  // Embree's round curve: Bézier segments
  std::vector<double> tolerances;  // adaptive polylines, relative to the size
  std::vector<int> uniformPoints;
};

std::vector<int> powersOfTwo(int from, int to) {
  std::vector<int> values;
  for (int v = from; v <= to; v *= 2) values.push_back(v);
  return values;
}

Ladders laddersFor(const RunSettings& settings) {
  if (settings.quick) {
    return {{16, 64, 256}, {16, 64}, {16, 64, 256}, {16, 64, 256}, 1u << 20, {4, 16, 64}, {1e-3, 1e-5}, {16, 256}};
  }
  // Meshes up to 2^23 triangles (a 2048 x 2048 grid): past that, building the grid's largest meshes
  // takes longer than the whole rest of the run. Round curves reach their single-precision floor by
  // 16 segments (cubic arcs: error ~ theta^6); up to 1,024 shows what more of them costs.
  return {powersOfTwo(16, 4096),
          powersOfTwo(16, 1024),
          powersOfTwo(16, 4096),
          powersOfTwo(8, 4096),
          1u << 23,
          powersOfTwo(4, 1024),
          {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7},
          powersOfTwo(16, 4096)};
}

double facetError(double rMax, int slices) { return rMax * (1.0 - std::cos(std::numbers::pi / slices)); }

Box boxOf(const SmoothProfile& profile) {
  const SmoothProfile::Extent e = profile.extent();
  return {{-e.rMax, -e.rMax, e.zLow}, {e.rMax, e.rMax, e.zHigh}};
}

// The floor primitive: the sphere shape's own sphere; on other shapes a sphere filling the box's
// narrower dimension (its error is then meaningless, its cost is what counts).
AnalyticSphere floorSphereFor(const SmoothProfile& profile) {
  const SmoothProfile::Extent e = profile.extent();
  const double radius = std::min(e.rMax, 0.5 * (e.zHigh - e.zLow));
  return {{0.0, 0.0, 0.5 * (e.zLow + e.zHigh)}, radius};
}

// The rays and the reference answers one shape is measured on.
struct RaySets {
  std::vector<Ray> incoherent, camera;
  std::shared_ptr<const std::vector<RTCRayHit8>> cameraPackets;
  std::vector<ReferenceHit> incoherentReference, cameraReference;
};

std::size_t grazingCount(const std::vector<ReferenceHit>& hits) {
  std::size_t count = 0;
  for (const ReferenceHit& hit : hits) count += hit.grazing;
  return count;
}

class ShapeBench {
 public:
  ShapeBench(RTCDevice device, const MemoryMonitor& monitor, const SmoothProfile& profile, const RunSettings& settings,
             bool withCamera)
      : device_(device),
        monitor_(monitor),
        profile_(profile),
        smoothSpline_(bezierOf(profile, kSplineError * profile.size())),
        spline_(SplineKind::bezier, smoothSpline_.bezier),
        tracer_(profile),
        sphere_(floorSphereFor(profile)) {
    result_.name = profile.name();
    result_.size = profile.size();
    result_.splineError = smoothSpline_.error / profile.size();
    result_.splinePieces = spline_.pieceCount();
    const Box box = boxOf(profile);
    rays_.incoherent = incoherentRays(box, settings.incoherentRays, settings.seed);
    rays_.incoherentReference = referenceHits(tracer_, rays_.incoherent);
    result_.incoherentRays = rays_.incoherent.size();
    result_.incoherentGrazing = grazingCount(rays_.incoherentReference);
    if (withCamera) {
      rays_.camera = cameraRays(box, settings.cameraWidth, settings.cameraHeight);
      rays_.cameraPackets = packetsOf(rays_.camera);
      rays_.cameraReference = referenceHits(tracer_, rays_.camera);
      result_.cameraRays = rays_.camera.size();
      result_.cameraGrazing = grazingCount(rays_.cameraReference);
    }
  }

  // Builds the method, measures its errors now and queues its timing in `modes`.
  // A configuration the method cannot trace is recorded with the reason, and neither built nor timed.
  void add(const MethodConfig& config, const std::vector<const char*>& modes, Timer& timer) {
    if (std::optional<std::string> limitation = limitationOf(profile_, config)) {
      ConfigResult refused;
      refused.config = config;
      refused.limitation = std::move(*limitation);
      result_.configs.push_back(std::move(refused));
      return;
    }
    scenes_.push_back(std::make_unique<TracedScene>(device_, monitor_, profile_, spline_, config, sphere_));
    const TracedScene& scene = *scenes_.back();
    ConfigResult result;
    result.config = config;
    result.config.points = scene.points();
    result.buildSeconds = scene.buildSeconds();
    result.revolveBytes = scene.revolveBytes();
    result.embreeBytes = scene.embreeBytes();
    result.triangles = scene.triangles();
    const bool meaningful = config.kind != MethodKind::sphere || profile_.name() == "sphere";
    if (meaningful) {
      const bool oriented = config.orientedNormals();
      result.incoherent =
          measureErrors(scene.scene(), rays_.incoherent, rays_.incoherentReference, tracer_, result_.size, oriented);
      if (!rays_.camera.empty()) {
        result.camera =
            measureErrors(scene.scene(), rays_.camera, rays_.cameraReference, tracer_, result_.size, oriented);
      }
    }
    const std::size_t index = result_.configs.size();
    result_.configs.push_back(result);
    for (const char* mode : modes) {
      timed_.push_back({index, mode});
      const std::string name = profile_.name() + " " + config.label() + " " + mode;
      const std::string m = mode;
      if (m == kIncoherent1)
        timer.add(name, singleRayBatch(scene.scene(), rays_.incoherent));
      else if (m == kCamera1)
        timer.add(name, singleRayBatch(scene.scene(), rays_.camera));
      else if (m == kCamera8)
        timer.add(name, packetBatch(scene.scene(), rays_.cameraPackets));
      else if (m == kIncoherentAll)
        timer.add(name, threadedBatch(scene.scene(), rays_.incoherent), true);
      else if (m == kOccluded1)
        timer.add(name, occludedBatch(scene.scene(), rays_.incoherent));
      else if (m == kOccluded8)
        timer.add(name, occludedPacketBatch(scene.scene(), rays_.cameraPackets));
      else
        throw std::logic_error("unknown timing mode " + m);
    }
  }

  const Spline& spline() const { return spline_; }

  ShapeResult finish(Timer& timer) {
    std::fprintf(stderr, "  timing %zu jobs\n", timed_.size());
    const std::vector<Throughput> speeds = timer.run();
    for (std::size_t i = 0; i < timed_.size(); ++i)
      result_.configs[timed_[i].first].speed[timed_[i].second] = speeds[i];
    scenes_.clear();
    return std::move(result_);
  }

 private:
  // The spline's own distance from the lines and arcs, relative to the size: far below what any
  // method here resolves (float hit points carry ~6e-8 of it).
  static constexpr double kSplineError = 1e-9;

  RTCDevice device_;
  const MemoryMonitor& monitor_;
  const SmoothProfile& profile_;
  SmoothSpline smoothSpline_;
  Spline spline_;
  ReferenceTracer tracer_;
  AnalyticSphere sphere_;
  RaySets rays_;
  ShapeResult result_;
  std::vector<std::unique_ptr<TracedScene>> scenes_;
  std::vector<std::pair<std::size_t, std::string>> timed_;
};

}  // namespace

std::vector<ShapeResult> runSpeedError(RTCDevice device, const RunSettings& settings,
                                       const std::vector<std::string>& only) {
  const MemoryMonitor monitor(device);
  const Ladders ladders = laddersFor(settings);
  const std::vector<const char*> allModes(std::begin(kModes), std::end(kModes));
  const std::vector<const char*> incoherentOnly = {kIncoherent1};
  std::vector<ShapeResult> results;
  for (const SmoothProfile& profile : testShapes()) {
    if (!only.empty() && std::find(only.begin(), only.end(), profile.name()) == only.end()) continue;
    std::fprintf(stderr, "speed-error: %s: reference hits\n", profile.name().c_str());
    Timer timer(settings.repetitions, settings.minSeconds);
    ShapeBench bench(device, monitor, profile, settings, true);
    std::fprintf(stderr, "  building and measuring errors\n");
    bench.add({.kind = MethodKind::sphere}, allModes, timer);
    for (int n : ladders.mibitPoints) {
      bench.add({.kind = MethodKind::mibit, .shell = ShellKind::cylinder, .points = n}, allModes, timer);
      bench.add({.kind = MethodKind::mibit, .shell = ShellKind::cylinder, .points = n, .binary = true}, incoherentOnly,
                timer);
      bench.add({.kind = MethodKind::mibit, .shell = ShellKind::cone, .points = n}, incoherentOnly, timer);
      bench.add({.kind = MethodKind::mibit, .shell = ShellKind::hybrid, .points = n}, incoherentOnly, timer);
    }
    for (int n : ladders.baselinePoints) {
      bench.add({.kind = MethodKind::linear, .shell = ShellKind::cylinder, .points = n}, incoherentOnly, timer);
      bench.add({.kind = MethodKind::kajiya, .shell = ShellKind::cylinder, .points = n}, incoherentOnly, timer);
    }
    // Embree's own curves: the cone curve on MIBIT's very polylines, the round curve fitted anew.
    for (int n : ladders.mibitPoints)
      bench.add({.kind = MethodKind::embreeCone, .shell = ShellKind::cylinder, .points = n}, allModes, timer);
    for (int n : ladders.roundSegments)
      bench.add({.kind = MethodKind::embreeRoundCurve, .shell = ShellKind::cylinder, .points = n}, allModes, timer);
    // Meshes whose two errors (the profile's chords, the slices' facets) are within a factor of 16
    // of each other: a mesh far off that balance is beaten by one with fewer triangles.
    for (int n : ladders.meshPoints) {
      for (int k : ladders.meshSlices) {
        const double chord = profile.sampleError(n), facet = facetError(profile.rMax(), k);
        const std::uint64_t triangles = 2ull * std::uint64_t(n - 1) * std::uint64_t(k);
        if (triangles > ladders.maxTriangles || std::max(chord, facet) > 16.0 * std::min(chord, facet)) continue;
        bench.add({.kind = MethodKind::mesh, .shell = ShellKind::cylinder, .points = n, .slices = k}, allModes, timer);
      }
    }
    // The curves: the spline exactly, its adaptive polylines (and their meshes, slices balancing the
    // tolerance), and polylines of evenly spaced points.
    const std::vector<const char*> curveModes = {kIncoherent1, kCamera8};
    bench.add({.kind = MethodKind::spline}, allModes, timer);
    for (double tolerance : ladders.tolerances) {
      bench.add({.kind = MethodKind::adaptive, .shell = ShellKind::cylinder, .tolerance = tolerance}, curveModes,
                timer);
      int k = 8;
      while (k < 4096 && facetError(profile.rMax(), k) > tolerance * profile.size()) k *= 2;
      const Profile polyline = Profile::fromCurve(bench.spline(), tolerance * profile.size());
      if (2ull * polyline.segmentCount() * std::uint64_t(k) <= ladders.maxTriangles) {
        bench.add({.kind = MethodKind::adaptiveMesh, .shell = ShellKind::cylinder, .slices = k, .tolerance = tolerance},
                  curveModes, timer);
      }
    }
    for (int n : ladders.uniformPoints) {
      if (n > int(profile.pieces().size()))
        bench.add({.kind = MethodKind::uniform, .shell = ShellKind::cylinder, .points = n}, {kIncoherent1}, timer);
    }
    ShapeResult result = bench.finish(timer);
    matchErrorLevels(result, kErrorLevels);
    comparePolylinePoints(result, profile);
    results.push_back(std::move(result));
  }
  return results;
}

std::vector<ShapeResult> runScaling(RTCDevice device, const RunSettings& settings) {
  const MemoryMonitor monitor(device);
  const SmoothProfile profile = vaseShape();
  const std::vector<int> points = settings.quick ? std::vector<int>{16, 256, 4096} : powersOfTwo(16, 32768);
  // Each ray meets every round-curve segment in its height range (their boxes span the body's
  // width) at some microseconds each: past 4,096 segments (256 in a quick run) its error
  // measurement alone would outlast the rest of the run.
  const int roundCurveMax = settings.quick ? 256 : 4096;
  const std::vector<const char*> modes = {kIncoherent1};
  std::fprintf(stderr, "scaling: %s: reference hits\n", profile.name().c_str());
  Timer timer(settings.repetitions, settings.minSeconds);
  ShapeBench bench(device, monitor, profile, settings, false);
  std::fprintf(stderr, "  building and measuring errors\n");
  for (int n : points) {
    bench.add({.kind = MethodKind::mibit, .shell = ShellKind::cylinder, .points = n}, modes, timer);
    bench.add({.kind = MethodKind::mibit, .shell = ShellKind::cylinder, .points = n, .binary = true}, modes, timer);
    bench.add({.kind = MethodKind::linear, .shell = ShellKind::cylinder, .points = n}, modes, timer);
    bench.add({.kind = MethodKind::kajiya, .shell = ShellKind::cylinder, .points = n}, modes, timer);
    bench.add({.kind = MethodKind::embreeCone, .shell = ShellKind::cylinder, .points = n}, modes, timer);
    if (n <= roundCurveMax)
      bench.add({.kind = MethodKind::embreeRoundCurve, .shell = ShellKind::cylinder, .points = n}, modes, timer);
    // The mesh of the same profile with just enough slices that its facets are no coarser than its
    // chords (at most 4096 slices and 2^24 triangles).
    int k = 8;
    while (k < 4096 && facetError(profile.rMax(), k) > profile.sampleError(n)) k *= 2;
    if (2ull * std::uint64_t(n - 1) * std::uint64_t(k) <= (1ull << 24)) {
      bench.add({.kind = MethodKind::mesh, .shell = ShellKind::cylinder, .points = n, .slices = k}, modes, timer);
    }
  }
  return {bench.finish(timer)};
}

void comparePolylinePoints(ShapeResult& shape, const SmoothProfile& profile) {
  // Each reference polyline's closed-form max error, then the fewest points each other sampling
  // needs to be within it: the adaptive polyline of the spline (its tolerance less the spline's own
  // distance from the profile), and even spacing (the smallest count whose closed-form error fits).
  const SmoothSpline smooth = bezierOf(profile, 1e-9 * profile.size());
  const Spline spline(SplineKind::bezier, smooth.bezier);
  for (const int n : {32, 64, 128, 256, 512, 1024, 2048, 4096}) {
    if (n <= int(profile.pieces().size())) continue;
    PointsRow row;
    row.samplePoints = n;
    row.error = profile.sampleError(n) / profile.size();
    if (!(row.error > 0.0)) continue;  // no arcs: nothing to compare
    row.adaptivePoints = int(Profile::fromCurve(spline, profile.sampleError(n) - smooth.error).points().size());
    int low = int(profile.pieces().size()) + 1, high = 1 << 22;  // `high` is within the error
    while (low < high) {                                         // the uniform error falls as points are added
      const int middle = low + (high - low) / 2;
      if (profile.uniformError(middle) <= profile.sampleError(n)) {
        high = middle;
      } else {
        low = middle + 1;
      }
    }
    row.uniformPoints = low;
    shape.points.push_back(row);
  }
}

void matchErrorLevels(ShapeResult& shape, const std::vector<double>& levels) {
  for (const char* mode : kModes) {
    // Camera rays' errors for the modes that trace them (occluded_8 shadows along the camera rays).
    const bool camera = std::string(mode).rfind("camera", 0) == 0 || std::string(mode) == kOccluded8;
    for (double level : levels) {
      MatchedRow row{shape.name, mode, level, {}, {}, {}, {}, {}, {}};
      for (std::size_t i = 0; i < shape.configs.size(); ++i) {
        const ConfigResult& c = shape.configs[i];
        const std::optional<ErrorSummary>& error = camera ? c.camera : c.incoherent;
        const auto speed = c.speed.find(mode);
        if (!error || speed == c.speed.end() || error->hits == 0 || !(error->residualMax <= level)) continue;
        const bool mibit =
            c.config.kind == MethodKind::mibit && c.config.shell == ShellKind::cylinder && !c.config.binary;
        const bool mesh = c.config.kind == MethodKind::mesh;
        const auto keepFastest = [&](std::optional<std::size_t>& fastest) {
          if (!fastest || speed->second.median > shape.configs[*fastest].speed.at(mode).median) fastest = i;
        };
        if (c.config.kind == MethodKind::embreeCone) keepFastest(row.embreeCone);
        if (c.config.kind == MethodKind::embreeRoundCurve) keepFastest(row.embreeRoundCurve);
        if (!mibit && !mesh) continue;
        std::optional<std::size_t>& fastest = mibit ? row.mibit : row.mesh;
        std::optional<std::size_t>& leanest = mibit ? row.leanestMibit : row.leanestMesh;
        if (!fastest || speed->second.median > shape.configs[*fastest].speed.at(mode).median) fastest = i;
        if (!leanest || c.totalBytes() < shape.configs[*leanest].totalBytes()) leanest = i;
      }
      shape.matched.push_back(row);
    }
  }
}

}  // namespace revolve::bench
