// Bad parameters of a "revolution" geometry: each is an OSPRay error, through the device's error
// callback, whose message names the parameter, the point and the rule; OSPRay keeps running, and
// a world holding the refused geometry still renders and picks its other objects.
#include "ospray_session.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace revolve::ospray_test {
namespace {

using Points = std::vector<std::array<float, 2>>;

class OsprayErrors : public ::testing::Test {
 protected:
  // Commits `geometry` and expects exactly one error whose message holds every one of `parts`.
  void expectError(OSPGeometry geometry, const std::vector<std::string>& parts) {
    ospCommit(geometry);
    const std::vector<ReportedError> errors = session.takeErrors();
    ASSERT_EQ(errors.size(), 1u) << "expected one error holding '" << parts.front() << "'";
    std::printf("OSPRay error %d: %s\n", int(errors[0].code), errors[0].message.c_str());
    for (const std::string& part : parts) {
      EXPECT_NE(errors[0].message.find(part), std::string::npos)
          << "the message '" << errors[0].message << "' does not say '" << part << "'";
    }
  }

  OSPGeometry withProfile(const Points& points) {
    OSPGeometry geometry = ospNewGeometry("revolution");
    OSPData data = ownedData(points.data(), OSP_VEC2F, points.size());
    ospSetObject(geometry, "profile", data);
    ospRelease(data);
    return geometry;
  }

  Session session;
};

const Points kCup = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.2f, 1.5f}};

