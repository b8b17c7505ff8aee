#include "pov_compare.h"

#include "io/output_set.h"

#include "io/pov_scene.h"
#include "io/scene_file.h"
#include "povray.h"
#include "render/image_output.h"
#include "render/renderer.h"
#include "scene/embree_scene.h"
#include "smooth_spline.h"
#include "test_shapes.h"

#include <tbb/info.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace revolve::bench {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int allThreads(int requested) { return requested > 0 ? requested : tbb::info::default_concurrency(); }

// The scene as SDL in `directory`; refuses a scene that POV-Ray would render differently, since
// the comparison would then measure the approximation.
std::string exportForComparison(const io::SceneDescription& description, const std::string& directory,
                                const std::string& name, int depth, bool shadows) {
  const io::PovScene pov = io::povScene(description, {depth, shadows});
  if (!pov.warnings.empty()) {
    throw std::runtime_error(description.file + ": POV-Ray cannot render this scene as revolve does (" +
                             pov.warnings.front() +
                             "); compare a scene of point lights, a uniform environment and diffuse, mirror and glass "
                             "materials, such as scenes/patio_points.json");
  }
  std::filesystem::create_directories(directory);
  const std::string file = name + ".pov";
  io::writePovScene((std::filesystem::path(directory) / file).string(), description, {depth, shadows});
  return file;
}

struct Renders {
  render::RenderResult revolve;
  PovrayRun povray;
};

// Both renderers on `threads` threads, `repetitions` times each, interleaved so that a noisy
// moment of a shared machine falls on both.
TimedRun timeBoth(const io::SceneDescription& description, const scene::EmbreeScene& built,
                  render::RenderSettings render, const std::string& povray, PovrayRequest request, int threads,
                  int repetitions, Renders& last) {
  render.threads = threads;
  request.threads = threads;
  std::vector<double> revolve, trace, parse, bounding;
  // revolve's render takes milliseconds where POV-Ray's takes seconds: each repetition renders it
  // enough times to fill about a quarter of a second (at most 25), so its median rests on as
  // many samples as the noise of a shared machine needs.
  int revolveRuns = 1;
  for (int i = 0; i < repetitions; ++i) {
    for (int k = 0; k < revolveRuns; ++k) {
      last.revolve = render::render(description, built, render);
      revolve.push_back(last.revolve.seconds);
      if (i == 0 && k == 0) revolveRuns = std::clamp(int(0.25 / std::max(last.revolve.seconds, 1e-6)), 1, 25);
    }
    last.povray = runPovray(povray, request);
    trace.push_back(last.povray.traceSeconds);
    parse.push_back(last.povray.parseSeconds);
    bounding.push_back(last.povray.boundingSeconds);
  }
  TimedRun run;
  run.threads = threads;
  run.revolveRenders = int(revolve.size());
  run.revolveSeconds = median(revolve);
  run.revolveLow = *std::min_element(revolve.begin(), revolve.end());
  run.revolveHigh = *std::max_element(revolve.begin(), revolve.end());
  run.povraySeconds = median(trace);
  run.povrayLow = *std::min_element(trace.begin(), trace.end());
  run.povrayHigh = *std::max_element(trace.begin(), trace.end());
  run.povrayParseSeconds = median(parse);
  run.povrayBoundingSeconds = median(bounding);
  return run;
}

render::RenderSettings whitted(int width, int height, int depth, bool shadows) {
  render::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.spp = 1;  // one ray through each pixel's centre, as POV-Ray's -A
  settings.integrator.kind = render::IntegratorKind::whitted;
  settings.integrator.depth = depth;
  settings.integrator.shadows = shadows;
  return settings;
}

nlohmann::ordered_json timedJson(const TimedRun& run) {
  return {{"threads", run.threads},
          {"revolve_render_seconds",
           {{"median", run.revolveSeconds},
            {"low", run.revolveLow},
            {"high", run.revolveHigh},
            {"renders", run.revolveRenders}}},
          {"povray_trace_seconds", {{"median", run.povraySeconds}, {"low", run.povrayLow}, {"high", run.povrayHigh}}},
          {"povray_parse_seconds", run.povrayParseSeconds},
          {"povray_bounding_seconds", run.povrayBoundingSeconds},
          {"povray_over_revolve", run.ratio()}};
}

