// What OSPRay's renderers read from a "revolution" hit (the module's postIntersect), as OSPRay's
// debug renderer shows it: texture coordinates (revolve's u, v) and the normals on a cylinder
// wall, whose closed forms say what each must be (at the hit (x, y, z), u = atan2(y, x) / 2 pi in
// [0, 1), v = z / height, Ng = Ns = (x, y, 0) / radius), and the curve's shading normals on a
// spline traced as its polyline.
#include "ospray_session.h"

#include <gtest/gtest.h>

#include <revolve/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <vector>

namespace revolve::ospray_test {
namespace {

// One "revolution" geometry (`geometry`, consumed) seen by an orthographic camera along +y from
// (0, -5, 1), 2.5 high and wide, rendered by OSPRay's debug renderer in the given views: each
// view's RGBA and the depth, one sample at each of 64 x 64 pixel centres, row 0 at the bottom.
struct DebugViews {
  static constexpr int kPixels = 64;
  static constexpr float kViewHeight = 2.5f;
  static constexpr std::array<float, 3> kPosition = {0.0f, -5.0f, 1.0f};
  std::vector<std::vector<float>> rgba;
  std::vector<float> depth;

  // The hit of pixel (i, j) at depth t, in world (= object) space.
  static std::array<double, 3> hitPoint(int i, int j, double t) {
    const double sx = (i + 0.5) / kPixels, sy = (j + 0.5) / kPixels;
    return {kPosition[0] + (sx - 0.5) * kViewHeight, kPosition[1] + t, kPosition[2] + (sy - 0.5) * kViewHeight};
  }
};

DebugViews renderDebugViews(OSPGeometry geometry, const std::vector<const char*>& methods) {
  OSPGeometricModel model = ospNewGeometricModel(geometry);
  ospCommit(model);
  OSPInstance instance = newInstance(model, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
  OSPWorld world = ospNewWorld();
  OSPData instances = ownedData(&instance, OSP_INSTANCE, 1);
  ospSetObject(world, "instance", instances);
  ospCommit(world);
  const std::array<float, 3> direction = {0, 1, 0}, up = {0, 0, 1};
  OSPCamera camera = ospNewCamera("orthographic");
  ospSetParam(camera, "position", OSP_VEC3F, DebugViews::kPosition.data());
  ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera, "up", OSP_VEC3F, up.data());
  ospSetFloat(camera, "height", DebugViews::kViewHeight);
  ospSetFloat(camera, "aspect", 1.0f);
  ospCommit(camera);
  DebugViews views;
  const int n = DebugViews::kPixels;
  for (const char* method : methods) {
    OSPRenderer renderer = ospNewRenderer("debug");
    ospSetParam(renderer, "method", OSP_STRING, method);
    ospSetInt(renderer, "pixelFilter", OSP_PIXELFILTER_POINT);
    ospCommit(renderer);
    OSPFrameBuffer framebuffer = ospNewFrameBuffer(n, n, OSP_FB_RGBA32F, OSP_FB_COLOR | OSP_FB_DEPTH);
    ospCommit(framebuffer);
    ospRenderFrameBlocking(framebuffer, renderer, camera, world);
    const auto* rgba = static_cast<const float*>(ospMapFrameBuffer(framebuffer, OSP_FB_COLOR));
    views.rgba.emplace_back(rgba, rgba + 4 * std::size_t(n) * n);
    ospUnmapFrameBuffer(rgba, framebuffer);
    const auto* depth = static_cast<const float*>(ospMapFrameBuffer(framebuffer, OSP_FB_DEPTH));
    views.depth.assign(depth, depth + std::size_t(n) * n);
    ospUnmapFrameBuffer(depth, framebuffer);
    ospRelease(framebuffer);
    ospRelease(renderer);
  }
  ospRelease(camera);
  ospRelease(instances);
  ospRelease(world);
  ospRelease(instance);
  ospRelease(model);
  ospRelease(geometry);
  return views;
}

// A spline traced as its polyline (`tolerance`) shades with the curve's normal: for a hit on the
// surface of the chord from curve parameter T0 to T1, the normal of the curve point B(T) whose
// projection on the chord is the hit's (T found here by bisection in long double; the library
// finds it by safeguarded Newton steps), not the chord's own normal.
TEST(OsprayAttributes, ShadingNormalsOfASplinePolylineAreTheCurves) {
  Session session;
  // One quadratic Bezier piece bulging out from (1, 0) to (1, 2), to r = 1.5 at z = 1.
  const std::array<Point2, 3> control = {{{1, 0}, {2, 1}, {1, 2}}};
  const float tolerance = 0.02f;
  OSPGeometry bulge = ospNewGeometry("revolution");
  const std::array<float, 6> points = {1, 0, 2, 1, 1, 2};
  OSPData data = ownedData(points.data(), OSP_VEC2F, 3);
  ospSetObject(bulge, "profile", data);
  ospRelease(data);
  ospSetParam(bulge, "spline", OSP_STRING, "quadratic");
  ospSetFloat(bulge, "tolerance", tolerance);
  ospCommit(bulge);
  const DebugViews views = renderDebugViews(bulge, {"Ns", "Ng"});
  // The polyline the module traces: the library's fitting (its rule is tested with the library);
  // what is tested here is the normal OSPRay shades a hit on it with.
  const Profile polyline =
      Profile::fromCurve(Spline(SplineKind::quadratic, std::span<const Point2>(control)), double(tolerance));
  const std::span<const Point2> vertex = polyline.points();
  const std::span<const double> T = polyline.curveParameters();
  const auto curve = [&](long double t) {
    const long double a = (1 - t) * (1 - t), b = 2 * t * (1 - t), c = t * t;
    return std::array<long double, 2>{a * control[0].r + b * control[1].r + c * control[2].r,
                                      a * control[0].z + b * control[1].z + c * control[2].z};
  };

  const double bound = 0x1p-14;  // float hit points and normals, the library's Newton to 2^-30 of a segment
  std::size_t hits = 0;
  double worstNs = 0, largestNgNs = 0;
  const int n = DebugViews::kPixels;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const std::size_t pixel = std::size_t(j) * n + i;
      if (!std::isfinite(views.depth[pixel])) continue;
      ++hits;
      const std::array<double, 3> p = DebugViews::hitPoint(i, j, views.depth[pixel]);
      const double rho = std::hypot(p[0], p[1]), z = p[2];
      // The chord the hit lies on: the nearest, and where along it.
      std::size_t k = 0;
      double bestDistance = INFINITY, s = 0;
      for (std::size_t q = 0; q + 1 < vertex.size(); ++q) {
        const double er = vertex[q + 1].r - vertex[q].r, ez = vertex[q + 1].z - vertex[q].z;
        const double f =
            std::clamp(((rho - vertex[q].r) * er + (z - vertex[q].z) * ez) / (er * er + ez * ez), 0.0, 1.0);
        const double d = std::hypot(vertex[q].r + f * er - rho, vertex[q].z + f * ez - z);
        if (d < bestDistance) bestDistance = d, k = q, s = f;
      }
      const long double er = vertex[k + 1].r - vertex[k].r, ez = vertex[k + 1].z - vertex[k].z;
      long double lo = T[k], hi = T[k + 1];
      for (int step = 0; step < 80; ++step) {
        const long double mid = (lo + hi) / 2;
        const auto b = curve(mid);
        const long double f = ((b[0] - vertex[k].r) * er + (b[1] - vertex[k].z) * ez) / (er * er + ez * ez);
        (f < s ? lo : hi) = mid;
      }
      const long double t = (lo + hi) / 2;
      // The tangent B'(t); the normal to the right of travel, (dz, -dr), outwards for a rising curve.
      const long double dr = 2 * (1 - t) * (control[1].r - control[0].r) + 2 * t * (control[2].r - control[1].r);
      const long double dz = 2 * (1 - t) * (control[1].z - control[0].z) + 2 * t * (control[2].z - control[1].z);
      const long double length = std::hypot(dr, dz);
      const double nr = double(dz / length), nz = double(-dr / length);
      const std::array<double, 3> expected = {std::abs(nr * p[0] / rho), std::abs(nr * p[1] / rho), std::abs(nz)};
      for (int c = 0; c < 3; ++c) {
        worstNs = std::max(worstNs, std::abs(views.rgba[0][4 * pixel + c] - expected[c]));
        largestNgNs =
            std::max(largestNgNs, double(std::abs(views.rgba[1][4 * pixel + c] - views.rgba[0][4 * pixel + c])));
      }
    }
  }
  std::printf("%zu hits on %zu chords: worst error of Ns %.3g (bound %.3g); Ng and Ns differ by up to %.3g\n", hits,
              vertex.size() - 1, worstNs, bound, largestNgNs);
  EXPECT_GT(hits, std::size_t(n) * n / 4);
  EXPECT_LE(worstNs, bound);
  EXPECT_GT(largestNgNs, 0.01);  // the chords' own normals would fail the check above
  EXPECT_TRUE(session.takeErrors().empty());
}

