// Many objects in one scene (scene/embree_scene.h): EmbreeScene::addRevolutions against closed
// forms (each cylinder's wall where its placement puts it, under its own id, ids consecutive) and
// against addRevolution one object at a time (the same hits, bit for bit); and what a scene
// file's exact surfaces keep (a spline no shading normals, its shading normal its geometric one).
#include "scene/embree_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

constexpr std::uint64_t kSeed = 0x5ca1e;

struct Cylinder {
  double radius, height, scale;
};

Shape cylinderShape(const Cylinder& c) {
  return Shape(Profile(std::vector<Point2>{{0, 0}, {c.radius, 0}, {c.radius, c.height}, {0, c.height}}));
}

app::Placement placementOf(const Cylinder& c, std::size_t i) {
  app::Transform t;
  t.scale = {c.scale, c.scale, c.scale};
  t.translate = {3.0 * double(i), 0, 0};
  return app::Placement(t);
}

std::vector<Cylinder> cylinders(std::size_t count) {
  std::mt19937_64 random(kSeed);
  std::uniform_real_distribution<double> radius(0.2, 0.9), height(0.5, 2.0), scale(0.5, 1.5);
  std::vector<Cylinder> result;
  for (std::size_t i = 0; i < count; ++i) result.push_back({radius(random), height(random), scale(random)});
  return result;
}

// Along +y at mid-height towards object i's axis: its wall at y = -scale r, t = 10 - scale r.
Ray rayAt(const Cylinder& c, std::size_t i) {
  return {{float(3.0 * double(i)), -10.0f, float(0.5 * c.scale * c.height)}, {0, 1, 0}};
}

TEST(ManyObjects, EachIsHitWhereItsPlacementPutsItUnderItsOwnId) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  const std::vector<Cylinder> objects = cylinders(200);
  scene::EmbreeScene scene{scene::Layout{}};
  scene.addRevolution(cylinderShape({0.1, 0.1, 1}), placementOf({0.1, 0.1, 1}, 1000));  // one before: ids go on from it
  std::vector<Shape> shapes;
  std::vector<app::Placement> placements;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    shapes.push_back(cylinderShape(objects[i]));
    placements.push_back(placementOf(objects[i], i));
  }
  const std::uint32_t first = scene.addRevolutions(std::move(shapes), placements);
  EXPECT_EQ(first, 1u);
  ASSERT_EQ(scene.geometryCount(), objects.size() + 1);
  scene.commit();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::optional<scene::WorldHit> hit = scene.intersect(rayAt(objects[i], i));
    ASSERT_TRUE(hit.has_value()) << "object " << i;
    EXPECT_EQ(hit->object, first + i);
    // t rounds in float, with the instance's transform: a few ulps of 10.
    EXPECT_NEAR(hit->t, 10 - objects[i].scale * objects[i].radius, 1e-5) << "object " << i;
    EXPECT_EQ(scene.shapeOf(first + std::uint32_t(i))->profile().points()[1].r, objects[i].radius);
  }
}

TEST(ManyObjects, InOneCallAsOneByOne) {
  const std::vector<Cylinder> objects = cylinders(60);
  scene::EmbreeScene bulk{scene::Layout{}}, single{scene::Layout{}};
  std::vector<Shape> shapes;
  std::vector<app::Placement> placements;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    shapes.push_back(cylinderShape(objects[i]));
    placements.push_back(placementOf(objects[i], i));
    single.addRevolution(cylinderShape(objects[i]), placements.back());
  }
  bulk.addRevolutions(std::move(shapes), placements);
  bulk.commit();
  single.commit();
  std::mt19937_64 random(kSeed + 1);
  std::uniform_real_distribution<float> x(-1.0f, 3.0f * float(objects.size())), z(-0.5f, 2.5f), d(-0.05f, 0.05f);
  int hits = 0;
  for (int k = 0; k < 5000; ++k) {
    const Ray ray{{x(random), -10.0f, z(random)}, {d(random), 1.0f, d(random)}};
    const std::optional<scene::WorldHit> a = bulk.intersect(ray), b = single.intersect(ray);
    ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << k;
    if (!a) continue;
    ++hits;
    EXPECT_EQ(a->t, b->t);
    EXPECT_EQ(a->object, b->object);
    EXPECT_EQ(a->geometricNormal.x, b->geometricNormal.x);
    EXPECT_EQ(a->shadingNormal.z, b->shadingNormal.z);
  }
  EXPECT_GT(hits, 500);  // not a comparison of misses alone (884 of 5,000 hit)
}

TEST(ManyObjects, AnExactSplineKeepsNoShadingNormalsAndShadesWithItsOwnNormal) {
  // One spline and one polyline through the same points, side by side.
  const std::vector<Point2> points{{0, 0}, {0.5, 0.1}, {0.7, 0.5}, {0.4, 1.0}, {0, 1.2}};
  io::SceneDescription description;
  description.file = "in memory";
  description.materials.emplace_back();
  io::SceneProfile spline{.name = "spline", .profile = Profile(points)};
  spline.spline.emplace(SplineKind::catmullRom, points);
  description.profiles.push_back(std::move(spline));
  description.profiles.push_back({.name = "polyline", .profile = Profile(points)});
  for (std::size_t i = 0; i < 2; ++i) {
    io::SceneObject object;
    object.profile = i;
    object.transform.translate = {3.0 * double(i), 0, 0};
    description.objects.push_back(object);
  }
  const scene::EmbreeScene scene(description, scene::BuildSettings{});
  const std::size_t shapes = scene.shapeOf(0)->memoryBytes() + scene.shapeOf(1)->memoryBytes();
  const ShadingNormals polylineNormals(Profile(points), ShadingNormals::kDefaultCreaseDegrees);
  EXPECT_EQ(scene.revolveBytes(), shapes + polylineNormals.memoryBytes());
  const std::optional<scene::WorldHit> hit = scene.intersect({{0.0f, -5.0f, 0.6f}, {0, 1, 0}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->object, 0u);
  EXPECT_EQ(hit->shadingNormal.x, hit->geometricNormal.x);
  EXPECT_EQ(hit->shadingNormal.y, hit->geometricNormal.y);
  EXPECT_EQ(hit->shadingNormal.z, hit->geometricNormal.z);
}

}  // namespace
}  // namespace revolve
