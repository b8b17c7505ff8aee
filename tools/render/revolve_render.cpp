// revolve-render: renders a scene file (io/scene_file.h) with path tracing or the Whitted ray tracer
// of Baciu, Jia & Lam (2001), every surface of revolution traced exactly by revolve inside Embree
// (or tessellated, or as Embree's own linear cone curve, for comparison). Options and the scene
// format are documented in README.md.
#include "cli/command_line.h"
#include "embree/memory_check.h"
#include "io/output_set.h"
#include "io/poses_file.h"
#include "io/pov_scene.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "render/curve_polylines.h"
#include "render/depth_image.h"
#include "render/glass_checks.h"
#include "render/image_output.h"
#include "render/progress.h"
#include "render/renderer.h"
#include "robot/camera_rig.h"
#include "scene/degenerate_objects.h"
#include "scene/embree_scene.h"
#include "scene/picking.h"
#include "threads/thread_arenas.h"

#include <tbb/info.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace revolve;

struct Options {
  std::string scene, output, integrator = "path", geometry = "mibit", shell = "cylinder", filter = "tent", stats, pick,
                             exportPov, camera, poses, depthImage;
  std::optional<io::CurveTolerance> tolerance;  // --tolerance
  int width = 0, height = 0, spp = 0, depth = 0, threads = 0;
  std::uint32_t subdivisions = 0, slices = 64;
  std::uint64_t seed = 1;
  bool noMonotoneSplit = false, noRangeSearch = false, noShadows = false, noRegularize = false, filteredShadows = false;
  double exposure = 0;
};

scene::BuildSettings buildSettings(const Options& options) {
  scene::BuildSettings build;
  build.mesh = options.geometry == "mesh";
  build.embreeCone = options.geometry == "embree-cone";
  build.slices = options.slices;
  // --geometry mesh and embree-cone name no Method: the default stays, unused. The command line
  // has checked both names.
  if (const std::optional<Method> method = methodNamed(options.geometry)) build.options.method = *method;
  build.options.shell = *shellKindNamed(options.shell);
  build.options.subdivisions = options.subdivisions;
  build.options.monotoneSplit = !options.noMonotoneSplit;
  build.options.rangeSearch = !options.noRangeSearch;
  build.countStats = !options.stats.empty();
  return build;
}

void writeStats(io::OutputSet& outputs, const Options& options, const render::RenderSettings& settings,
                const scene::EmbreeScene& built, const render::RenderResult& result, std::size_t objects,
                const std::vector<render::CurvePolyline>& curves) {
  const std::uint64_t total = result.rays.camera + result.rays.bounce + result.rays.shadow;
  const Stats mibit = built.stats();
  nlohmann::ordered_json json;
  json["scene"] = options.scene;
  json["image"] = {{"width", settings.width}, {"height", settings.height}};
  json["spp"] = settings.spp;
  json["integrator"] = options.integrator;
  json["depth"] = settings.integrator.depth;
  if (settings.integrator.kind == render::IntegratorKind::path)
    json["regularize"] = settings.integrator.regularize;
  else
    json["filtered_shadows"] = settings.integrator.filteredShadows;
  json["seed"] = settings.seed;
  json["filter"] = options.filter;
  json["exposure"] = options.exposure;
  json["threads"] = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  json["geometry"] = options.geometry;
  json["objects"] = objects;
  json["distinct_profiles"] = built.prototypeCount();
  json["build_seconds"] = built.buildSeconds();
  json["render_seconds"] = result.seconds;
  json["rays"] = {
      {"camera", result.rays.camera}, {"bounce", result.rays.bounce}, {"shadow", result.rays.shadow}, {"total", total}};
  json["mrays_per_second"] = result.seconds > 0 ? double(total) / result.seconds * 1e-6 : 0.0;
  const auto share = [&](render::Phase phase) { return result.phaseShares[std::size_t(phase)]; };
  json["time_shares"] = {{"intersection", share(render::Phase::intersection)},
                         {"shadows", share(render::Phase::shadows)},
                         {"sampling", share(render::Phase::sampling)},
                         {"shading", share(render::Phase::shading)}};
  json["mibit"] = {{"queries", mibit.rays},
                   {"nodes_visited", mibit.nodesVisited},
                   {"shell_tests", mibit.shellTests},
                   {"quadratics", mibit.quadratics}};
  json["memory"] = {{"revolve_bytes", built.revolveBytes()},
                    {"embree_bytes", built.embreeBytes()},
                    {"embree_peak_bytes", built.embreePeakBytes()}};
  if (options.tolerance) {
    json["tolerance"] = options.tolerance->text;
    nlohmann::ordered_json polylines = nlohmann::ordered_json::array();
    for (const render::CurvePolyline& c : curves)
      polylines.push_back({{"profile", c.profile}, {"tolerance", c.tolerance}, {"points", c.points}});
    json["curves_as_polylines"] = polylines;
  }
  const std::string text = json.dump(2) + "\n";
  outputs.write(options.stats, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
}

// --pick X,Y: two whole numbers, a pixel of the width x height image.
std::pair<int, int> parsePixel(const std::string& text, int width, int height) {
  const std::size_t comma = text.find(',');
  int xy[2];
  const std::string parts[2] = {text.substr(0, comma), comma == std::string::npos ? "" : text.substr(comma + 1)};
  for (int i = 0; i < 2; ++i) {
    std::size_t used = 0;
    bool ok = comma != std::string::npos && !parts[i].empty() &&
              parts[i].find_first_not_of("0123456789-+") == std::string::npos;
    try {
      if (ok) xy[i] = std::stoi(parts[i], &used);
    } catch (const std::exception&) {
      ok = false;
    }
    if (!ok || used != parts[i].size()) {
      throw std::runtime_error("--pick \"" + text.substr(0, 40) +
                               "\": expected X,Y, two whole numbers (a pixel from the top left)");
    }
  }
  if (xy[0] < 0 || xy[0] >= width) {
    throw std::runtime_error("--pick: X = " + std::to_string(xy[0]) +
                             " is outside the image: 0 <= X < width = " + std::to_string(width));
  }
  if (xy[1] < 0 || xy[1] >= height) {
    throw std::runtime_error("--pick: Y = " + std::to_string(xy[1]) +
                             " is outside the image: 0 <= Y < height = " + std::to_string(height));
  }
  return {xy[0], xy[1]};
}

void printWarnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) std::fprintf(stderr, "revolve-render: warning: %s\n", warning.c_str());
}

