// revolve-bench scale --write-scene: the family written as a scene file with an object table reads
// back to the family's own points and placements (scale_family.h, not the writer's output), and the
// scene built from it in parallel answers every ray bit for bit as the same shapes added one by
// one through EmbreeScene::addRevolution.
#include "scale/scale_family.h"
#include "scale/scale_scene_file.h"

#include "io/scene_file.h"
#include "io/scratch_directory.h"
#include "scene/embree_scene.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <span>
#include <vector>

namespace revolve::bench {
namespace {

using revolve::testing::ScratchDirectory;

constexpr std::size_t kObjects = 41;  // not a square: the grid's last row is partly empty

TEST(ScaleSceneTest, WrittenSceneReadsBackToTheFamily) {
  const ScratchDirectory dir;
  const ScaleFamily family{.seed = 7};
  const io::SceneDescription scene = io::readScene(writeFamilyScene(family, kObjects, dir.path().string()));
  ASSERT_EQ(scene.objects.size(), kObjects);
  for (std::size_t i = 0; i < kObjects; ++i) {
    const io::SceneObject& object = scene.objects[i];
    const io::SceneProfile& profile = scene.profiles[object.profile];
    const std::vector<Point2> expected = family.points(i);
    ASSERT_EQ(profile.spline.has_value(), family.isSpline(i)) << i;
    const std::span<const Point2> read = family.isSpline(i) ? profile.spline->points() : profile.profile->points();
    if (family.isSpline(i)) EXPECT_EQ(profile.spline->kind(), SplineKind::catmullRom);
    ASSERT_EQ(read.size(), expected.size()) << i;
    for (std::size_t k = 0; k < read.size(); ++k) {
      EXPECT_EQ(read[k].r, expected[k].r) << i << " " << k;  // bit for bit: the shortest round-trip text
      EXPECT_EQ(read[k].z, expected[k].z) << i << " " << k;
    }
    const app::Transform placed = family.transform(i, kObjects);
    EXPECT_EQ(object.transform.translate, placed.translate) << i;
    EXPECT_EQ(object.transform.scale, placed.scale) << i;
    EXPECT_EQ(object.transform.rotateDegrees, 0) << i;
  }
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(Vec3 a, Vec3 b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }

TEST(ScaleSceneTest, ParallelBuildAnswersAsOneByOne) {
  const ScratchDirectory dir;
  const ScaleFamily family{.seed = 11};
  const io::SceneDescription description = io::readScene(writeFamilyScene(family, kObjects, dir.path().string()));
  const scene::EmbreeScene parallel(description, scene::BuildSettings{});

  // The same shapes from the family's points, added one call each.
  scene::EmbreeScene oneByOne{scene::Layout{}};
  for (std::size_t i = 0; i < kObjects; ++i) {
    const app::Placement placement(family.transform(i, kObjects));
    if (family.isSpline(i))
      oneByOne.addRevolution(Shape(Spline(SplineKind::catmullRom, family.points(i))), placement);
    else
      oneByOne.addRevolution(Shape(Profile(family.points(i))), placement);
  }
  oneByOne.commit();

  // Rays from around each object's neighbourhood towards a point near its axis (seed printed on
  // failure): most hit it or a neighbour, some pass between.
  const std::uint32_t seed = 20260;
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::size_t> anyObject(0, kObjects - 1);
  std::uniform_real_distribution<double> around(-2, 2), height(-0.5, 2), nearAxis(-0.3, 0.3), along(0, 1);
  std::size_t hits = 0;
  for (int n = 0; n < 4000; ++n) {
    const app::Vec3d centre = family.transform(anyObject(random), kObjects).translate;
    const Vec3 origin{float(centre[0] + around(random)), float(centre[1] + around(random)), float(height(random))};
    const Vec3 target{float(centre[0] + nearAxis(random)), float(centre[1] + nearAxis(random)), float(along(random))};
    const Ray ray{origin, {target.x - origin.x, target.y - origin.y, target.z - origin.z}};
    const std::optional<scene::WorldHit> a = parallel.intersect(ray), b = oneByOne.intersect(ray);
    ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << n << ", seed " << seed;
    if (!a) continue;
    ++hits;
    EXPECT_EQ(a->object, b->object) << "ray " << n;
    EXPECT_TRUE(sameBits(a->t, b->t)) << "ray " << n << ": " << a->t << " " << b->t;
    EXPECT_TRUE(sameBits(a->point, b->point)) << "ray " << n;
    EXPECT_TRUE(sameBits(a->geometricNormal, b->geometricNormal)) << "ray " << n;
  }
  std::printf("%zu of 4000 rays hit\n", hits);
  EXPECT_GT(hits, 2000u) << "the rays should mostly land on objects";
}

}  // namespace
}  // namespace revolve::bench