TEST(OsprayAttributes, TextureCoordinatesAndNormalsOfACylinderWall) {
  Session session;
  const float radius = 1.0f, height = 2.0f;
  const DebugViews views = renderDebugViews(newRevolutions({{{radius, 0.0f}, {radius, height}}}),  // a wall only
                                            {"texCoord", "Ng", "Ns"});
  // The hit point from the pixel's ray and OSPRay's depth is within a few units of 2^-24 of the
  // scene's size (5) of the exact one: u, v and the normal's components move by as little (u by
  // that over 2 pi r, v over the height, the normal over the radius); 2^-18 leaves room.
  const double bound = 0x1p-18;
  std::size_t hits = 0;
  double worstU = 0, worstV = 0, worstN = 0;
  const int n = DebugViews::kPixels;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const std::size_t pixel = std::size_t(j) * n + i;
      if (!std::isfinite(views.depth[pixel])) continue;
      ++hits;
      const std::array<double, 3> p = DebugViews::hitPoint(i, j, views.depth[pixel]);
      double u = std::atan2(p[1], p[0]) / (2 * M_PI);
      if (u < 0) u += 1;
      const double v = p[2] / height;
      worstU = std::max(worstU, std::abs(views.rgba[0][4 * pixel] - u));
      worstV = std::max(worstV, std::abs(views.rgba[0][4 * pixel + 1] - v));
      // The debug renderer shows |Ng| and |Ns| (normalised, component-wise absolute values).
      const std::array<double, 3> normal = {std::abs(p[0] / radius), std::abs(p[1] / radius), 0.0};
      for (int c = 0; c < 3; ++c) {
        worstN = std::max(worstN, std::abs(views.rgba[1][4 * pixel + c] - normal[c]));
        worstN = std::max(worstN, std::abs(views.rgba[2][4 * pixel + c] - normal[c]));
      }
    }
  }
  std::printf("%zu hits: worst error of u %.3g, v %.3g, normal components %.3g (bound %.3g)\n", hits, worstU, worstV,
              worstN, bound);
  EXPECT_GT(hits, std::size_t(n) * n / 2);
  EXPECT_LE(worstU, bound);
  EXPECT_LE(worstV, bound);
  EXPECT_LE(worstN, bound);
  EXPECT_TRUE(session.takeErrors().empty());
}

}  // namespace
}  // namespace revolve::ospray_test