nlohmann::ordered_json differenceJson(const ImageDifference& d) {
  return {{"exposure", d.exposure},
          {"mean_absolute", d.meanAbsolute},
          {"mean_reference", d.meanReference},
          {"relative", d.meanReference > 0 ? d.meanAbsolute / d.meanReference : 0.0},
          {"differing_pixels", d.differingPixels}};
}

// The scaling scene: the vase at `points` profile points (or, with `spline`, as that spline traced
// exactly, exported as the same Bézier pieces), seen whole, one point light.
io::SceneDescription vaseScene(int points, const std::optional<Spline>& spline = std::nullopt) {
  const SmoothProfile vase = vaseShape();
  const SmoothProfile::Extent e = vase.extent();
  const double middle = 0.5 * (e.zLow + e.zHigh), height = e.zHigh - e.zLow;
  io::SceneDescription scene;
  scene.camera.from = {0.0, -3.0 * height, middle + 0.8 * height};
  scene.camera.to = {0.0, 0.0, middle};
  scene.camera.up = {0, 0, 1};
  scene.camera.fovDegrees = 24;
  if (spline) {
    scene.file = "vase (" + std::to_string(spline->pieceCount()) + " Bezier pieces)";
    // Traced exactly: a tool that needs its polyline draws it (io::SceneProfile::polyline).
    scene.profiles.push_back({.name = "vase", .spline = spline});
  } else {
    scene.file = "vase (" + std::to_string(points) + " points)";
    scene.profiles.push_back({.name = "vase", .profile = Profile(vase.sample(points))});
  }
  io::SceneMaterial clay;
  clay.name = "clay";
  clay.color = {0.7, 0.5, 0.35};
  scene.materials.push_back(clay);
  scene.objects.push_back({"vase", 0, 0, {}});
  io::SceneLight light;
  light.position = {-2.0 * height, -3.0 * height, middle + 3.0 * height};
  const double d2 = 2.0 * 2.0 + 3.0 * 3.0 + 2.5 * 2.5;  // squared distance to the vase's middle, in heights
  light.intensity = {3.0 * d2 * height * height, 3.0 * d2 * height * height, 3.0 * d2 * height * height};
  scene.lights.push_back(light);
  scene.environment.color = {0.1, 0.1, 0.12};
  return scene;
}

}  // namespace

PovComparison runPovComparison(const std::string& povray, const PovCompareSettings& settings) {
  const io::SceneDescription description = io::readScene(settings.scene);
  const std::string name = std::filesystem::path(settings.scene).stem().string();
  PovComparison result;
  result.width = settings.width > 0 ? settings.width : description.camera.width.value_or(640);
  result.height = settings.height > 0 ? settings.height : description.camera.height.value_or(480);
  result.figure = !settings.figure.empty()
                      ? settings.figure
                      : (std::filesystem::path(settings.outDirectory) / (name + "_side_by_side.png")).string();
  render::imageFormatFor(result.figure);
  const std::string file =
      exportForComparison(description, settings.outDirectory, name, settings.depth, settings.shadows);
  result.povFile = (std::filesystem::path(settings.outDirectory) / file).string();
  // The figure's folder must take it: checked now (by naming it as an output), before minutes of work.
  io::OutputSet{}.add("--figure", result.figure);

  const scene::EmbreeScene built(description, scene::BuildSettings{});
  result.revolveBuildSeconds = built.buildSeconds();
  const render::RenderSettings render = whitted(result.width, result.height, settings.depth, settings.shadows);
  PovrayRequest request{settings.outDirectory, file, name + "_povray.exr", result.width,
                        result.height,         1,    settings.depth,       settings.shadows};
  Renders last;
  const int all = allThreads(settings.threads);
  result.runs.push_back(timeBoth(description, built, render, povray, request, 1, settings.repetitions, last));
  if (all > 1)
    result.runs.push_back(timeBoth(description, built, render, povray, request, all, settings.repetitions, last));

  result.revolveRays = last.revolve.rays.camera + last.revolve.rays.bounce + last.revolve.rays.shadow;
  result.revolveShadowRays = last.revolve.rays.shadow;
  result.povrayRays = last.povray.rays;
  result.povrayShadowRayTests = last.povray.shadowRayTests;
  result.povrayLatheTests = last.povray.latheTests;
  result.difference = compareImages(last.revolve.image, last.povray.image);
  result.revolveImage = (std::filesystem::path(settings.outDirectory) / (name + "_revolve.exr")).string();
  result.povrayImage = (std::filesystem::path(settings.outDirectory) / request.image).string();
  io::OutputSet outputs;
  outputs.add("revolve's image", result.revolveImage);
  render::writeImage(outputs.stream(result.revolveImage), result.revolveImage, last.revolve.image);
  outputs.commit();
  writeSideBySide(result.figure, last.revolve.image, last.povray.image, result.difference.exposure, "revolve",
                  "POV-Ray 3.7");
  return result;
}

