// The patio through OSPRay (revolve-ospray-scene's world) against revolve-render's own view of it:
// per pixel, the object OSPRay's ID buffer shows must be the one revolve's picking finds through
// the same pixel's centre (platform/scene/picking.h), except on silhouette pixels, and OSPRay's
// depth buffer must give the exact distance revolve finds.
#include "io/scene_file.h"
#include "ospray_session.h"
#include "scene/embree_scene.h"
#include "scene/picking.h"
#include "scene_to_ospray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

namespace revolve::ospray_test {
namespace {

constexpr std::uint32_t kNothing = 0xffffffffu;  // OSPRay's ID for no hit, and revolve's here

TEST(OsprayPatio, PrimaryVisibilityAndDepthAgreeWithRevolve) {
  Session session;
  const io::SceneDescription description = io::readScene(REVOLVE_SOURCE_DIR "/scenes/patio.json");
  const int width = 160, height = 120;

  // revolve: one ray through each pixel's centre, as revolve-render's --pick finds the object.
  const scene::EmbreeScene built(description, {});
  std::vector<std::uint32_t> revolveId(std::size_t(width) * height, kNothing);
  std::vector<float> revolveDistance(revolveId.size(), INFINITY);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (const std::optional<scene::Pick> picked = scene::pick(description, built, width, height, x, y)) {
        revolveId[std::size_t(y) * width + x] = picked->object;
        revolveDistance[std::size_t(y) * width + x] = picked->distance;
      }
    }
  }

  // OSPRay: one sample a pixel at its centre (the point pixel filter). The object under each
  // pixel from scivis' ID channel. The depth from the debug renderer ("eyeLight": the camera ray's
  // t): Debian's OSPRay 3.2 is built without volumes, and its scivis writes depth only with them
  // (SciVis.ispc sets a sample's z under OSPRAY_ENABLE_VOLUMES).
  const ospray_example::OsprayScene world(description, width, height);
  const auto render = [&](const char* type, std::uint32_t channel) {
    OSPRenderer renderer = ospNewRenderer(type);
    ospSetInt(renderer, "pixelSamples", 1);
    ospSetInt(renderer, "pixelFilter", OSP_PIXELFILTER_POINT);
    ospCommit(renderer);
    OSPFrameBuffer framebuffer = ospNewFrameBuffer(width, height, OSP_FB_RGBA32F, OSP_FB_COLOR | channel);
    ospCommit(framebuffer);
    ospRenderFrameBlocking(framebuffer, renderer, world.camera(), world.world());
    const auto* mapped =
        static_cast<const std::uint32_t*>(ospMapFrameBuffer(framebuffer, OSPFrameBufferChannel(channel)));
    std::vector<std::uint32_t> words(mapped, mapped + std::size_t(width) * height);  // ID or float bits
    ospUnmapFrameBuffer(mapped, framebuffer);
    ospRelease(framebuffer);
    ospRelease(renderer);
    return words;
  };
  const std::vector<std::uint32_t> ids = render("scivis", OSP_FB_ID_INSTANCE);
  const std::vector<std::uint32_t> depthBits = render("debug", OSP_FB_DEPTH);
  std::vector<float> depth(depthBits.size());
  std::memcpy(depth.data(), depthBits.data(), depth.size() * sizeof(float));

  // A silhouette pixel: revolve sees another object (or nothing) at one of its 8 neighbours, so
  // that a camera ray rounded otherwise may cross to it.
  const auto silhouette = [&](int x, int y) {
    const std::uint32_t id = revolveId[std::size_t(y) * width + x];
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
        if (revolveId[std::size_t(ny) * width + nx] != id) return true;
      }
    }
    return false;
  };
  std::size_t compared = 0, silhouettes = 0, hits = 0, disagreements = 0;
  std::vector<double> relativeDepthError;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t mine = std::size_t(y) * width + x;
      const std::size_t theirs = std::size_t(height - 1 - y) * width + x;  // OSPRay's row 0 is the bottom
      if (silhouette(x, y)) {
        ++silhouettes;
        continue;
      }
      ++compared;
      if (ids[theirs] != revolveId[mine]) {
        ++disagreements;
        ADD_FAILURE() << "pixel (" << x << ", " << y << "): OSPRay shows " << ids[theirs] << ", revolve "
                      << revolveId[mine];
        continue;
      }
      if (revolveId[mine] == kNothing) continue;
      ++hits;
      relativeDepthError.push_back(std::abs(double(depth[theirs]) - revolveDistance[mine]) / revolveDistance[mine]);
    }
  }
  std::sort(relativeDepthError.begin(), relativeDepthError.end());
  const double medianDepthError = relativeDepthError[relativeDepthError.size() / 2];
  const double worstDepthError = relativeDepthError.back();
  std::printf(
      "%zu pixels compared (%zu on silhouettes left out), %zu disagree; depth of %zu hits: relative error "
      "median %.3g, worst %.3g\n",
      compared, silhouettes, disagreements, hits, medianDepthError, worstDepthError);
  EXPECT_GT(hits, std::size_t(width) * height / 2);
  // The two camera rays through a pixel's centre are the same ray rounded by two float
  // computations (OSPRay's camera and revolve's), each direction within a few units of 2^-24 of
  // the other, so a hit moves by that fraction of its distance divided by the cosine of its
  // incidence: 2^-16 allows incidences up to about 89.6 degrees, grazing enough that such a pixel
  // borders a silhouette anyway.
  const double bound = 0x1p-16;
  EXPECT_LE(worstDepthError, bound);
  EXPECT_TRUE(session.takeErrors().empty());
}

}  // namespace
}  // namespace revolve::ospray_test