// What is valid but almost surely not meant: points the profiles dropped, objects nothing can see
// (of the profiles as they will be traced).
std::vector<std::string> sceneWarnings(const io::SceneDescription& description) {
  std::vector<std::string> warnings;
  for (const io::SceneProfile& profile : description.profiles)
    warnings.insert(warnings.end(), profile.warnings.begin(), profile.warnings.end());
  for (std::string& warning : scene::degenerateObjectWarnings(description, true))
    warnings.push_back(std::move(warning));
  return warnings;
}

// Kajiya's strip tree bounds polylines: a curve traced exactly is refused before any work, naming
// the scene's profile and the ways that work.
void checkKajiya(const Options& options, const io::SceneDescription& description) {
  if (options.geometry != "kajiya") return;
  for (const io::SceneObject& object : description.objects) {
    const io::SceneProfile& profile = description.profiles[object.profile];
    if (!profile.spline) continue;
    throw std::runtime_error(
        description.file + ": profiles." + profile.name + ": a " + splineKindName(profile.spline->kind()) +
        " spline, traced exactly: --geometry kajiya cannot trace it (Kajiya's strip tree bounds "
        "polylines only); use --geometry mibit or linear, or --tolerance to trace it as a polyline");
  }
}

// The scene as it is traced: splines within --tolerance made polylines (for an image `height`
// pixels high), Kajiya's limit checked, built into Embree; then the scene's warnings (of the
// profiles as traced), before the long work: every refusal before this point is the run's one line.
struct PreparedScene {
  std::vector<render::CurvePolyline> curves;  // the curves traced as polylines (--stats reports them)
  std::unique_ptr<scene::EmbreeScene> built;
};

PreparedScene prepareScene(const Options& options, io::SceneDescription& description, int height) {
  PreparedScene prepared;
  if (options.tolerance) prepared.curves = render::applyCurveTolerance(description, *options.tolerance, height);
  checkKajiya(options, description);
  prepared.built = std::make_unique<scene::EmbreeScene>(description, buildSettings(options));
  printWarnings(sceneWarnings(description));
  printWarnings(render::glassWarnings(description));
  return prepared;
}

