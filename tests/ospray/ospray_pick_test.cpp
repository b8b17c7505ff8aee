// OSPRay's "revolution" geometry (ospray/) picked through OSPRay itself: a grid of ospPick screen
// positions over profiles with every kind of segment, a spline, and an instance turned and scaled.
// Every picked point must lie on the exact surface, by the test oracle's long-double meridian
// distance (support/reference.h, support/curve_reference.h; independent of revolve's kernel), and
// every miss must be a miss of the oracle too, or a ray the oracle itself calls fragile (within
// rounding of a silhouette, a rim or an apex).
#include "ospray_session.h"
#include "support/curve_reference.h"
#include "support/reference.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <vector>

namespace revolve::ospray_test {
namespace {

using Points = std::vector<std::array<float, 2>>;

// A goblet closed on the axis at both ends: a disc (horizontal, ending on the axis), a vertical
// foot, a sloped waist, a vertical stem, a sloped bowl, a vertical rim, an annulus and a cone to an
// apex on the axis.
const Points kGoblet = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.5f}, {0.4f, 1.0f}, {0.4f, 1.6f},
                        {1.1f, 2.2f}, {1.1f, 2.6f}, {0.6f, 2.6f}, {0.0f, 3.2f}};
// An open ring around it, in the same geometry (revolution 1): an annulus and a wall.
const Points kRing = {{1.6f, 0.3f}, {2.1f, 0.3f}, {2.1f, 0.9f}};
// Two cubic Bezier pieces from the axis to the axis, traced exactly.
const Points kVase = {{0.0f, 0.0f}, {0.9f, 0.0f}, {1.2f, 0.6f}, {0.8f, 1.2f}, {0.4f, 1.8f}, {0.9f, 2.2f}, {0.0f, 2.6f}};

std::vector<Point2> asPoint2(const Points& points) {
  std::vector<Point2> out;
  for (const auto& p : points) out.push_back({p[0], p[1]});
  return out;
}

// An affine map x -> L x + t in double, with its inverse, from OSPRay's column-major affine3f.
struct Placement {
  Affine transform;
  std::array<double, 9> inverse;  // row-major inverse of L
  double minScale;                // smallest singular value of L: object distances <= world / minScale

  std::array<double, 3> toObject(const std::array<double, 3>& world) const {
    const std::array<double, 3> d = {world[0] - transform[9], world[1] - transform[10], world[2] - transform[11]};
    return {inverse[0] * d[0] + inverse[1] * d[1] + inverse[2] * d[2],
            inverse[3] * d[0] + inverse[4] * d[1] + inverse[5] * d[2],
            inverse[6] * d[0] + inverse[7] * d[1] + inverse[8] * d[2]};
  }
  std::array<double, 3> vectorToObject(const std::array<double, 3>& v) const {
    return {inverse[0] * v[0] + inverse[1] * v[1] + inverse[2] * v[2],
            inverse[3] * v[0] + inverse[4] * v[1] + inverse[5] * v[2],
            inverse[6] * v[0] + inverse[7] * v[1] + inverse[8] * v[2]};
  }
};

// Uniform scale s, a turn by `degrees` about the x axis, then a translation.
Placement turnedAndScaled(double s, double degrees, std::array<float, 3> at) {
  const double a = degrees * M_PI / 180.0, c = std::cos(a), sn = std::sin(a);
  Placement p;
  // Columns of L = s * Rx(a): (1, 0, 0), (0, c, sn), (0, -sn, c).
  p.transform = {float(s), 0.0f,           0.0f,         0.0f,  float(s * c), float(s * sn),
                 0.0f,     float(-s * sn), float(s * c), at[0], at[1],        at[2]};
  // The inverse of the float matrix OSPRay was given, up to double rounding.
  const double l00 = p.transform[0], l11 = p.transform[4], l21 = p.transform[5], l12 = p.transform[7],
               l22 = p.transform[8];
  const double det = l11 * l22 - l12 * l21;
  p.inverse = {1.0 / l00, 0.0, 0.0, 0.0, l22 / det, -l12 / det, 0.0, -l21 / det, l11 / det};
  p.minScale = s * (1.0 - 1e-6);  // the float matrix's singular values are s within 2^-23
  return p;
}

Placement translated(std::array<float, 3> at) { return turnedAndScaled(1.0, 0.0, at); }

struct Placed {
  OSPInstance instance;
  OSPGeometricModel model;
  Placement placement;
  std::vector<std::vector<Point2>> profiles;  // per primID; empty for the Bezier one
  std::vector<Point2> bezier;                 // the Bezier control points, for the spline
};

