// What OSPRay's renderers read from a "revolution" hit (the module's postIntersect), as OSPRay's
// debug renderer shows it: texture coordinates (revolve's u, v) and the normals, on a cylinder
// wall whose closed forms say what each must be: at the hit (x, y, z), u = atan2(y, x) / 2 pi in
// [0, 1), v = z / height (arc length along the wall), and Ng = Ns = (x, y, 0) / radius.
#include "ospray_session.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace revolve::ospray_test {
namespace {

TEST(OsprayAttributes, TextureCoordinatesAndNormalsOfACylinderWall) {
  Session session;
  const float radius = 1.0f, height = 2.0f;
  OSPGeometry wall = newRevolutions({{{radius, 0.0f}, {radius, height}}});  // open: a wall only
  OSPGeometricModel model = ospNewGeometricModel(wall);
  ospCommit(model);
  OSPInstance instance = newInstance(model, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
  OSPWorld world = ospNewWorld();
  OSPData instances = ownedData(&instance, OSP_INSTANCE, 1);
  ospSetObject(world, "instance", instances);
  ospCommit(world);

  // An orthographic camera looking along +y at the wall's front half (OrthographicCamera: the
  // image spans position -+ (width / 2, height / 2) along x and z).
  const int width = 64, pixelsHigh = 64;
  const std::array<float, 3> position = {0.0f, -5.0f, 1.0f}, direction = {0, 1, 0}, up = {0, 0, 1};
  const float viewHeight = 2.5f;
  OSPCamera camera = ospNewCamera("orthographic");
  ospSetParam(camera, "position", OSP_VEC3F, position.data());
  ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera, "up", OSP_VEC3F, up.data());
  ospSetFloat(camera, "height", viewHeight);
  ospSetFloat(camera, "aspect", 1.0f);
  ospCommit(camera);

  struct Frame {
    std::vector<float> rgba, depth;
  };
  const auto render = [&](const char* method) {
    OSPRenderer renderer = ospNewRenderer("debug");
    ospSetParam(renderer, "method", OSP_STRING, method);
    ospSetInt(renderer, "pixelFilter", OSP_PIXELFILTER_POINT);
    ospCommit(renderer);
    OSPFrameBuffer framebuffer = ospNewFrameBuffer(width, pixelsHigh, OSP_FB_RGBA32F, OSP_FB_COLOR | OSP_FB_DEPTH);
    ospCommit(framebuffer);
    ospRenderFrameBlocking(framebuffer, renderer, camera, world);
    Frame frame;
    const auto* rgba = static_cast<const float*>(ospMapFrameBuffer(framebuffer, OSP_FB_COLOR));
    frame.rgba.assign(rgba, rgba + 4 * std::size_t(width) * pixelsHigh);
    ospUnmapFrameBuffer(rgba, framebuffer);
    const auto* depth = static_cast<const float*>(ospMapFrameBuffer(framebuffer, OSP_FB_DEPTH));
    frame.depth.assign(depth, depth + std::size_t(width) * pixelsHigh);
    ospUnmapFrameBuffer(depth, framebuffer);
    ospRelease(framebuffer);
    ospRelease(renderer);
    return frame;
  };
  const Frame texCoord = render("texCoord"), ng = render("Ng"), ns = render("Ns");

  // The hit point from the pixel's ray and OSPRay's depth is within a few units of 2^-24 of the
  // scene's size (5) of the exact one: u, v and the normal's components move by as little (u by
  // that over 2 pi r, v over the height, the normal over the radius); 2^-18 leaves room.
  const double bound = 0x1p-18;
  std::size_t hits = 0;
  double worstU = 0, worstV = 0, worstN = 0;
  for (int j = 0; j < pixelsHigh; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t pixel = std::size_t(j) * width + i;  // row 0 at the bottom
      const double t = texCoord.depth[pixel];
      if (!std::isfinite(t)) continue;
      ++hits;
      const double sx = (i + 0.5) / width, sy = (j + 0.5) / pixelsHigh;
      const double x = position[0] + (sx - 0.5) * viewHeight, z = position[2] + (sy - 0.5) * viewHeight;
      const double y = position[1] + t;
      double u = std::atan2(y, x) / (2 * M_PI);
      if (u < 0) u += 1;
      const double v = z / height;
      worstU = std::max(worstU, std::abs(texCoord.rgba[4 * pixel] - u));
      worstV = std::max(worstV, std::abs(texCoord.rgba[4 * pixel + 1] - v));
      // The debug renderer shows |Ng| and |Ns| (normalised, component-wise absolute values).
      const std::array<double, 3> normal = {std::abs(x / radius), std::abs(y / radius), 0.0};
      for (int c = 0; c < 3; ++c) {
        worstN = std::max(worstN, std::abs(ng.rgba[4 * pixel + c] - normal[c]));
        worstN = std::max(worstN, std::abs(ns.rgba[4 * pixel + c] - normal[c]));
      }
    }
  }
  std::printf("%zu hits: worst error of u %.3g, v %.3g, normal components %.3g (bound %.3g)\n", hits, worstU, worstV,
              worstN, bound);
  EXPECT_GT(hits, std::size_t(width) * pixelsHigh / 2);
  EXPECT_LE(worstU, bound);
  EXPECT_LE(worstV, bound);
  EXPECT_LE(worstN, bound);
  EXPECT_TRUE(session.takeErrors().empty());

  ospRelease(camera);
  ospRelease(instances);
  ospRelease(world);
  ospRelease(instance);
  ospRelease(model);
  ospRelease(wall);
}

}  // namespace
}  // namespace revolve::ospray_test
