// Worlds that use a "revolution" geometry in ways other than as a plain visible object: as a
// group's clipping geometry, and re-committed with fewer profiles while a committed world still holds it. Expected
// answers are the analytic surfaces of the cylinders involved.
#include "ospray_session.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace revolve::ospray_test {
namespace {

using Points = std::vector<std::array<float, 2>>;

// A closed cylinder: radius 1, z in [0, 2].
const Points kCan = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 2.0f}, {0.0f, 2.0f}};
// A ring (no cap): r in [1.6, 2.1], z in [0.3, 0.9].
const Points kRing = {{1.6f, 0.3f}, {2.1f, 0.3f}, {2.1f, 0.9f}};
const Affine kIdentity = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};

// An orthographic view from y = -10 along +y, 6 units high: the screen point (sx, sy) looks along
// the line x = 6 (sx - 0.5), z = 1 + 6 (sy - 0.5).
class OsprayView : public ::testing::Test {
 protected:
  OsprayView() {
    camera = ospNewCamera("orthographic");
    const std::array<float, 3> position = {0, -10, 1}, direction = {0, 1, 0}, up = {0, 0, 1};
    ospSetParam(camera, "position", OSP_VEC3F, position.data());
    ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
    ospSetParam(camera, "up", OSP_VEC3F, up.data());
    ospSetFloat(camera, "height", 6.0f);
    ospSetFloat(camera, "aspect", 1.0f);
    ospCommit(camera);
    renderer = ospNewRenderer("scivis");
    ospCommit(renderer);
    framebuffer = ospNewFrameBuffer(16, 16, OSP_FB_RGBA8, OSP_FB_COLOR);
    ospCommit(framebuffer);
  }
  ~OsprayView() override {
    ospRelease(framebuffer);
    ospRelease(renderer);
    ospRelease(camera);
  }

  struct Picked {
    std::array<float, 3> position;
    std::uint32_t primID;
  };
  // What ospPick finds along the line through world (x, z); nothing: a miss.
  std::optional<Picked> pickAt(OSPWorld world, float x, float z) {
    OSPPickResult pick;
    ospPick(&pick, framebuffer, renderer, camera, world, 0.5f + x / 6.0f, 0.5f + (z - 1.0f) / 6.0f);
    if (!pick.hasHit) return std::nullopt;
    ospRelease(pick.instance);
    ospRelease(pick.model);
    return Picked{{pick.worldPosition[0], pick.worldPosition[1], pick.worldPosition[2]}, pick.primID};
  }

  static OSPWorld worldOf(const std::vector<OSPInstance>& instances) {
    OSPWorld world = ospNewWorld();
    OSPData data = ownedData(instances.data(), OSP_INSTANCE, instances.size());
    ospSetObject(world, "instance", data);
    ospRelease(data);
    ospCommit(world);
    return world;
  }

  Session session;
  OSPCamera camera;
  OSPRenderer renderer;
  OSPFrameBuffer framebuffer;
};

// An instance of a group whose clipping geometry is `geometry`, moved by (x, y, 0).
OSPInstance clippingInstance(OSPGeometry geometry, float x, float y) {
  OSPGeometricModel model = ospNewGeometricModel(geometry);
  ospCommit(model);
  OSPGroup group = ospNewGroup();
  OSPData models = ownedData(&model, OSP_GEOMETRIC_MODEL, 1);
  ospSetObject(group, "clippingGeometry", models);
  ospCommit(group);
  OSPInstance instance = ospNewInstance(group);
  const Affine moved = {1, 0, 0, 0, 1, 0, 0, 0, 1, x, y, 0};
  ospSetParam(instance, "transform", OSP_AFFINE3F, moved.data());
  ospCommit(instance);
  ospRelease(models);
  ospRelease(group);
  ospRelease(model);
  return instance;
}