// Prints the object under the pixel (as the GLBot simulator's scene editor): index, name, hit point, distance.
void pickObject(const Options& options, const io::SceneDescription& description, int width, int height) {
  const auto [x, y] = parsePixel(options.pick, width, height);
  const scene::EmbreeScene built(description, buildSettings(options));
  const std::optional<scene::Pick> picked = scene::pick(description, built, width, height, x, y);
  if (!picked) {
    std::printf("nothing\n");
    return;
  }
  std::printf("object %u \"%s\" point %.9g %.9g %.9g distance %.9g\n", picked->object, picked->name.c_str(),
              picked->point.x, picked->point.y, picked->point.z, picked->distance);
}

// --export-pov: the scene as POV-Ray SDL (io/pov_scene.h), with whitted's depth and shadows as the
// file's defaults, into the run's outputs. What maps only approximately is returned as warnings,
// printed once the file is written (a run that fails writes no file to warn about).
std::vector<std::string> exportPov(const Options& options, const io::SceneDescription& description,
                                   io::OutputSet& outputs) {
  io::PovDefaults defaults;
  defaults.depth = options.depth > 0 ? options.depth : render::IntegratorSettings{}.depth;
  defaults.shadows = !options.noShadows;
  const io::PovScene pov = io::povScene(description, defaults);
  outputs.stream(options.exportPov).write(pov.text);
  std::vector<std::string> warnings;
  for (const std::string& warning : pov.warnings) warnings.push_back(options.exportPov + ": " + warning);
  return warnings;
}

void checkPovName(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".pov") throw std::runtime_error(path + ": --export-pov writes POV-Ray scene files, named .pov");
}

// The render's settings: the command line's, else the scene camera's defaults, else the renderer's.
render::RenderSettings renderSettings(const Options& options, const io::SceneDescription& description) {
  render::RenderSettings settings;
  settings.width = options.width > 0 ? options.width : description.camera.width.value_or(640);
  settings.height = options.height > 0 ? options.height : description.camera.height.value_or(480);
  settings.spp = options.spp > 0 ? options.spp : description.camera.spp.value_or(16);
  settings.seed = options.seed;
  settings.filter = options.filter == "box" ? render::PixelFilter::box : render::PixelFilter::tent;
  settings.threads = options.threads;
  settings.integrator.kind =
      options.integrator == "whitted" ? render::IntegratorKind::whitted : render::IntegratorKind::path;
  settings.integrator.depth = options.depth > 0 ? options.depth : render::IntegratorSettings{}.depth;
  settings.integrator.shadows = !options.noShadows;
  settings.integrator.regularize = !options.noRegularize;
  settings.integrator.filteredShadows = options.filteredShadows;
  settings.measurePhases = !options.stats.empty();
  return settings;
}

// Frame `index` of `count`'s file: `path` with _NNNN before its extension (at least 4 digits, as
// many as the last frame's number needs), e.g. out/frame.png -> out/frame_0007.png.
std::string framePath(const std::string& path, std::size_t index, std::size_t count, const std::string& extension) {
  const std::filesystem::path p(path);
  const int digits = std::max<int>(4, int(std::to_string(count == 0 ? 0 : count - 1).size()));
  char number[32];
  std::snprintf(number, sizeof number, "_%0*zu", digits, index);
  return (p.parent_path() / (p.stem().string() + number + extension)).string();
}

