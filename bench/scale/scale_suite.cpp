#include "scale/scale_suite.h"

#include "scale/scale_family.h"
#include "scale/scale_library.h"

#include "scene/camera.h"
#include "scene/embree_scene.h"
#include "shape/shape_impl.h"

#include <sys/resource.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace revolve::bench {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The process's peak and current resident memory, in bytes.
double peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024.0;  // Linux reports kilobytes
}
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * double(sysconf(_SC_PAGESIZE));
}

// A camera above one corner of the grid looking across it, and a lidar between four objects near
// the middle: the first sees far along rows of objects, the second hits its neighbours.
std::vector<Ray> cameraRays(const ScaleSettings& settings) {
  const double side = ScaleFamily::kSpacing * double(ScaleFamily::gridSide(settings.objects));
  io::SceneCamera camera;
  camera.from = {-0.05 * side - 2, -0.05 * side - 2, 0.25 * side + 2};
  camera.to = {0.5 * side, 0.5 * side, 0};
  camera.up = {0, 0, 1};
  camera.fovDegrees = 50;
  const scene::Camera pinhole(camera, settings.cameraWidth, settings.cameraHeight);
  std::vector<Ray> rays;
  rays.reserve(std::size_t(settings.cameraWidth) * std::size_t(settings.cameraHeight));
  for (int y = 0; y < settings.cameraHeight; ++y) {
    for (int x = 0; x < settings.cameraWidth; ++x) rays.push_back(pinhole.ray(float(x) + 0.5f, float(y) + 0.5f));
  }
  return rays;
}

std::vector<Ray> lidarRays(const ScaleSettings& settings) {
  const std::size_t middle = ScaleFamily::gridSide(settings.objects) / 2;
  const float centre = float(ScaleFamily::kSpacing * (double(middle) - 0.5));
  std::vector<Ray> rays;
  rays.reserve(std::size_t(settings.lidarAzimuths) * std::size_t(settings.lidarElevations));
  for (int e = 0; e < settings.lidarElevations; ++e) {
    const double elevation = (-15.0 + 30.0 * e / std::max(1, settings.lidarElevations - 1)) * std::numbers::pi / 180;
    for (int a = 0; a < settings.lidarAzimuths; ++a) {
      const double azimuth = 2 * std::numbers::pi * a / settings.lidarAzimuths;
      rays.push_back({{centre, centre, 0.5f},
                      {float(std::cos(elevation) * std::cos(azimuth)), float(std::cos(elevation) * std::sin(azimuth)),
                       float(std::sin(elevation))}});
    }
  }
  return rays;
}

struct Throughput {
  double medianMrays = 0;
  std::size_t hits = 0;
};

// Every ray's nearest hit (`hits(ray)`: whether there is one) on TBB's threads, `repetitions`
// times: the median rate.
template <typename Hits>
Throughput trace(const Hits& hits, const std::vector<Ray>& rays, int repetitions) {
  std::vector<double> rates;
  Throughput result;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = Clock::now();
    const std::size_t hitCount = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, rays.size(), 256), std::size_t{0},
        [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) count += hits(rays[i]);
          return count;
        },
        [](std::size_t a, std::size_t b) { return a + b; });
    rates.push_back(double(rays.size()) / secondsSince(start) * 1e-6);
    result.hits = hitCount;
  }
  std::sort(rates.begin(), rates.end());
  result.medianMrays = rates[rates.size() / 2];
  return result;
}

// Where one exact shape's bytes go (Shape::memoryBytes, part by part).
nlohmann::ordered_json shapeBreakdown(const Shape& shape) {
  const detail::ShapeImpl& impl = detail::implOf(shape);
  const std::size_t points = impl.profile.points().size();
  nlohmann::ordered_json parts;
  parts["shape_struct"] = sizeof(detail::ShapeImpl);
  parts["profile_points"] = points * sizeof(Point2);
  parts["profile_arc_lengths"] = impl.profile.arcLength().size() * sizeof(double);
  parts["profile_source_indices"] = impl.profile.sourceIndex().identity() ? 0 : points * sizeof(std::size_t);
  parts["mibit_tree"] = impl.mibit.nodes.capacity() * sizeof(detail::MibitNode) +
                        impl.mibit.cones.capacity() * sizeof(detail::NodeCone) +
                        impl.mibit.intervals.capacity() * sizeof(detail::MonotoneInterval) +
                        impl.mibit.implicitShells.capacity() * sizeof(detail::ImplicitShell);
  parts["wide_tree"] = impl.wide.memoryBytes();
  // A spline shape's parts with the index of its pieces' first parts; its records of v; its curve.
  const detail::SplineData* curve = impl.curve.get();
  parts["curve_parts"] = impl.parts.capacity() * sizeof(detail::CurvePart) +
                         (curve ? curve->firstPartOfPiece.capacity() * sizeof(std::uint32_t) : 0);
  parts["arc_tables"] = curve ? curve->arcRecords.capacity() * sizeof(double) : 0;
  std::uint32_t mostSteps = 0;
  for (const detail::CurvePart& part : impl.parts) mostSteps = std::max<std::uint32_t>(mostSteps, part.arcSteps);
  parts["curve_part_count"] = impl.parts.size();
  parts["arc_steps_most"] = mostSteps;
  parts["spline"] = curve ? sizeof(detail::SplineData) + curve->spline.memoryBytes() : 0;
  parts["total"] = shape.memoryBytes();
  return parts;
}

