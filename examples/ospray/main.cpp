// revolve-ospray-scene: renders a scene file through OSPRay, headless, to a PNG or EXR: its
// revolutions as the revolve module's "revolution" geometries (docs/ospray.md).
//   revolve-ospray-scene scenes/patio.json -o out/patio_ospray.png [--renderer scivis|pathtracer]
// Run with the module's folder on LD_LIBRARY_PATH (build/lib for a build tree).
#include "io/output_set.h"
#include "io/scene_file.h"
#include "render/image_output.h"
#include "scene_to_ospray.h"

#include <ospray/ospray.h>
#include <ospray/ospray_util.h>
#include <CLI/CLI.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Options {
  std::string scene, output, renderer = "scivis";
  int width = 0, height = 0, spp = 0;  // 0: the scene's
  unsigned meshSlices = 0;             // > 0: profiles as triangle meshes of this many slices
  int frames = 1;                      // frames rendered; the median time is reported
};

// Every error OSPRay reports counts: an image of a scene OSPRay refused part of is no answer.
int osprayErrors = 0;

void onError(void*, OSPError code, const char* message) {
  std::fprintf(stderr, "revolve-ospray-scene: OSPRay error %d: %s\n", int(code), message);
  ++osprayErrors;
}

int run(const Options& options) {
  using namespace revolve;
  const render::ImageFormat format = render::imageFormatFor(options.output);
  (void)format;
  const io::SceneDescription scene = io::readScene(options.scene);
  const int width = options.width > 0 ? options.width : scene.camera.width.value_or(800);
  const int height = options.height > 0 ? options.height : scene.camera.height.value_or(600);
  const int spp = options.spp > 0 ? options.spp : scene.camera.spp.value_or(16);
  io::OutputSet outputs;
  outputs.addInput("the scene file", options.scene);
  outputs.add("-o", options.output);

  if (ospInit(nullptr, nullptr) != OSP_NO_ERROR) throw std::runtime_error("ospInit failed");
  ospDeviceSetErrorCallback(ospGetCurrentDevice(), onError, nullptr);
  if (ospLoadModule("revolve") != OSP_NO_ERROR) {
    throw std::runtime_error(
        "OSPRay cannot load the revolve module: put the folder holding libospray_module_revolve on LD_LIBRARY_PATH "
        "(build/lib in a build tree; docs/ospray.md)");
  }
  render::Image image;
  double seconds = 0;
  {
    const auto buildStart = std::chrono::steady_clock::now();
    const ospray_example::OsprayScene world(scene, width, height, options.meshSlices);
    const double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    OSPRenderer renderer = ospNewRenderer(options.renderer.c_str());
    ospSetInt(renderer, "pixelSamples", spp);
    // The environment seen behind everything (a sky as its horizon), as revolve-render shows it.
    const io::Rgb& seen = scene.environment.sky ? scene.environment.horizon : scene.environment.color;
    const float background[4] = {float(seen[0]), float(seen[1]), float(seen[2]), 1.0f};
    ospSetParam(renderer, "backgroundColor", OSP_VEC4F, background);
    if (options.renderer == "scivis") {
      ospSetBool(renderer, "shadows", true);
      ospSetInt(renderer, "aoSamples", 1);
    }
    ospCommit(renderer);
    OSPFrameBuffer framebuffer = ospNewFrameBuffer(width, height, OSP_FB_RGBA32F, OSP_FB_COLOR);
    ospCommit(framebuffer);
    // Each frame from a cleared framebuffer, so that every one does the same work.
    std::vector<double> times;
    for (int frame = 0; frame < options.frames; ++frame) {
      ospResetAccumulation(framebuffer);
      const auto start = std::chrono::steady_clock::now();
      ospRenderFrameBlocking(framebuffer, renderer, world.camera(), world.world());
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    seconds = times[times.size() / 2];
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("%s: scene built in %.3f s; surfaces %.1f KiB (%s); process peak resident %.1f MiB\n",
                options.scene.c_str(), buildSeconds, double(world.geometryBytes()) / 1024.0,
                options.meshSlices > 0 ? "triangle meshes" : "revolve shapes", double(usage.ru_maxrss) / 1024.0);
    // OSPRay's row 0 is the bottom; the image's, the top.
    const auto* rgba = static_cast<const float*>(ospMapFrameBuffer(framebuffer, OSP_FB_COLOR));
    image.width = width, image.height = height;
    image.pixels.resize(std::size_t(3) * width * height);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const float* p = rgba + 4 * (std::size_t(height - 1 - y) * width + x);
        float* q = image.pixels.data() + 3 * (std::size_t(y) * width + x);
        q[0] = p[0], q[1] = p[1], q[2] = p[2];
      }
    }
    ospUnmapFrameBuffer(rgba, framebuffer);
    ospRelease(framebuffer);
    ospRelease(renderer);
  }
  ospShutdown();
  if (osprayErrors > 0) {
    throw std::runtime_error("OSPRay reported " + std::to_string(osprayErrors) + " error(s) (above): no image written");
  }
  render::writeImage(outputs.stream(options.output), options.output, image);
  outputs.commit();
  std::printf("%s: %dx%d, %d samples a pixel, OSPRay %s, %.3f s a frame (median of %d)\n", options.output.c_str(),
              width, height, spp, options.renderer.c_str(), seconds, options.frames);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Renders a revolve scene file through OSPRay with the revolve module (docs/ospray.md)"};
  app.add_option("scene", options.scene, "the scene file (JSON)")->required();
  app.add_option("-o,--output", options.output, "the image to write: .png or .exr")->required();
  app.add_option("--renderer", options.renderer, "OSPRay's renderer")->check(CLI::IsMember({"scivis", "pathtracer"}));
  app.add_option("--width", options.width, "image width in pixels (default: the scene's, else 800)")
      ->check(CLI::PositiveNumber);
  app.add_option("--height", options.height, "image height in pixels (default: the scene's, else 600)")
      ->check(CLI::PositiveNumber);
  app.add_option("--spp", options.spp, "samples a pixel (default: the scene's, else 16)")->check(CLI::PositiveNumber);
  app.add_option(
         "--mesh", options.meshSlices,
         "trace each profile as a triangle mesh of this many azimuthal slices instead of exactly (a comparison)")
      ->check(CLI::Range(3u, 65536u));
  app.add_option("--frames", options.frames, "frames to render, reporting the median time (default 1)")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  try {
    return run(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "revolve-ospray-scene: %s\n", error.what());
    return 1;
  }
}