// --camera with --poses: the robot's camera (a sensor file of type camera) rendered at every pose
// of the path, one frame of files a pose, each frame whole or absent (its files renamed into
// place together). Beside each image its camera's ROS CameraInfo (JSON) and, with --depth-image,
// a depth image (render/depth_image.h).
void renderPath(const Options& options) {
  if (options.camera.empty() || options.poses.empty())
    throw std::runtime_error("--camera and --poses go together: a camera renders along a path of poses");
  if (!options.pick.empty() || !options.exportPov.empty() || !options.stats.empty())
    throw std::runtime_error("--camera: renders frames along a path; --pick, --export-pov and --stats take one view");
  if (options.width > 0 || options.height > 0)
    throw std::runtime_error("--camera " + options.camera + ": the camera file gives the image's width and height");
  if (options.output.empty())
    throw std::runtime_error("--camera: -o names the frames (out/frame.png: frame_0000.png, ...)");
  render::imageFormatFor(options.output);
  if (!options.depthImage.empty()) render::checkDepthImageName(options.depthImage);
  io::SceneDescription description = io::readScene(options.scene);
  const io::CameraDescription camera = io::readCamera(options.camera);
  const std::vector<io::RobotPose> poses = io::readPosesCsv(options.poses);
  render::RenderSettings settings = renderSettings(options, description);
  settings.width = camera.width;
  settings.height = camera.height;
  app::requireMemory(40.0 * settings.width * settings.height, "an image of " + std::to_string(settings.width) + " x " +
                                                                  std::to_string(settings.height) + " pixels");
  const PreparedScene prepared = prepareScene(options, description, settings.height);
  const scene::EmbreeScene& built = *prepared.built;
  const std::array<double, 9> k = robot::intrinsics(camera);
  const float scale = float(std::exp2(options.exposure));
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const std::string image =
        framePath(options.output, i, poses.size(), std::filesystem::path(options.output).extension().string());
    const std::string info = framePath(options.output, i, poses.size(), ".json");
    const std::string depth = options.depthImage.empty() ? "" : framePath(options.depthImage, i, poses.size(), ".exr");
    io::OutputSet outputs;
    outputs.addInput("the scene file", options.scene);
    for (const io::SceneProfile& profile : description.profiles)
      outputs.addInput("a profile CSV of the scene", profile.csvFile);
    outputs.addInput("the camera file (--camera)", options.camera);
    outputs.addInput("the poses file (--poses)", options.poses);
    outputs.add("-o", image);
    outputs.add("-o (camera info)", info);
    if (!depth.empty()) outputs.add("--depth-image", depth);

    const std::optional<int> spp = description.camera.spp;
    description.camera = robot::cameraAt(camera, poses[i]);
    description.camera.spp = spp;
    render::RenderResult result = render::render(description, built, settings);
    for (float& value : result.image.pixels) value *= scale;
    render::writeImage(outputs.stream(image), image, result.image);
    if (!depth.empty()) {
      render::writeDepthImage(
          outputs.stream(depth), depth, settings.width, settings.height,
          render::depthImage(built, description.camera, settings.width, settings.height, options.threads));
    }
    // sensor_msgs/msg/CameraInfo's fields (ROS 2 names), the camera's optical frame in the world
    // (x right, y down, z forward) and the pose it was rendered at.
    const std::array<double, 9> rotation = robot::opticalRotation(camera, poses[i]);
    nlohmann::ordered_json json;
    json["frame"] = i;
    json["time"] = poses[i].timed() ? nlohmann::ordered_json(poses[i].time) : nlohmann::ordered_json(nullptr);
    json["height"] = camera.height;
    json["width"] = camera.width;
    json["distortion_model"] = "none";
    json["d"] = nlohmann::ordered_json::array();
    json["k"] = k;
    json["r"] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    json["p"] = {k[0], 0, k[2], 0, 0, k[4], k[5], 0, 0, 0, 1, 0};
    json["frame_id"] = "camera_optical";
    json["position"] = description.camera.from;
    json["rotation"] = rotation;  // world from optical, row-major
    if (!depth.empty()) json["depth_image"] = std::filesystem::path(depth).filename().string();
    json["image"] = std::filesystem::path(image).filename().string();
    const std::string text = json.dump(1) + "\n";
    outputs.write(info, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
    outputs.commit();
    std::printf("revolve-render: frame %zu of %zu: %s\n", i + 1, poses.size(), image.c_str());
    std::fflush(stdout);
  }
  if (built.refusedRays() > 0) {
    std::fprintf(stderr, "revolve-render: warning: %s: %llu rays fell outside Embree's range and were not traced\n",
                 options.scene.c_str(), static_cast<unsigned long long>(built.refusedRays()));
  }
}

