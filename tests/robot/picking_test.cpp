// Picking: the object under a pixel, against a ray built here from the camera's definition (pixel
// centres, vertical field of view, (0, 0) at the top left) and the closed-form hit of a pole.
#include "scene/picking.h"
#include "robot_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace revolve {
namespace {

using testing::Vec3d;

TEST(PickingTest, ThePixelsRayPicksThePoleTheFloorOrNothing) {
  io::SceneDescription scene = testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), testing::at(0.1, 0), "pole"}},
                                                {{{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}});
  scene.camera = {{0, -5, 1}, {0, 0, 1}, {0, 0, 1}, 40, {}, {}, {}};
  const scene::EmbreeScene built(scene, {});
  const int width = 64, height = 48, x = 33, y = 20;
  // The camera looks along +y; right is +x, up +z; the pixel's centre at (x + 1/2, y + 1/2).
  const double half = std::tan(20 * M_PI / 180), aspect = double(width) / height;
  const double sx = 2 * (x + 0.5) / width - 1, sy = 1 - 2 * (y + 0.5) / height;
  Vec3d u{sx * half * aspect, 1, sy * half};
  const double n = std::sqrt(testing::dot(u, u));
  for (double& c : u) c /= n;
  const Vec3d o{0, -5, 1};
  const std::optional<double> t = testing::rayCappedCylinder(o, u, 0.1, 0, 0.25, 0, 2);
  ASSERT_TRUE(t.has_value());
  const std::optional<scene::Pick> picked = scene::pick(scene, built, width, height, x, y);
  ASSERT_TRUE(picked.has_value());
  EXPECT_EQ(picked->object, 0u);
  EXPECT_EQ(picked->name, "pole");
  const double tolerance = 0x1p-20 * 6;  // float rounding of the camera ray over ~6 m, with room
  EXPECT_NEAR(picked->distance, *t, tolerance);
  EXPECT_NEAR(picked->point.x, o[0] + *t * u[0], tolerance);
  EXPECT_NEAR(picked->point.y, o[1] + *t * u[1], tolerance);
  EXPECT_NEAR(picked->point.z, o[2] + *t * u[2], tolerance);
  // The bottom row looks down at the floor: quads[0], object index objects.size() + 0.
  const std::optional<scene::Pick> floor = scene::pick(scene, built, width, height, 2, height - 1);
  ASSERT_TRUE(floor.has_value());
  EXPECT_EQ(floor->object, 1u);
  EXPECT_EQ(floor->name, "quads[0]");
  EXPECT_NEAR(floor->point.z, 0, 1e-6);
  // The top row looks over everything.
  EXPECT_FALSE(scene::pick(scene, built, width, height, 2, 0).has_value());
}

}  // namespace
}  // namespace revolve
