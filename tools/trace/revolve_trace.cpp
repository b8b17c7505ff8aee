// revolve-trace: the nearest hit of each ray of a file with a surface of revolution, traced through
// Embree (rtcIntersect1 on a scene holding the shape), written as CSV, and a summary line on stdout. An interface other
// tools depend on: its options and file formats are documented in README.md and kept exact.
#include "cli/command_line.h"
#include "cli/counted.h"
#include "embree/embree_handles.h"
#include "embree/embree_rays.h"
#include "embree/memory_check.h"
#include "geometry/ray_limits.h"
#include "io/curve_tolerance.h"
#include "io/text_files.h"

#include <revolve/embree_baselines.h>
#include <revolve/revolve.h>

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace revolve;

struct Options {
  std::string profile, rays, out;
  std::string method = "mibit", shell = "cylinder", spline = "linear";
  std::uint32_t subdivisions = 0;
  std::uint32_t slices = 64;
  std::optional<io::CurveTolerance> tolerance;  // none: the curve is traced exactly
};

// What is traced: the polyline, and the curve when it is traced exactly.
struct LoadedProfile {
  Profile polyline;
  std::optional<Spline> curve;
};

// The profile (or spline), with a ProfileError or warning pointed at the file line of the point
// concerned. A curve traced exactly keeps a polyline within 1e-5 of its size for --method mesh.
LoadedProfile loadProfile(const Options& options) {
  const std::string& path = options.profile;
  const io::ProfileFile file = io::readProfileCsv(path);
  const SplineKind kind = *splineKindNamed(options.spline);
  if (options.tolerance && kind == SplineKind::linear) {
    throw std::runtime_error(
        "--tolerance applies to a curved --spline (quadratic, bezier, catmull-rom or natural) only");
  }
  if (options.method == "kajiya" && kind != SplineKind::linear && !options.tolerance) {
    throw std::runtime_error(
        "--method kajiya: Kajiya's strip tree bounds polylines only, and a curved --spline is traced "
        "exactly; use --method mibit or linear, or --tolerance to trace the curve as a polyline");
  }
  try {
    if (kind == SplineKind::linear) {
      Profile profile(file.points);
      for (const ProfileWarning& warning : profile.warnings()) {
        std::fprintf(stderr, "%s:%zu: warning: %s\n", path.c_str(), file.lines[warning.index], warning.message.c_str());
      }
      return {std::move(profile), std::nullopt};
    }
    Spline spline(kind, file.points);
    double size = 0;
    for (const Point2& p : spline.bezier()) size = std::max({size, std::abs(p.r), std::abs(p.z)});
    // A tolerance the user gave is held to the scene file's rule (io/curve_tolerance.h).
    Profile polyline = options.tolerance ? io::curvePolyline(spline, options.tolerance->value)
                                         : Profile::fromCurve(spline, 1e-5 * size);
    if (options.tolerance) return {std::move(polyline), std::nullopt};
    return {std::move(polyline), std::move(spline)};
  } catch (const ProfileError& error) {
    const std::size_t line = error.index() < file.lines.size() ? file.lines[error.index()] : 0;
    throw io::InputError(path, line, error.what());
  } catch (const std::invalid_argument& error) {  // the tolerance, for this curve
    throw std::runtime_error(std::string("--tolerance: ") + error.what());
  }
}

Vec3 unit(float x, float y, float z) {
  const float length = std::sqrt(x * x + y * y + z * z);
  return length > 0.0f ? Vec3{x / length, y / length, z / length} : Vec3{0.0f, 0.0f, 0.0f};
}

// A mesh hit in the exact surface's conventions: u from the hit's azimuth, v from its projection
// on the profile segment its triangle belongs to.
Hit meshHit(const Profile& profile, std::uint32_t slices, const Ray& ray, const RTCRayHit& rayHit) {
  Hit hit;
  hit.t = rayHit.ray.tfar;
  hit.point = {ray.origin.x + hit.t * ray.direction.x, ray.origin.y + hit.t * ray.direction.y,
               ray.origin.z + hit.t * ray.direction.z};
  hit.normal = unit(rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z);
  hit.segment = rayHit.hit.primID / (2 * slices);
  const double u = std::atan2(double(hit.point.y), double(hit.point.x)) * (0.5 / std::numbers::pi);
  hit.u = float(u < 0.0 ? u + 1.0 : u);
  if (hit.u >= 1.0f) hit.u = 0.0f;
  const Point2 a = profile.points()[hit.segment], b = profile.points()[hit.segment + 1];
  const double rho = std::hypot(double(hit.point.x), double(hit.point.y));
  const double er = b.r - a.r, ez = b.z - a.z;
  const double along = std::clamp(((rho - a.r) * er + (hit.point.z - a.z) * ez) / (er * er + ez * ez), 0.0, 1.0);
  const std::span<const double> arc = profile.arcLength();
  hit.v = float((arc[hit.segment] + along * (arc[hit.segment + 1] - arc[hit.segment])) / arc.back());
  return hit;
}

Hit exactHit(const RTCRayHit& rayHit) {
  Hit hit{};
  hit.t = rayHit.ray.tfar;
  hit.normal = unit(rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z);
  hit.u = rayHit.hit.u;
  hit.v = rayHit.hit.v;
  hit.segment = rayHit.hit.primID;
  return hit;
}

std::vector<std::optional<Hit>> traceAll(RTCScene scene, const std::vector<Ray>& rays, const Profile& profile,
                                         bool mesh, std::uint32_t slices) {
  std::vector<std::optional<Hit>> hits(rays.size());
  tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
    const Ray& ray = rays[i];
    if (!app::embreeAccepts(ray)) return;  // unreachable: the reader keeps rays within +-2^60
    embree::RayQuery query;
    RTCRayHit rayHit = app::embreeRayHit(ray);
    query.intersect(scene, rayHit);
    if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
      hits[i] = mesh ? meshHit(profile, slices, ray, rayHit) : exactHit(rayHit);
    }
  });
  return hits;
}