// The memory, one shape of each kind and the throughput of a built scene, into `record`. `built`
// is an EmbreeScene or a LibraryScene; `shapeOf(i)` object i's Shape (for revolve's exact surfaces)
// and `hits(ray)` whether the ray hits anything.
template <typename Built, typename ShapeOf, typename Hits>
void measureBuilt(nlohmann::ordered_json& record, const ScaleSettings& settings, const Built& built,
                  const ShapeOf& shapeOf, const Hits& hits, const std::vector<Ray>& lidar) {
  nlohmann::ordered_json memory;
  memory["revolve_bytes"] = built.revolveBytes();
  memory["embree_bytes"] = built.embreeBytes();
  memory["embree_peak_bytes"] = built.embreePeakBytes();
  memory["record_bytes"] = built.recordBytes();
  memory["resident_bytes"] = residentBytes();
  memory["peak_resident_bytes"] = peakResidentBytes();
  const double counted = double(built.revolveBytes()) + double(built.embreeBytes()) + double(built.recordBytes());
  memory["counted_bytes_per_object"] = counted / double(settings.objects);
  record["memory"] = memory;
  if (!settings.mesh) {
    record["shape_bytes"] = {{"polyline", shapeBreakdown(shapeOf(0))}};
    if (settings.objects > 1) record["shape_bytes"]["spline"] = shapeBreakdown(shapeOf(1));
  }
  const std::vector<Ray> camera = cameraRays(settings);
  const Throughput cameraRate = trace(hits, camera, settings.repetitions);
  const Throughput lidarRate = trace(hits, lidar, settings.repetitions);
  record["camera"] = {{"rays", camera.size()}, {"hits", cameraRate.hits}, {"mrays_per_second", cameraRate.medianMrays}};
  record["lidar"] = {{"rays", lidar.size()}, {"hits", lidarRate.hits}, {"mrays_per_second", lidarRate.medianMrays}};
  record["repetitions"] = settings.repetitions;
}

// The family built by the library alone (scale_library.h): no description is made or held.
nlohmann::ordered_json runLibrary(const ScaleSettings& settings) {
  if (settings.mesh)
    throw std::runtime_error("--build library builds exact surfaces; --geometry mesh needs --build scene");
  if (!settings.sceneFile.empty()) throw std::runtime_error("--scene is read by the scene stack: --build scene");
  nlohmann::ordered_json record;
  record["objects"] = settings.objects;
  record["geometry"] = "revolve";
  record["build"] = "library";
  record["points_per_profile"] = ScaleFamily::kPoints;
  // Time to the first ray: the profiles and splines made and checked, their shapes, geometries
  // and Embree's tree (all in parallel but the attaching), and one ray.
  const auto start = Clock::now();
  const LibraryScene scene(ScaleFamily{.seed = settings.seed}, settings.objects);
  const std::vector<Ray> lidar = lidarRays(settings);
  (void)scene.hits(lidar.front());
  record["first_ray_seconds"] = secondsSince(start);
  record["build_seconds"] = scene.buildSeconds();
  measureBuilt(
      record, settings, scene, [&](std::size_t i) -> const Shape& { return scene.shape(i); },
      [&](const Ray& ray) { return scene.hits(ray); }, lidar);
  return record;
}

}  // namespace