TEST_F(OsprayErrors, NoProfile) {
  OSPGeometry geometry = ospNewGeometry("revolution");
  expectError(geometry, {"revolution", "'profile' is missing"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, ProfileOfTheWrongType) {
  OSPGeometry geometry = ospNewGeometry("revolution");
  const std::array<float, 6> points = {0, 0, 0, 1, 1, 1};
  OSPData data = ownedData(points.data(), OSP_VEC3F, 2);
  ospSetObject(geometry, "profile", data);
  ospRelease(data);
  expectError(geometry, {"'profile'", "vec3f", "OSP_VEC2F"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, CrossingProfile) {
  // Segments 0 and 2 cross (a bow tie).
  OSPGeometry geometry = withProfile({{0.5f, 0.0f}, {1.5f, 1.0f}, {1.5f, 0.0f}, {0.5f, 1.0f}});
  expectError(geometry, {"'profile'", "point 0", "point 2", "must not cross or touch itself"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, NotANumber) {
  OSPGeometry geometry = withProfile({{0.0f, 0.0f}, {std::numeric_limits<float>::quiet_NaN(), 1.0f}, {1.0f, 2.0f}});
  expectError(geometry, {"'profile'", "point 1", "must be finite"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, UnknownSplineKind) {
  OSPGeometry geometry = withProfile(kCup);
  ospSetParam(geometry, "spline", OSP_STRING, "cubic");
  expectError(geometry, {"revolution: 'spline' is \"cubic\"", "\"catmull-rom\""});
  ospRelease(geometry);
}

// What OSPRay 3.2's ospSetString hands the device (a pointer's bytes) is shown escaped, not raw.
TEST_F(OsprayErrors, SplineOfUnprintableBytes) {
  OSPGeometry geometry = withProfile(kCup);
  ospSetParam(geometry, "spline", OSP_STRING, "q\x01\xff\"\\");
  expectError(geometry, {"revolution: 'spline' is \"q\\x01\\xff\\\"\\\\\": it must be one of"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, ToleranceNotAPositiveNumber) {
  OSPGeometry geometry = withProfile(kCup);
  ospSetParam(geometry, "spline", OSP_STRING, "catmull-rom");
  ospSetFloat(geometry, "tolerance", -0.01f);
  expectError(geometry, {"revolution: 'tolerance' is -0.01: ", "finite number > 0"});
  ospRelease(geometry);
}

// OSPRay's getParam would answer "not given" for these, so the geometry would trace something
// else than asked without a word.
TEST_F(OsprayErrors, ToleranceOfAnotherType) {
  OSPGeometry geometry = withProfile(kCup);
  ospSetParam(geometry, "spline", OSP_STRING, "quadratic");
  const double tolerance = 0.01;
  ospSetParam(geometry, "tolerance", OSP_DOUBLE, &tolerance);
  expectError(geometry, {"revolution: 'tolerance' is not a float", "OSP_FLOAT"});
  ospSetInt(geometry, "tolerance", 1);
  expectError(geometry, {"revolution: 'tolerance' is not a float"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, SplineNotAString) {
  OSPGeometry geometry = withProfile(kCup);
  ospSetInt(geometry, "spline", 2);
  expectError(geometry, {"revolution: 'spline' is not a string", "OSP_STRING"});
  ospRelease(geometry);
}

TEST_F(OsprayErrors, UnknownParameters) {
  for (const char* misspelt : {"profiles", "splin", "Tolerance"}) {
    OSPGeometry geometry = withProfile(kCup);
    ospSetParam(geometry, misspelt, OSP_STRING, "quadratic");
    expectError(geometry, {std::string("revolution: unknown parameter '") + misspelt + "'", "'profile', 'spline'"});
    ospRelease(geometry);
  }
}

TEST_F(OsprayErrors, OneBadProfileAmongMany) {
  OSPGeometry geometry = ospNewGeometry("revolution");
  const Points bad = {{0.0f, 0.0f}, {-1.0f, 1.0f}};
  std::array<OSPData, 2> each = {ownedData(kCup.data(), OSP_VEC2F, kCup.size()),
                                 ownedData(bad.data(), OSP_VEC2F, bad.size())};
  OSPData list = ownedData(each.data(), OSP_DATA, each.size());
  for (OSPData one : each) ospRelease(one);
  ospSetObject(geometry, "profile", list);
  ospRelease(list);
  expectError(geometry, {"'profile' 1", "point 1", "r = -1"});
  ospRelease(geometry);
}

// After every refusal above, in one session: a world holding a refused geometry (it has no
// revolutions) and a good one renders a frame and picks the good one.
TEST_F(OsprayErrors, OsprayKeepsRunning) {
  OSPGeometry refused = ospNewGeometry("revolution");
  ospCommit(refused);
  OSPGeometry good = newRevolutions({kCup});
  ASSERT_EQ(session.takeErrors().size(), 1u);

  std::vector<OSPInstance> instances;
  std::vector<OSPGeometricModel> models;
  for (OSPGeometry geometry : {refused, good}) {
    OSPGeometricModel model = ospNewGeometricModel(geometry);
    ospCommit(model);
    models.push_back(model);
    instances.push_back(newInstance(model, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}));
  }
  OSPWorld world = ospNewWorld();
  OSPData instanceData = ownedData(instances.data(), OSP_INSTANCE, instances.size());
  ospSetObject(world, "instance", instanceData);
  ospCommit(world);
  OSPCamera camera = ospNewCamera("perspective");
  const std::array<float, 3> position = {0.0f, -6.0f, 0.75f}, direction = {0.0f, 1.0f, 0.0f}, up = {0, 0, 1};
  ospSetParam(camera, "position", OSP_VEC3F, position.data());
  ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
  ospSetParam(camera, "up", OSP_VEC3F, up.data());
  ospCommit(camera);
  OSPRenderer renderer = ospNewRenderer("scivis");
  ospCommit(renderer);
  OSPFrameBuffer framebuffer = ospNewFrameBuffer(32, 32, OSP_FB_RGBA8, OSP_FB_COLOR);
  ospCommit(framebuffer);
  ospRenderFrameBlocking(framebuffer, renderer, camera, world);  // returns the frame's variance
  OSPPickResult pick;
  ospPick(&pick, framebuffer, renderer, camera, world, 0.5f, 0.5f);
  ASSERT_TRUE(pick.hasHit);
  EXPECT_EQ(pick.model, models[1]);
  EXPECT_NEAR(std::hypot(pick.worldPosition[0], pick.worldPosition[1]), 1.1f, 1e-5f);  // r at z = 0.75
  ospRelease(pick.instance);
  ospRelease(pick.model);
  EXPECT_TRUE(session.takeErrors().empty());

  ospRelease(framebuffer);
  ospRelease(renderer);
  ospRelease(camera);
  ospRelease(instanceData);
  ospRelease(world);
  for (OSPInstance instance : instances) ospRelease(instance);
  for (OSPGeometricModel model : models) ospRelease(model);
  ospRelease(refused);
  ospRelease(good);
}

// A refused first commit still gives the geometry an (empty) Embree geometry: in one group with a
// good one, Embree's geometry IDs stay those OSPRay gave the models, so a pick names the right one.
// A profile of the wrong type once left none, and the pick named the refused model.
TEST_F(OsprayErrors, ARefusedGeometryInTheSameGroupAsAGoodOne) {
  for (const bool wrongType : {false, true}) {
    OSPGeometry refused = ospNewGeometry("revolution");
    if (wrongType) {
      const std::array<float, 6> points = {0, 0, 0, 1, 1, 1};
      OSPData data = ownedData(points.data(), OSP_VEC3F, 2);
      ospSetObject(refused, "profile", data);
      ospRelease(data);
    }
    ospCommit(refused);
    ASSERT_EQ(session.takeErrors().size(), 1u);
    OSPGeometry good = newRevolutions({kCup});
    std::array<OSPGeometricModel, 2> models = {ospNewGeometricModel(refused), ospNewGeometricModel(good)};
    for (OSPGeometricModel model : models) ospCommit(model);
    OSPGroup group = ospNewGroup();
    OSPData modelData = ownedData(models.data(), OSP_GEOMETRIC_MODEL, models.size());
    ospSetObject(group, "geometry", modelData);
    ospCommit(group);
    OSPInstance instance = ospNewInstance(group);
    ospCommit(instance);
    OSPWorld world = ospNewWorld();
    OSPData instanceData = ownedData(&instance, OSP_INSTANCE, 1);
    ospSetObject(world, "instance", instanceData);
    ospCommit(world);
    OSPCamera camera = ospNewCamera("perspective");
    const std::array<float, 3> position = {0.0f, -6.0f, 0.75f}, direction = {0.0f, 1.0f, 0.0f}, up = {0, 0, 1};
    ospSetParam(camera, "position", OSP_VEC3F, position.data());
    ospSetParam(camera, "direction", OSP_VEC3F, direction.data());
    ospSetParam(camera, "up", OSP_VEC3F, up.data());
    ospCommit(camera);
    OSPRenderer renderer = ospNewRenderer("scivis");
    ospCommit(renderer);
    OSPFrameBuffer framebuffer = ospNewFrameBuffer(16, 16, OSP_FB_RGBA8, OSP_FB_COLOR);
    ospCommit(framebuffer);
    OSPPickResult pick;
    ospPick(&pick, framebuffer, renderer, camera, world, 0.5f, 0.5f);
    ASSERT_TRUE(pick.hasHit) << (wrongType ? "wrongly typed profile" : "no profile");
    EXPECT_EQ(pick.model, models[1]) << (wrongType ? "wrongly typed profile" : "no profile");
    EXPECT_NEAR(std::hypot(pick.worldPosition[0], pick.worldPosition[1]), 1.1f, 1e-5f);  // r at z = 0.75
    ospRelease(pick.instance);
    ospRelease(pick.model);
    EXPECT_TRUE(session.takeErrors().empty());

    for (OSPObject object : {OSPObject(framebuffer), OSPObject(renderer), OSPObject(camera), OSPObject(instanceData),
                             OSPObject(world), OSPObject(instance), OSPObject(modelData), OSPObject(group),
                             OSPObject(models[0]), OSPObject(models[1]), OSPObject(refused), OSPObject(good)}) {
      ospRelease(object);
    }
  }
}

}  // namespace
}  // namespace revolve::ospray_test
