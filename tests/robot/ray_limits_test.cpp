// Embree's ray contract in process: app::embreeAccepts is Embree 3's RayK::valid() (kernels/common/
// ray.h: every component of org and dir within FLT_LARGE = 1.844e18, tnear and tfar not NaN);
// EmbreeScene refuses a description made in code whose transform would carry rays beyond it, and
// counts and misses a ray beyond it rather than let Embree abort the process. And the warnings for
// objects that show nothing: one per object, for exactly the cases they name.
#include "geometry/ray_limits.h"
#include "robot_scenes.h"
#include "scene/degenerate_objects.h"
#include "scene/embree_scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace revolve {
namespace {

using testing::at;
using testing::cylinderProfile;
using ::testing::HasSubstr;
using testing::sceneOf;
using testing::sphereProfile;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

TEST(RayLimitsTest, EmbreeAcceptsIsRayValidAtItsEdges) {
  const float large = 1.844e18f, beyond = std::nextafter(large, kInf);
  const auto ray = [](Vec3 o, Vec3 d, float tnear = 0, float tfar = kInf) { return Ray{o, d, tnear, tfar}; };
  EXPECT_TRUE(app::embreeAccepts(ray({large, -large, 0}, {0, 0, large})));
  EXPECT_FALSE(app::embreeAccepts(ray({beyond, 0, 0}, {1, 0, 0})));
  EXPECT_FALSE(app::embreeAccepts(ray({0, 0, -beyond}, {1, 0, 0})));
  EXPECT_FALSE(app::embreeAccepts(ray({0, 0, 0}, {0, beyond, 0})));
  EXPECT_FALSE(app::embreeAccepts(ray({kNan, 0, 0}, {1, 0, 0})));
  EXPECT_FALSE(app::embreeAccepts(ray({0, 0, 0}, {kInf, 0, 0})));
  EXPECT_FALSE(app::embreeAccepts(ray({0, 0, 0}, {1, 0, 0}, kNan)));
  EXPECT_FALSE(app::embreeAccepts(ray({0, 0, 0}, {1, 0, 0}, 0, kNan)));
  EXPECT_TRUE(app::embreeAccepts(ray({0, 0, 0}, {1, 0, 0}, 0, kInf)));
  EXPECT_TRUE(app::embreeAccepts(ray({0, 0, 0}, {0, 0, 0})));  // Embree's contract allows it; revolve misses it
}

TEST(RayLimitsTest, ADescriptionMadeInCodeWithATransformBeyondEmbreesRangeIsRefused) {
  app::Transform tiny = at(0, 0);
  tiny.scale = {1e-20, 1, 1};
  try {
    const scene::EmbreeScene built(sceneOf({{cylinderProfile(1, 0, 1), tiny, "tiny"}}), {});
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(
        error.what(),
        HasSubstr("test scene: objects[0] \"tiny\": 1e-20 is out of range: scale factors lie in [2^-16, 2^40]"));
  }
}

TEST(RayLimitsTest, ARayBeyondEmbreesRangeMissesAndIsCountedInsteadOfAborting) {
  const scene::EmbreeScene built(sceneOf({{cylinderProfile(1, 0, 1), at(0, 0), "pole"}}), {});
  const Ray far{{1e19f, 0, 0.5f}, {-1, 0, 0}};
  EXPECT_FALSE(built.intersect(far).has_value());
  EXPECT_FALSE(built.nearest(far).has_value());
  EXPECT_FALSE(built.occluded(far));
  EXPECT_EQ(built.refusedRays(), 3u);
  // The same ray from within the range hits the pole's side, 2 - 1 away.
  const std::optional<scene::RangeHit> near = built.nearest(Ray{{2, 0, 0.5f}, {-1, 0, 0}});
  ASSERT_TRUE(near.has_value());
  EXPECT_NEAR(near->t, 1, 1e-6);
  EXPECT_EQ(built.refusedRays(), 3u);
}

// A closed ball of radius 1, scaled by (2, 3, 0.5), turned and moved: the camera is inside exactly
// when its position, mapped back, lies within the unit ball (the inscribed polyline's 64 segments
// are within 0.0003 of it, far from the points tested).
TEST(DegenerateObjectsTest, TheCameraInsideAClosedObjectIsFoundThroughItsTransform) {
  app::Transform placed = at(4, -1, 2);
  placed.scale = {2, 3, 0.5};
  placed.rotateAxis = {0, 0, 1};
  placed.rotateDegrees = 90;  // x -> y: the ball spans 3 along x and 2 along y
  io::SceneDescription scene =
      sceneOf({{sphereProfile(1, 64), placed, "ball"}, {{{0, 0}, {1, 0}, {1, 1}}, at(4, -1, 2), "open cup"}});
  const auto warningsWithCameraAt = [&](app::Vec3d from) {
    scene.camera.from = from;
    return scene::degenerateObjectWarnings(scene, true);
  };
  EXPECT_THAT(warningsWithCameraAt({4 + 2.9, -1, 2}),
              ::testing::ElementsAre("test scene: objects[0] \"ball\": the camera (camera.from) lies inside it: the "
                                     "view shows its inside, or nothing"));
  EXPECT_TRUE(warningsWithCameraAt({4 + 3.1, -1, 2}).empty());
  EXPECT_EQ(warningsWithCameraAt({4, -1 + 1.9, 2}).size(), 1u);
  EXPECT_TRUE(warningsWithCameraAt({4, -1 + 2.1, 2}).empty());
  EXPECT_EQ(warningsWithCameraAt({4, -1, 2 + 0.45}).size(), 1u);
  EXPECT_TRUE(warningsWithCameraAt({4, -1, 2 + 0.55}).empty());
  // The open cup (its ends neither meet nor lie both on the axis) has no inside; tools without a
  // camera do not ask.
  EXPECT_TRUE(warningsWithCameraAt({4.5, -1, 2.5}).empty());
  scene.camera.from = {4, -1, 2};
  EXPECT_TRUE(scene::degenerateObjectWarnings(scene, false).empty());
}

// A profile on the axis has no area; a pole 3.05e-5 tall at 1e6 is below float's step there
// (0.0625 = 2^-23 of 2^19..2^20, and 0.119 by the warning's 2^-23 x 1e6), the same pole at 1 is not.
TEST(DegenerateObjectsTest, AnAxisOnlyProfileAndAnObjectBelowFloatResolutionAreNamed) {
  app::Transform speck = at(1e6, 0, 0);
  speck.scale = {0x1p-16, 0x1p-16, 0x1p-16};
  app::Transform visible = at(1, 0, 0);
  visible.scale = {0x1p-16, 0x1p-16, 0x1p-16};
  const io::SceneDescription scene = sceneOf({{{{0, 0}, {0, 1}}, at(0, 0), "thread"},
                                              {cylinderProfile(0.25, 0, 2), speck, "speck"},
                                              {cylinderProfile(0.25, 0, 2), visible, "visible"}});
  const std::vector<std::string> warnings = scene::degenerateObjectWarnings(scene, false);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_THAT(warnings[0], HasSubstr("objects[0] \"thread\": every point of profile \"p0\" lies on the axis (r = 0)"));
  EXPECT_THAT(
      warnings[1],
      HasSubstr("objects[1] \"speck\": placed, it spans 3.05e-05, less than one float step at its distance 1e+06"));
}

// Exact splines are judged by their curves, and drawn (SceneProfile::polyline) only where a check
// needs the curve's points: a closed one when the camera is asked about, a tiny one to measure it.
// The ball: two cubic quarter circles (inner points at 0.5523 of the radius, within 3e-4 of the
// circle), from the bottom pole to the top, both ends on the axis (closed); the cup: the lower
// quarter alone (open).
TEST(DegenerateObjectsTest, ExactSplinesAreJudgedByTheirCurvesAndDrawnOnlyWhereNeeded) {
  const double k = 0.5523;
  const std::vector<Point2> ball{{0, -1}, {k, -1}, {1, -k}, {1, 0}, {1, k}, {k, 1}, {0, 1}};
  const std::vector<Point2> cup{{0, -1}, {k, -1}, {1, -k}, {1, 0}};
  app::Transform speck = at(1e6, 0, 0);
  speck.scale = {0x1p-16, 0x1p-16, 0x1p-16};
  const auto sceneWith = [&](const std::vector<Point2>& points, const app::Transform& placed) {
    io::SceneDescription scene = sceneOf({});
    scene.profiles.push_back({.name = "curve"});
    scene.profiles.back().spline.emplace(SplineKind::bezier, points);
    scene.objects.push_back({"curved", 0, 0, placed});
    return scene;
  };
  const auto drawn = [](const io::SceneDescription& scene) { return scene.profiles[0].drawing->polyline.has_value(); };

  // Nothing to say without a camera, and nothing drawn.
  io::SceneDescription ballScene = sceneWith(ball, at(4, -1, 2));
  EXPECT_TRUE(scene::degenerateObjectWarnings(ballScene, false).empty());
  EXPECT_FALSE(drawn(ballScene));
  // With the camera inside the ball, or just outside it.
  ballScene.camera.from = {4 + 0.95, -1, 2};
  EXPECT_THAT(scene::degenerateObjectWarnings(ballScene, true),
              ::testing::ElementsAre("test scene: objects[0] \"curved\": the camera (camera.from) lies inside it: the "
                                     "view shows its inside, or nothing"));
  EXPECT_TRUE(drawn(ballScene));
  ballScene.camera.from = {4 + 1.05, -1, 2};
  EXPECT_TRUE(scene::degenerateObjectWarnings(ballScene, true).empty());
  // The open cup has no inside: not drawn even with the camera in its hollow.
  io::SceneDescription cupScene = sceneWith(cup, at(4, -1, 2));
  cupScene.camera.from = {4, -1, 2 - 0.5};
  EXPECT_TRUE(scene::degenerateObjectWarnings(cupScene, true).empty());
  EXPECT_FALSE(drawn(cupScene));
  // The ball 3.05e-5 across at 1e6, below float's step there, as the polyline pole above.
  const io::SceneDescription speckScene = sceneWith(ball, speck);
  const std::vector<std::string> warnings = scene::degenerateObjectWarnings(speckScene, false);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("objects[0] \"curved\": placed, it spans 3.05e-05, less than one float step"));
}

}  // namespace
}  // namespace revolve