void printPovComparison(std::FILE* out, const PovCompareSettings& settings, const PovComparison& c) {
  std::fprintf(out,
               "\n== %s: revolve (whitted) and POV-Ray 3.7, %d x %d, 1 sample a pixel, depth %d, %s; median of %d\n",
               settings.scene.c_str(), c.width, c.height, settings.depth, settings.shadows ? "shadows" : "no shadows",
               settings.repetitions);
  std::fprintf(out, "%8s %16s %22s %10s %18s\n", "threads", "revolve render s", "POV-Ray Trace Time s", "ratio",
               "POV-Ray parse+bound s");
  for (const TimedRun& run : c.runs) {
    std::fprintf(out, "%8d %16.4f %22.3f %9.1fx %18.3f\n", run.threads, run.revolveSeconds, run.povraySeconds,
                 run.ratio(), run.povrayParseSeconds + run.povrayBoundingSeconds);
  }
  std::fprintf(out,
               "rays: revolve %llu (%llu shadow), POV-Ray %llu (+%llu shadow ray tests); lathe tests %llu; revolve "
               "build %.4f s\n",
               (unsigned long long)c.revolveRays, (unsigned long long)c.revolveShadowRays,
               (unsigned long long)c.povrayRays, (unsigned long long)c.povrayShadowRayTests,
               (unsigned long long)c.povrayLatheTests, c.revolveBuildSeconds);
  std::fprintf(out,
               "image difference (linear, clamped to [0, 1]): exposure %.4f, mean |d| %.4f of mean %.4f (%.1f%%), "
               "%.2f%% of pixels differ by > 0.05\n",
               c.difference.exposure, c.difference.meanAbsolute, c.difference.meanReference,
               100.0 * c.difference.meanAbsolute / std::max(c.difference.meanReference, 1e-30),
               100.0 * c.difference.differingPixels);
  std::fprintf(out, "wrote %s (revolve | POV-Ray | difference x 4), %s, %s, %s\n", c.figure.c_str(),
               c.revolveImage.c_str(), c.povrayImage.c_str(), c.povFile.c_str());
}

nlohmann::ordered_json povComparisonJson(const PovCompareSettings& settings, const PovComparison& c) {
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const TimedRun& run : c.runs) runs.push_back(timedJson(run));
  return {
      {"settings",
       {{"scene", settings.scene},
        {"width", c.width},
        {"height", c.height},
        {"spp", 1},
        {"integrator", "whitted"},
        {"depth", settings.depth},
        {"shadows", settings.shadows},
        {"repetitions", settings.repetitions}}},
      {"runs", runs},
      {"revolve_build_seconds", c.revolveBuildSeconds},
      {"rays",
       {{"revolve", c.revolveRays},
        {"revolve_shadow", c.revolveShadowRays},
        {"povray", c.povrayRays},
        {"povray_shadow_ray_tests", c.povrayShadowRayTests},
        {"povray_lathe_tests", c.povrayLatheTests}}},
      {"image_difference", differenceJson(c.difference)},
      {"files",
       {{"figure", c.figure}, {"pov", c.povFile}, {"revolve_image", c.revolveImage}, {"povray_image", c.povrayImage}}}};
}

