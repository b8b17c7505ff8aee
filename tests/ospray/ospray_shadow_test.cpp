// Shadow rays through revolve's occlusion query: a can on a ground disc under a distant light, seen
// from straight above by scivis with shadows. Every ground pixel is dark exactly where the ray from
// it towards the light meets the can (a closed form: a line against a finite cylinder).
#include "ospray_session.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace revolve::ospray_test {
namespace {

constexpr float kCanRadius = 0.5f, kCanHeight = 2.0f, kGroundZ = -0.01f, kGroundRadius = 5.0f;
constexpr int kPixels = 64;
constexpr float kViewSize = 8.0f;  // the orthographic view: x and y in [-4, 4]

enum class Seen { CanTop, Lit, Shadowed, Background };

// What the vertical ray through (x, y) sees. The light travels along (1, 0, -1): from a ground point
// the light is towards (-1, 0, 1), reaching height z at x - (z - ground), so the can (|y| < r)
// shadows the point when [x - (height - ground), x + ground] meets [-w, w], w = sqrt(r^2 - y^2).
Seen seenAt(float x, float y) {
  if (x * x + y * y < kCanRadius * kCanRadius) return Seen::CanTop;
  if (x * x + y * y > kGroundRadius * kGroundRadius) return Seen::Background;
  if (std::fabs(y) >= kCanRadius) return Seen::Lit;
  const float w = std::sqrt(kCanRadius * kCanRadius - y * y);
  const bool shadowed = x - (kCanHeight - kGroundZ) <= w && x + kGroundZ >= -w;
  return shadowed ? Seen::Shadowed : Seen::Lit;
}

TEST(OsprayShadows, ACanShadowsTheGroundWhereItsAnalyticShadowIs) {
  Session session;
  OSPGeometry geometry = newRevolutions({{{0, 0}, {kCanRadius, 0}, {kCanRadius, kCanHeight}, {0, kCanHeight}},
                                         {{0, kGroundZ}, {kGroundRadius, kGroundZ}}});
  OSPGeometricModel model = ospNewGeometricModel(geometry);
  ospCommit(model);
  OSPInstance instance = newInstance(model, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
  OSPWorld world = ospNewWorld();
  OSPData instances = ownedData(&instance, OSP_INSTANCE, 1);
  ospSetObject(world, "instance", instances);
  OSPLight sun = ospNewLight("distant");
  const std::array<float, 3> towards = {1, 0, -1};
  ospSetParam(sun, "direction", OSP_VEC3F, towards.data());
  ospSetFloat(sun, "intensity", 3.0f);
  ospCommit(sun);
  OSPData lights = ownedData(&sun, OSP_LIGHT, 1);
  ospSetObject(world, "light", lights);
  ospCommit(world);

  OSPCamera camera = ospNewCamera("orthographic");
  const std::array<float, 3> position = {0, 0, 10}, direction = {0, 0, -1}, up = {0, 1, 0};
  ospSetParam(camera, "position", OSP_VEC3F, position.data());
  ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera, "up", OSP_VEC3F, up.data());
  ospSetFloat(camera, "height", kViewSize);
  ospSetFloat(camera, "aspect", 1.0f);
  ospCommit(camera);
  OSPRenderer renderer = ospNewRenderer("scivis");
  ospSetBool(renderer, "shadows", true);
  ospSetInt(renderer, "aoSamples", 0);
  const std::array<float, 4> black = {0, 0, 0, 1};
  ospSetParam(renderer, "backgroundColor", OSP_VEC4F, black.data());
  ospCommit(renderer);
  OSPFrameBuffer framebuffer = ospNewFrameBuffer(kPixels, kPixels, OSP_FB_RGBA32F, OSP_FB_COLOR);
  ospCommit(framebuffer);
  ospRenderFrameBlocking(framebuffer, renderer, camera, world);

  // Camera right = +x, up = +y; OSPRay's row 0 is the bottom. A pixel counts when its whole
  // footprint (centre and corners) sees the same thing.
  const auto* rgba = static_cast<const float*>(ospMapFrameBuffer(framebuffer, OSP_FB_COLOR));
  const float pixel = kViewSize / kPixels;
  std::vector<float> lit, shadowed;
  for (int j = 0; j < kPixels; ++j) {
    for (int i = 0; i < kPixels; ++i) {
      const float x = (float(i) + 0.5f) * pixel - kViewSize / 2, y = (float(j) + 0.5f) * pixel - kViewSize / 2;
      const Seen seen = seenAt(x, y);
      bool uniform = true;
      for (const float dx : {-0.5f, 0.5f}) {
        for (const float dy : {-0.5f, 0.5f}) uniform = uniform && seenAt(x + dx * pixel, y + dy * pixel) == seen;
      }
      if (!uniform) continue;
      const float red = rgba[4 * (j * kPixels + i)];
      if (seen == Seen::Lit) lit.push_back(red);
      if (seen == Seen::Shadowed) shadowed.push_back(red);
    }
  }
  ospUnmapFrameBuffer(rgba, framebuffer);
  ASSERT_GT(lit.size(), 100u);
  ASSERT_GT(shadowed.size(), 20u);
  const float darkestLit = *std::min_element(lit.begin(), lit.end());
  const float brightestShadowed = *std::max_element(shadowed.begin(), shadowed.end());
  std::printf("%zu lit ground pixels, darkest %.4f; %zu shadowed, brightest %.4f\n", lit.size(), darkestLit,
              shadowed.size(), brightestShadowed);
  EXPECT_LT(brightestShadowed, 0.5f * darkestLit);
  EXPECT_TRUE(session.takeErrors().empty());

  for (OSPObject object :
       {OSPObject(framebuffer), OSPObject(renderer), OSPObject(camera), OSPObject(lights), OSPObject(sun),
        OSPObject(instances), OSPObject(world), OSPObject(instance), OSPObject(model), OSPObject(geometry)}) {
    ospRelease(object);
  }
}

}  // namespace
}  // namespace revolve::ospray_test