// A revolution as clipping geometry once made the renderer index the clipping group's (empty)
// models and crash. It clips as OSPRay's own geometries do: the can's surface inside the clipper (a
// closed cylinder of radius 0.5 about the line x = 0, y = -1) is gone, so the ray through x = 0
// meets the can's back wall at y = +1; through x = 0.8, the can's front at y = -0.6 lies outside the
// clipper (0.89 from its axis) and stays. A clipper beside the can (x = 2) clips nothing.
TEST_F(OsprayView, ARevolutionAsClippingGeometryClips) {
  OSPGeometry can = newRevolutions({kCan});
  OSPGeometry clipper = newRevolutions({{{0.0f, -1.0f}, {0.5f, -1.0f}, {0.5f, 3.0f}, {0.0f, 3.0f}}});
  OSPGeometricModel model = ospNewGeometricModel(can);
  ospCommit(model);
  struct Case {
    float clipperX, clipperY;
    float frontY;  // the y picked through x = 0, z = 1
  };
  for (const Case c : {Case{2.0f, 0.0f, -1.0f}, Case{0.0f, -1.0f, 1.0f}}) {
    const std::vector<OSPInstance> instances = {newInstance(model, kIdentity),
                                                clippingInstance(clipper, c.clipperX, c.clipperY)};
    OSPWorld world = worldOf(instances);
    ospRenderFrameBlocking(framebuffer, renderer, camera, world);
    EXPECT_FALSE(pickAt(world, 2.0f, 1.0f)) << "clipper at x = " << c.clipperX << ": nothing visible at x = 2";
    const std::optional<Picked> middle = pickAt(world, 0.0f, 1.0f);
    ASSERT_TRUE(middle) << "clipper at x = " << c.clipperX;
    EXPECT_NEAR(middle->position[1], c.frontY, 1e-5f) << "clipper at (" << c.clipperX << ", " << c.clipperY << ")";
    const std::optional<Picked> side = pickAt(world, 0.8f, 1.0f);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->position[1], -0.6f, 1e-5f) << "-sqrt(1 - 0.8^2): the can's front, unclipped";
    EXPECT_TRUE(session.takeErrors().empty());
    ospRelease(world);
    for (OSPInstance instance : instances) ospRelease(instance);
  }
  ospRelease(model);
  ospRelease(clipper);
  ospRelease(can);
}

// OSPRay asks that a group and world holding a re-committed geometry be re-committed; one that is
// not still holds Embree's bounds of the old revolutions. A ray reaching a revolution no longer
// there misses (it once read past the end of the geometry's list).
TEST_F(OsprayView, FewerProfilesWithoutRecommittingTheWorld) {
  OSPGeometry geometry = newRevolutions({kCan, kRing});
  OSPGeometricModel model = ospNewGeometricModel(geometry);
  ospCommit(model);
  const std::vector<OSPInstance> instances = {newInstance(model, kIdentity)};
  OSPWorld world = worldOf(instances);
  const std::optional<Picked> ringBefore = pickAt(world, 1.8f, 0.6f);
  ASSERT_TRUE(ringBefore);
  EXPECT_EQ(ringBefore->primID, 1u);
  EXPECT_NEAR(ringBefore->position[1], -1.0816654f, 1e-5f);  // -sqrt(2.1^2 - 1.8^2): the ring's outside

  OSPData canOnly = ownedData(kCan.data(), OSP_VEC2F, kCan.size());
  ospSetObject(geometry, "profile", canOnly);
  ospRelease(canOnly);
  ospCommit(geometry);
  ospRenderFrameBlocking(framebuffer, renderer, camera, world);
  EXPECT_FALSE(pickAt(world, 1.8f, 0.6f));
  const std::optional<Picked> can = pickAt(world, 0.0f, 1.0f);
  ASSERT_TRUE(can);
  EXPECT_EQ(can->primID, 0u);
  EXPECT_NEAR(can->position[1], -1.0f, 1e-5f);
  EXPECT_TRUE(session.takeErrors().empty());

  ospRelease(world);
  for (OSPInstance instance : instances) ospRelease(instance);
  ospRelease(model);
  ospRelease(geometry);
}

}  // namespace
}  // namespace revolve::ospray_test