std::vector<PovScalingPoint> runPovScaling(const std::string& povray, const PovScalingSettings& settings) {
  std::vector<PovScalingPoint> results;
  const int threads = allThreads(settings.threads);
  for (const int points : settings.points) {
    if (points < 16 || std::size_t(points) > io::kPovMaxLathePoints) {
      throw std::invalid_argument("--points " + std::to_string(points) +
                                  ": expected 16 to 32767 (POV-Ray's lathe limit)");
    }
  }
  // The polylines at each count, then the spline: the vase's lines and arcs as cubic pieces within
  // 1e-9 of its size (bench/smooth_spline.h), traced exactly and given to POV-Ray as bezier_spline.
  const SmoothProfile vase = vaseShape();
  const Spline spline(SplineKind::bezier, bezierOf(vase, 1e-9 * vase.size()).bezier);
  for (std::size_t run = 0; run <= settings.points.size(); ++run) {
    const bool exact = run == settings.points.size();
    const int points = exact ? int(spline.pieceCount()) : settings.points[run];
    const io::SceneDescription description = exact ? vaseScene(0, spline) : vaseScene(points);
    const std::string name = exact ? "vase_spline" : "vase_" + std::to_string(points);
    const std::string file = exportForComparison(description, settings.outDirectory, name, 1, true);
    const scene::EmbreeScene built(description, scene::BuildSettings{});
    const render::RenderSettings render = whitted(settings.size, settings.size, 1, true);
    const PovrayRequest request{
        settings.outDirectory, file, name + "_povray.exr", settings.size, settings.size, threads, 1, true};
    Renders last;
    PovScalingPoint point;
    point.points = points;
    point.spline = exact;
    point.timing = timeBoth(description, built, render, povray, request, threads, settings.repetitions, last);
    point.difference = compareImages(last.revolve.image, last.povray.image);
    results.push_back(point);
    std::fprintf(stderr, "revolve-bench: pov-scaling: %d %s: revolve %.4f s, POV-Ray %.3f s\n", points,
                 exact ? "Bezier pieces" : "points", point.timing.revolveSeconds, point.timing.povraySeconds);
  }
  return results;
}

void printPovScaling(std::FILE* out, const PovScalingSettings& settings, const std::vector<PovScalingPoint>& points) {
  std::fprintf(out, "\n== one lathe (the vase), %d x %d, whitted depth 1 with shadows, %d threads, median of %d\n",
               settings.size, settings.size, points.empty() ? 0 : points.front().timing.threads, settings.repetitions);
  std::fprintf(out, "%8s %16s %22s %10s %14s\n", "points", "revolve render s", "POV-Ray Trace Time s", "ratio",
               "mean |d| image");
  for (const PovScalingPoint& p : points) {
    if (p.spline) continue;
    std::fprintf(out, "%8d %16.5f %22.3f %9.1fx %14.5f\n", p.points, p.timing.revolveSeconds, p.timing.povraySeconds,
                 p.timing.ratio(), p.difference.meanAbsolute);
  }
  for (const PovScalingPoint& p : points) {
    if (!p.spline) continue;
    std::fprintf(
        out, "the vase as %d cubic Bezier pieces, traced exactly; POV-Ray's bezier_spline lathe of the same pieces:\n",
        p.points);
    std::fprintf(out, "%8s %16.5f %22.3f %9.1fx %14.5f\n", "spline", p.timing.revolveSeconds, p.timing.povraySeconds,
                 p.timing.ratio(), p.difference.meanAbsolute);
  }
}

nlohmann::ordered_json povScalingJson(const PovScalingSettings& settings, const std::vector<PovScalingPoint>& points) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  nlohmann::ordered_json spline;
  for (const PovScalingPoint& p : points) {
    nlohmann::ordered_json entry = timedJson(p.timing);
    entry[p.spline ? "bezier_pieces" : "points"] = p.points;
    entry["image_difference"] = differenceJson(p.difference);
    (p.spline ? spline : list.emplace_back()) = entry;
  }
  return {{"settings",
           {{"shape", "vase"},
            {"width", settings.size},
            {"height", settings.size},
            {"spp", 1},
            {"integrator", "whitted"},
            {"depth", 1},
            {"shadows", true},
            {"threads", points.empty() ? 0 : points.front().timing.threads},
            {"repetitions", settings.repetitions}}},
          {"points", list},
          {"spline", spline}};
}

}  // namespace revolve::bench