BuildOptions buildOptions(const Options& options) {
  BuildOptions build;
  // --method mesh names no Method: the default stays, unused. The command line has checked both names.
  if (const std::optional<Method> method = methodNamed(options.method)) build.method = *method;
  build.shell = *shellKindNamed(options.shell);
  build.subdivisions = options.subdivisions;
  return build;
}

void run(const Options& options) {
  const LoadedProfile loaded = loadProfile(options);
  const Profile& profile = loaded.polyline;
  const std::vector<Ray> rays = io::readRaysCsv(options.rays);
  io::OutputSet outputs;
  outputs.addInput("the profile file (--profile)", options.profile);
  outputs.addInput("the rays file (--rays)", options.rays);
  outputs.add("--out", options.out);
  const app::Device device = app::newDevice();
  const app::Scene scene = app::newScene(device.get());
  const bool mesh = options.method == "mesh";
  std::optional<Shape> shape;
  std::optional<Geometry> geometry;
  if (mesh) {
    app::requireMemory(2.0 * double(profile.segmentCount()) * options.slices * app::kMeshBytesPerTriangle,
                       "--method mesh with " + std::to_string(options.slices) + " slices");
    RTCGeometry triangles = newTessellatedGeometry(device.get(), profile, options.slices);
    rtcAttachGeometry(scene.get(), triangles);
    rtcReleaseGeometry(triangles);
  } else {
    if (loaded.curve) {
      shape.emplace(*loaded.curve, buildOptions(options));
    } else {
      shape.emplace(profile, buildOptions(options));
    }
    geometry.emplace(device.get(), *shape);
    rtcAttachGeometry(scene.get(), geometry->handle());
  }
  rtcCommitScene(scene.get());
  if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
    throw std::runtime_error(options.profile + ": Embree failed to build the scene");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::optional<Hit>> hits = traceAll(scene.get(), rays, profile, mesh, options.slices);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  io::writeHitsCsv(outputs.stream(options.out), hits);
  outputs.commit();
  const std::size_t hitCount =
      std::size_t(std::count_if(hits.begin(), hits.end(), [](const auto& hit) { return hit.has_value(); }));
  // What was traced: the curve itself (its own points), or a polyline (of the file's points, of the
  // curve within --tolerance, or, for the mesh, of the curve within 1e-5 of its size).
  const std::string method = mesh ? "mesh, " + std::to_string(options.slices) + " slices" : options.method;
  std::string traced = app::counted(profile.points().size(), "profile point") + " (" + method + ")";
  if (!mesh && loaded.curve) {
    traced = "a " + std::string(splineKindName(loaded.curve->kind())) + " spline of " +
             app::counted(loaded.curve->points().size(), "point") + " (" + method + ", exactly)";
  } else if (options.spline != "linear") {
    traced = app::counted(profile.points().size(), "polyline point") + " (" + method + ")";
  }
  std::printf("revolve-trace: %s, %s; %s traced in %.3g s (%.3g Mrays/s, %s); wrote %s\n",
              app::counted(rays.size(), "ray").c_str(), app::counted(hitCount, "hit").c_str(), traced.c_str(), seconds,
              seconds > 0 ? double(rays.size()) / seconds * 1e-6 : 0.0,
              app::counted(std::size_t(tbb::info::default_concurrency()), "thread").c_str(), options.out.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Traces each ray of a CSV file against a surface of revolution through Embree and writes the "
      "nearest hit of each."};
  app.add_option("--profile", options.profile, "profile CSV: optional header r,z; one point r,z per line")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("--rays", options.rays, "rays CSV: optional header ox,oy,oz,dx,dy,dz,tnear,tfar; one ray per line")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("--out", options.out, "hits CSV to write: hit,t,nx,ny,nz,u,v per ray")
      ->required()
      ->check(app::kNonEmpty);
  app.add_option("--method", options.method, "intersection method")
      ->check(CLI::IsMember({"mibit", "linear", "kajiya", "mesh"}))
      ->capture_default_str();
  app.add_option("--shell", options.shell, "MIBIT bounding shells")
      ->check(CLI::IsMember({"cylinder", "cone", "hybrid"}))
      ->capture_default_str();
  app.add_option("--subdivisions", options.subdivisions, "MIBIT leaves per monotone interval (0: one segment per leaf)")
      ->check(app::wholeNumberIn<std::uint32_t>(0, UINT32_MAX))
      ->capture_default_str();
  app.add_option("--spline", options.spline,
                 "how the profile's points make a curve: linear (a polyline), quadratic (2n + 1 Bezier points), bezier "
                 "(3n + 1), catmull-rom or natural (through every point); curves are traced exactly")
      ->check(CLI::IsMember({"linear", "quadratic", "bezier", "catmull-rom", "natural"}))
      ->capture_default_str();
  app::addToleranceOption(
      app, options.tolerance, false,
      "trace a curved --spline as its polyline within this distance (Profile::fromCurve) instead of exactly");
  app.add_option("--slices", options.slices, "azimuthal steps of the tessellated mesh (--method mesh)")
      ->check(app::wholeNumberIn<std::uint32_t>(3, 1u << 24))
      ->capture_default_str();
  if (const std::optional<int> status = app::parseCommandLine(app, argc, argv, "revolve-trace")) return *status;
  return app::runTool("revolve-trace", options.profile, [&] { run(options); });
}