void run(const Options& options) {
  if (!options.camera.empty() || !options.poses.empty() || !options.depthImage.empty()) {
    if (!options.depthImage.empty() && options.camera.empty())
      throw std::runtime_error("--depth-image " + options.depthImage +
                               ": depth images are rendered along a path (--camera, --poses)");
    renderPath(options);
    return;
  }
  if (!options.pick.empty()) {
    // Picking prints what lies under a pixel and renders nothing: an output would stay unwritten.
    if (!options.output.empty())
      throw std::runtime_error("-o " + options.output + ": --pick renders no image; leave -o out");
    if (!options.stats.empty())
      throw std::runtime_error("--stats " + options.stats + ": --pick renders nothing to report; leave --stats out");
    const io::SceneDescription description = io::readScene(options.scene);
    printWarnings(sceneWarnings(description));
    const int width = options.width > 0 ? options.width : description.camera.width.value_or(640);
    const int height = options.height > 0 ? options.height : description.camera.height.value_or(480);
    pickObject(options, description, width, height);
    return;
  }
  // With --export-pov and no -o, only the SDL is written.
  const bool renders = options.exportPov.empty() || !options.output.empty();
  const std::string output =
      !options.output.empty() ? options.output : std::filesystem::path(options.scene).stem().string() + ".png";
  if (!options.exportPov.empty()) checkPovName(options.exportPov);
  if (!renders && !options.stats.empty()) {
    throw std::runtime_error("--stats: --export-pov without -o renders nothing to report; add -o to render as well");
  }
  if (renders) render::imageFormatFor(output);  // an unknown extension fails before any work
  io::SceneDescription description = io::readScene(options.scene);
  // Every output is named now (its temporary made: the folder takes files), and none may be an input.
  io::OutputSet outputs;
  outputs.addInput("the scene file", options.scene);
  for (const io::SceneProfile& profile : description.profiles)
    outputs.addInput("a profile CSV of the scene", profile.csvFile);
  if (!options.exportPov.empty()) outputs.add("--export-pov", options.exportPov);
  if (renders) outputs.add("-o", output);
  if (renders && !options.stats.empty()) outputs.add("--stats", options.stats);
  std::vector<std::string> povWarnings;
  if (!options.exportPov.empty()) povWarnings = exportPov(options, description, outputs);
  if (!renders) {
    outputs.commit();
    printWarnings(sceneWarnings(description));
    printWarnings(povWarnings);
    return;
  }

  const render::RenderSettings settings = renderSettings(options, description);

  // The float image, OpenImageIO's copy of it and the converted one: 3 x 12 bytes a pixel.
  app::requireMemory(36.0 * settings.width * settings.height, "an image of " + std::to_string(settings.width) + " x " +
                                                                  std::to_string(settings.height) + " pixels");

  const PreparedScene prepared = prepareScene(options, description, settings.height);
  const scene::EmbreeScene& built = *prepared.built;
  const std::vector<render::CurvePolyline>& curves = prepared.curves;
  render::ProgressReport progress;
  const render::RenderResult result =
      render::render(description, built, settings, [&](double fraction) { progress.update(fraction); });
  progress.finish();
  if (built.refusedRays() > 0) {
    std::fprintf(stderr, "revolve-render: warning: %s: %llu rays fell outside Embree's range and were not traced\n",
                 options.scene.c_str(), static_cast<unsigned long long>(built.refusedRays()));
  }
  render::Image image = result.image;
  const float scale = float(std::exp2(options.exposure));
  for (float& value : image.pixels) value *= scale;
  render::writeImage(outputs.stream(output), output, image);
  if (!options.stats.empty()) writeStats(outputs, options, settings, built, result, description.objects.size(), curves);
  outputs.commit();
  printWarnings(povWarnings);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Renders a scene of surfaces of revolution (JSON scene file) with path tracing or Whitted ray "
      "tracing through Embree, every surface traced exactly by revolve."};
  app.add_option("scene", options.scene, "scene file (JSON)")->required()->check(app::kNonEmpty);
  app.add_option("-o,--output", options.output,
                 "image to write: .png (8-bit sRGB) or .exr (linear half); default: <scene name>.png")
      ->check(app::kNonEmpty);
  app.add_option("--width", options.width, "image width in pixels (default: the scene's camera.width, else 640)")
      ->check(app::wholeNumberIn(1, 16384));
  app.add_option("--height", options.height, "image height in pixels (default: camera.height, else 480)")
      ->check(app::wholeNumberIn(1, 16384));
  app.add_option("--spp", options.spp, "samples per pixel (default: camera.spp, else 16)")
      ->check(app::wholeNumberIn(1, 1 << 20));
  app.add_option("--integrator", options.integrator,
                 "path: path tracing; whitted: the ray tracer of Baciu, Jia & Lam (2001)")
      ->check(CLI::IsMember({"path", "whitted"}))
      ->capture_default_str();
  app.add_option("--depth", options.depth,
                 "path: most surface hits a path has; whitted: ray levels, 1 = ray casting (default 8 for both; hollow "
                 "glass needs 5)")
      ->check(app::wholeNumberIn(1, 64));
  app.add_flag("--no-shadows", options.noShadows,
               "whitted: no shadow rays (with --depth 1, Baciu, Jia & Lam's Example 1)");
  app.add_flag(
      "--filtered-shadows", options.filteredShadows,
      "whitted: shadow rays pass straight through glass, dimmed by its Fresnel transmission and tint (as POV-Ray's)");
  app.add_flag("--no-regularize", options.noRegularize,
               "path: no path regularisation (unbiased: for reference renders; the default roughens glossy metal after "
               "the first "
               "diffuse or glossy bounce, which removes the fireflies of caustics)");
  app.add_option("--filter", options.filter,
                 "pixel filter of more than one sample a pixel: tent (radius 1 pixel) or box (the pixel's square)")
      ->check(CLI::IsMember({"tent", "box"}))
      ->capture_default_str();
  app.add_option("--exposure", options.exposure, "scale the image by 2^EV before writing it (default 0)")
      ->check(CLI::Range(-64.0, 64.0));
  app.add_option("--geometry", options.geometry,
                 "how surfaces of revolution are traced (mesh: tessellated with --slices; embree-cone: Embree's own "
                 "linear cone curve, for the profiles it can express)")
      ->check(CLI::IsMember({"mibit", "linear", "kajiya", "mesh", "embree-cone"}))
      ->capture_default_str();
  app.add_option("--shell", options.shell, "MIBIT bounding shells")
      ->check(CLI::IsMember({"cylinder", "cone", "hybrid"}))
      ->capture_default_str();
  app.add_flag("--no-monotone-split", options.noMonotoneSplit, "MIBIT: refine each profile as one interval");
  app.add_flag("--no-range-search", options.noRangeSearch, "MIBIT: test every node's shell");
  app.add_option("--subdivisions", options.subdivisions, "MIBIT leaves per monotone interval (0: one segment a leaf)")
      ->check(app::wholeNumberIn<std::uint32_t>(0, UINT32_MAX))
      ->capture_default_str();
  app.add_option("--slices", options.slices, "azimuthal steps of --geometry mesh")
      ->check(app::wholeNumberIn<std::uint32_t>(3, 1u << 16))
      ->capture_default_str();
  app::addToleranceOption(
      app, options.tolerance, true,
      "trace spline profiles as polylines within this tolerance (profile units) instead of exactly; "
      "\"pixel\": the smallest pixel footprint at which the camera sees an object made of the profile");
  app.add_option("--threads", options.threads, "worker threads (default: all)")
      ->check(app::wholeNumberIn(1, app::kMaxThreads));
  app.add_option("--seed", options.seed, "random seed: the same seed gives the same image")
      ->check(app::wholeNumberIn<std::uint64_t>(0, UINT64_MAX))
      ->capture_default_str();
  app.add_option("--stats", options.stats,
                 "write statistics as JSON: rays, Mrays/s, where the time goes, MIBIT counters, memory")
      ->check(app::kNonEmpty);
  CLI::Option* exportOption =
      app.add_option(
             "--export-pov", options.exportPov,
             "write the scene as POV-Ray SDL (FILE.pov; size from POV-Ray's +W +H) and render only if -o is given")
          ->check(app::kNonEmpty);
  app.add_option("--pick", options.pick,
                 "X,Y: instead of rendering, print the object under pixel (X, Y) of the image (from its top left): "
                 "its index, name, hit point and distance, or \"nothing\" (no -o or --stats with it)")
      ->check(CLI::Validator(
          [](std::string& value) {
            return value.empty() ? std::string("the value is empty; expected X,Y") : std::string();
          },
          "X,Y"))
      ->excludes(exportOption);
  app.add_option("--camera", options.camera,
                 "a robot's camera (a sensor file of type camera): render its view at every pose of --poses, "
                 "frames numbered by pose (-o out/frame.png: out/frame_0000.png, ...), each with its CameraInfo JSON")
      ->check(app::kNonEmpty);
  app.add_option("--poses", options.poses, "the robot's path for --camera (POSES.csv, as revolve-lidar reads it)")
      ->check(app::kNonEmpty);
  app.add_option("--depth-image", options.depthImage,
                 "with --camera: also a depth image a frame (EXR, float32 distance along the optical axis, +inf for "
                 "nothing; out/depth.exr: out/depth_0000.exr, ...)")
      ->check(app::kNonEmpty);
  if (const std::optional<int> status = app::parseCommandLine(app, argc, argv, "revolve-render")) return *status;
  return app::runTool("revolve-render", options.scene, [&] { run(options); });
}