nlohmann::ordered_json runScale(const ScaleSettings& given) {
  if (given.library) return runLibrary(given);
  ScaleSettings settings = given;
  const ScaleFamily family{.seed = settings.seed};
  nlohmann::ordered_json record;
  // From a file: its objects, read and timed first (the grid's rays assume the family's layout).
  std::optional<io::SceneDescription> fromFile;
  if (!settings.sceneFile.empty()) {
    if (settings.mesh)
      throw std::runtime_error("--scene builds the file's exact surfaces; --geometry mesh is for the family");
    const double residentBefore = residentBytes();
    const auto start = Clock::now();
    fromFile = io::readScene(settings.sceneFile);
    record["scene_file"] = settings.sceneFile;
    record["read_seconds"] = secondsSince(start);
    record["read_resident_bytes"] = residentBytes() - residentBefore;
    settings.objects = fromFile->objects.size();
    if (settings.objects == 0) throw std::runtime_error(settings.sceneFile + ": no objects to build");
  }
  record["objects"] = settings.objects;
  record["geometry"] = settings.mesh ? "mesh" : "revolve";
  record["build"] = "scene";
  record["points_per_profile"] = ScaleFamily::kPoints;

  // Meshes are matched to the error of a 64-point polyline against the smooth shape it samples:
  // polylines keep their points, splines are sampled within it, and the slices keep the polygon
  // within it of the circle at the family's largest radius (0.6).
  const double error = family.polylineError(std::min<std::size_t>(settings.objects, 1000));  // (the family's)
  const auto slices = std::uint32_t(std::ceil(std::numbers::pi / std::acos(1.0 - error / 0.6)));
  record["matched_error"] = error;
  if (settings.mesh) record["mesh_slices"] = slices;

  const double residentBefore = residentBytes();
  io::SceneDescription description =
      fromFile ? std::move(*fromFile)
               : familyDescription(family, settings.objects, FamilyScene{.mesh = settings.mesh, .tolerance = error});
  fromFile.reset();
  if (!record.contains("read_resident_bytes")) record["description_bytes"] = residentBytes() - residentBefore;

  // Time to the first ray: the build (shapes in parallel, Embree's geometries and tree) and one ray.
  const auto start = Clock::now();
  scene::BuildSettings build;
  build.mesh = settings.mesh;
  build.slices = slices;
  scene::EmbreeScene scene(description, build);
  const std::vector<Ray> lidar = lidarRays(settings);
  (void)scene.nearest(lidar.front());
  record["first_ray_seconds"] = secondsSince(start);
  record["build_seconds"] = scene.buildSeconds();
  description = io::SceneDescription{};  // the input is not the scene's memory

  measureBuilt(
      record, settings, scene, [&](std::size_t i) -> const Shape& { return *scene.shapeOf(std::uint32_t(i)); },
      [&](const Ray& ray) { return scene.nearest(ray).has_value(); }, lidar);
  record["refused_rays"] = scene.refusedRays();
  return record;
}

void printScale(std::FILE* out, const nlohmann::ordered_json& record) {
  const nlohmann::ordered_json& memory = record["memory"];
  if (record.contains("scene_file")) {
    std::fprintf(out, "%s: read %.2f s (resident %.1f MB more)\n", record["scene_file"].get<std::string>().c_str(),
                 record["read_seconds"].get<double>(), record["read_resident_bytes"].get<double>() * 1e-6);
  }
  std::fprintf(out,
               "%s (%s), %zu objects: build %.2f s, first ray %.2f s; memory %.0f bytes an object counted "
               "(revolve %.1f MB, Embree %.1f MB, records %.1f MB), peak resident %.1f MB; camera %.2f Mrays/s "
               "(%zu of %zu hit), lidar %.2f Mrays/s (%zu of %zu hit)\n",
               record["geometry"].get<std::string>().c_str(),
               record["build"] == "library" ? "the library alone" : "the scene stack",
               record["objects"].get<std::size_t>(), record["build_seconds"].get<double>(),
               record["first_ray_seconds"].get<double>(), memory["counted_bytes_per_object"].get<double>(),
               memory["revolve_bytes"].get<double>() * 1e-6, memory["embree_bytes"].get<double>() * 1e-6,
               memory["record_bytes"].get<double>() * 1e-6, memory["peak_resident_bytes"].get<double>() * 1e-6,
               record["camera"]["mrays_per_second"].get<double>(), record["camera"]["hits"].get<std::size_t>(),
               record["camera"]["rays"].get<std::size_t>(), record["lidar"]["mrays_per_second"].get<double>(),
               record["lidar"]["hits"].get<std::size_t>(), record["lidar"]["rays"].get<std::size_t>());
  if (record.contains("shape_bytes")) {
    for (const auto& [kind, parts] : record["shape_bytes"].items()) {
      std::fprintf(out, "  one %s shape:", kind.c_str());
      for (const auto& [part, bytes] : parts.items())
        std::fprintf(out, " %s %zu", part.c_str(), bytes.get<std::size_t>());
      std::fprintf(out, "\n");
    }
  }
}

}  // namespace revolve::bench