struct Camera {  // OSPRay's orthographic camera (OrthographicCamera.cpp), in double
  std::array<double, 3> origin, du, dv, dir;
  reference::RefRay ray(double sx, double sy) const {
    return {origin[0] + sx * du[0] + sy * dv[0],
            origin[1] + sx * du[1] + sy * dv[1],
            origin[2] + sx * du[2] + sy * dv[2],
            dir[0],
            dir[1],
            dir[2],
            0.0L,
            HUGE_VALL};
  }
};

class OsprayPick : public ::testing::Test {
 protected:
  Session session;
};

TEST_F(OsprayPick, PickedPointsLieOnTheExactSurfaceAndMissesAreMisses) {
  std::vector<Placed> placed;
  auto place = [&](OSPGeometry geometry, const Placement& placement, std::vector<std::vector<Point2>> profiles,
                   std::vector<Point2> bezier) {
    OSPGeometricModel model = ospNewGeometricModel(geometry);
    ospCommit(model);
    placed.push_back(
        {newInstance(model, placement.transform), model, placement, std::move(profiles), std::move(bezier)});
  };
  OSPGeometry gobletAndRing = newRevolutions({kGoblet, kRing});
  OSPGeometry vase = newRevolutions({kVase}, "bezier");
  place(gobletAndRing, translated({-3.5f, 0.0f, 0.0f}), {asPoint2(kGoblet), asPoint2(kRing)}, {});
  place(vase, translated({0.0f, 0.0f, 0.0f}), {}, asPoint2(kVase));
  place(gobletAndRing, turnedAndScaled(0.8, 25.0, {3.5f, 0.5f, 0.4f}), {asPoint2(kGoblet), asPoint2(kRing)}, {});
  for (const ReportedError& error : session.takeErrors()) ADD_FAILURE() << "OSPRay error: " << error.message;

  std::vector<OSPInstance> instances;
  for (const Placed& p : placed) instances.push_back(p.instance);
  OSPWorld world = ospNewWorld();
  OSPData instanceData = ownedData(instances.data(), OSP_INSTANCE, instances.size());
  ospSetObject(world, "instance", instanceData);
  ospCommit(world);

  // Looking along +y, tilted 20 degrees down so the discs and annuli face the camera.
  const int width = 120, height = 60;
  const float tilt = 20.0f * float(M_PI) / 180.0f;
  const std::array<float, 3> position = {0.0f, -10.0f, 4.0f};
  const std::array<float, 3> direction = {0.0f, std::cos(tilt), -std::sin(tilt)};
  const std::array<float, 3> up = {0.0f, 0.0f, 1.0f};
  const float viewHeight = 6.5f, aspect = float(width) / float(height);
  OSPCamera camera = ospNewCamera("orthographic");
  ospSetParam(camera, "position", OSP_VEC3F, position.data());
  ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera, "up", OSP_VEC3F, up.data());
  ospSetFloat(camera, "height", viewHeight);
  ospSetFloat(camera, "aspect", aspect);
  ospCommit(camera);
  OSPRenderer renderer = ospNewRenderer("scivis");
  ospCommit(renderer);
  OSPFrameBuffer framebuffer = ospNewFrameBuffer(width, height, OSP_FB_RGBA8, OSP_FB_COLOR);
  ospCommit(framebuffer);

  // The camera's frame as OrthographicCamera::commit makes it (direction is unit already).
  const double c = std::cos(double(tilt)), s = std::sin(double(tilt));
  const double w = double(viewHeight) * aspect, h = viewHeight;
  Camera frame;
  frame.dir = {0.0, c, -s};
  frame.du = {w, 0.0, 0.0};
  frame.dv = {0.0, s * h, c * h};
  frame.origin = {position[0] - 0.5 * w, position[1] - 0.5 * s * h, position[2] - 0.5 * c * h};

  // A picked point is org + t dir in float: t from revolve (the exact root, rounded once), the
  // object-space ray Embree made by the instance's float transform (each coordinate a 3-term dot
  // product plus a translation: within 4 ulps of the largest term), and OSPRay's org + t * dir (2
  // roundings). Each contributes at most a few units of 2^-24 of the largest magnitude involved,
  // the ray's reach R = |org| + t |dir| + |translation|: the point lies within 16 * 2^-24 * R of
  // the surface (world units; divided by the smallest scale in object units).
  const double unitRoundoff = 0x1p-24;
  std::size_t hits = 0, misses = 0, fragileMisses = 0;
  std::array<std::size_t, 3> hitsPerInstance{};
  std::array<std::size_t, 2> revolutionHits{};  // of the goblet and the ring, in one geometry
  double worstRatio = 0.0;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const float sx = (float(i) + 0.5f) / float(width), sy = (float(j) + 0.5f) / float(height);
      OSPPickResult pick;
      ospPick(&pick, framebuffer, renderer, camera, world, sx, sy);
      const reference::RefRay worldRay = frame.ray(sx, sy);
      if (pick.hasHit) {
        ++hits;
        std::size_t k = 0;
        while (k < placed.size() && placed[k].instance != pick.instance) ++k;
        ASSERT_LT(k, placed.size()) << "pick at (" << sx << ", " << sy << ") names an instance not in the world";
        EXPECT_EQ(pick.model, placed[k].model);
        ++hitsPerInstance[k];
        const Placed& p = placed[k];
        const std::array<double, 3> worldPoint = {pick.worldPosition[0], pick.worldPosition[1], pick.worldPosition[2]};
        const std::array<double, 3> o = p.placement.toObject(worldPoint);
        long double distance;
        if (p.bezier.empty()) {
          ASSERT_LT(pick.primID, p.profiles.size());
          distance = reference::meridianDistance(p.profiles[pick.primID], o[0], o[1], o[2]);
        } else {
          EXPECT_EQ(pick.primID, 0u);
          distance = reference::curveMeridianDistance(p.bezier, o[0], o[1], o[2]);
        }
        const double t = (worldPoint[1] - double(worldRay.oy)) / double(worldRay.dy);
        // On the camera ray as reconstructed here (so that the misses below test OSPRay's rays).
        const double offRay = std::hypot(worldPoint[0] - double(worldRay.ox + t * worldRay.dx),
                                         worldPoint[2] - double(worldRay.oz + t * worldRay.dz));
        EXPECT_LT(offRay, 1e-4) << "pick at (" << sx << ", " << sy << ") is not on the camera ray rebuilt here";
        if (k == 0) ++revolutionHits[pick.primID % 2];
        const double reach = std::hypot(double(worldRay.ox), double(worldRay.oy), double(worldRay.oz)) + std::abs(t) +
                             std::hypot(double(p.placement.transform[9]), double(p.placement.transform[10]),
                                        double(p.placement.transform[11]));
        const double bound = 16.0 * unitRoundoff * reach / p.placement.minScale;
        worstRatio = std::max(worstRatio, double(distance) / bound);
        EXPECT_LE(double(distance), bound)
            << "pick at (" << sx << ", " << sy << ") on instance " << k << " primID " << pick.primID << ": ("
            << worldPoint[0] << ", " << worldPoint[1] << ", " << worldPoint[2] << ")";
        ospRelease(pick.instance);
        ospRelease(pick.model);
      } else {
        ++misses;
        // A miss: no placed revolution meets the camera's ray, or the ray passes within rounding
        // of one (a nudge of 2^-20 of the scene's size: the float camera ray's own error).
        for (const Placed& p : placed) {
          const std::array<double, 3> origin =
              p.placement.toObject({double(worldRay.ox), double(worldRay.oy), double(worldRay.oz)});
          const std::array<double, 3> dir =
              p.placement.vectorToObject({double(worldRay.dx), double(worldRay.dy), double(worldRay.dz)});
          const reference::RefRay ray{origin[0], origin[1], origin[2], dir[0], dir[1], dir[2], 0.0L, HUGE_VALL};
          const long double nudge = 0x1p-20L * 16.0L, size = 16.0L;
          if (p.bezier.empty()) {
            for (const auto& profile : p.profiles) {
              if (!reference::intersectProfile(profile, ray)) continue;
              const bool fragile = reference::verdictIsFragile(profile, ray, nudge, size);
              fragileMisses += fragile;
              EXPECT_TRUE(fragile) << "miss at (" << sx << ", " << sy << ") but the oracle hits a profile";
            }
          } else if (reference::intersectCurve(p.bezier, ray)) {
            const bool fragile = reference::curveVerdictIsFragile(p.bezier, ray, nudge, size);
            fragileMisses += fragile;
            EXPECT_TRUE(fragile) << "miss at (" << sx << ", " << sy << ") but the oracle hits the vase";
          }
        }
      }
    }
  }
  std::printf(
      "picks: %zu hits (per instance %zu, %zu, %zu), %zu misses (%zu within rounding of a silhouette); "
      "worst distance / bound %.3g\n",
      hits, hitsPerInstance[0], hitsPerInstance[1], hitsPerInstance[2], misses, fragileMisses, worstRatio);
  for (std::size_t k = 0; k < placed.size(); ++k) EXPECT_GT(hitsPerInstance[k], 100u) << "instance " << k;
  EXPECT_GT(revolutionHits[0], 100u);
  EXPECT_GT(revolutionHits[1], 50u);
  for (const ReportedError& error : session.takeErrors()) ADD_FAILURE() << "OSPRay error: " << error.message;

  ospRelease(framebuffer);
  ospRelease(renderer);
  ospRelease(camera);
  ospRelease(instanceData);
  ospRelease(world);
  for (Placed& p : placed) {
    ospRelease(p.instance);
    ospRelease(p.model);
  }
  ospRelease(gobletAndRing);
  ospRelease(vase);
}

}  // namespace
}  // namespace revolve::ospray_test
