// The robot's clearance over a scene against closed forms (a pole, a cone upright, rotated, scaled
// and upside down, collisions, floors, walls, lintels, table tops, a pole lying on its side),
// against dense sampling of the surface where the answer is a lower bound (tilted shapes, sloping
// quads: never more clearance than the samples show), and the BVH search against every obstacle.
#include "robot/clearance_map.h"
#include "robot/robot_argument.h"
#include "robot_scenes.h"

#include "io/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace revolve {
namespace {

using robot::RobotBody;
using robot::SceneClearance;
using testing::Vec3d;

constexpr double kExact = 1e-12;  // double arithmetic on metre-sized closed forms

app::Transform placed(Vec3d translate, std::array<double, 4> rotate = {0, 0, 1, 0}, Vec3d scale = {1, 1, 1}) {
  app::Transform t;
  t.translate = translate;
  const double n = std::hypot(rotate[0], rotate[1], rotate[2]);
  t.rotateAxis = {rotate[0] / n, rotate[1] / n, rotate[2] / n};
  t.rotateDegrees = rotate[3];
  t.scale = scale;
  return t;
}

SceneClearance clearanceIn(const io::SceneDescription& scene, const RobotBody& robot) {
  const robot::ClearanceMap map(scene);
  const SceneClearance viaBvh = map.query(robot), direct = map.queryAll(robot);
  EXPECT_EQ(viaBvh.clearance, direct.clearance);
  EXPECT_EQ(viaBvh.object, direct.object);
  return viaBvh;
}

const std::vector<Point2> kCone{{0, 0}, {0.5, 0}, {0, 1}};  // base radius 0.5, height 1

TEST(ClearanceMapTest, PoleBesideTheRobotExactly) {
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), placed({2, 1, 0}), "pole"}});
  const SceneClearance c = clearanceIn(scene, {3, 1, 0.1, 1.0, 0.3});
  EXPECT_NEAR(c.clearance, 1 - 0.25 - 0.3, kExact);
  EXPECT_FALSE(c.collides);
  EXPECT_EQ(c.object, 0);
  EXPECT_TRUE(c.exact);
  EXPECT_NEAR(c.point[0], 2.25, kExact);  // on the pole's side facing the robot, within its heights
  EXPECT_NEAR(c.point[1], 1, kExact);
  EXPECT_GE(c.point[2], 0.1 - kExact);
  EXPECT_LE(c.point[2], 1.0 + kExact);
  // Turned about its axis and scaled to radius 0.5: still upright, still exact.
  const io::SceneDescription wide =
      testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), placed({2, 1, 0}, {0, 0, 1, 30}, {2, 2, 1}), "pole"}});
  EXPECT_NEAR(clearanceIn(wide, {3, 1, 0.1, 1.0, 0.3}).clearance, 1 - 0.5 - 0.3, kExact);
}

TEST(ClearanceMapTest, ConeUprightAndUpsideDown) {
  // The library's closed form (clearance_test.cpp) moved: the robot's corner (0.8, 0.5) in the
  // meridian is 1.1 / sqrt(5) from the side 2r + z = 1, its foot on the segment.
  const io::SceneDescription upright = testing::sceneOf({{kCone, placed({-1, 2, 0.25}), "cone"}});
  EXPECT_NEAR(clearanceIn(upright, {0, 2, 0.75, 1.15, 0.2}).clearance, 1.1 / std::sqrt(5.0), kExact);
  // Upside down (half a turn about x, then lifted by 1): the apex at z = 0, the side r = z / 2; the
  // robot's corner (0.8, 0.5) is 1.1 / sqrt(5) from the line 2r - z = 0, foot (0.36, 0.72).
  for (const std::array<double, 4> flip : {std::array<double, 4>{1, 0, 0, 180}, std::array<double, 4>{0, 1, 0, -180}}) {
    const io::SceneDescription flipped = testing::sceneOf({{kCone, placed({0, 0, 1}, flip), "cone"}});
    const SceneClearance c = clearanceIn(flipped, {1, 0, 0.1, 0.5, 0.2});
    EXPECT_NEAR(c.clearance, 1.1 / std::sqrt(5.0), kExact);
    EXPECT_TRUE(c.exact);
    EXPECT_NEAR(c.point[0], 0.36, kExact);
    EXPECT_NEAR(c.point[2], 0.72, kExact);
  }
}

TEST(ClearanceMapTest, CollisionsAreNegativeWithTheirDepth) {
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), placed({2, 1, 0}), "pole"}});
  // The pole's side 0.25 from the robot's axis: 0.05 inside its radius 0.3.
  const SceneClearance c = clearanceIn(scene, {2.5, 1, 0.2, 1.0, 0.3});
  EXPECT_NEAR(c.clearance, -0.05, kExact);
  EXPECT_TRUE(c.collides);
  // Touching is not a collision: the side exactly at the robot's radius 0.25 (dyadic, so exactly 0).
  const SceneClearance touching = clearanceIn(scene, {2.5, 1, 0.2, 1.0, 0.25});
  EXPECT_EQ(touching.clearance, 0);
  EXPECT_FALSE(touching.collides);
}

TEST(ClearanceMapTest, FloorsWallsLintelsAndTableTopsExactly) {
  const std::array<Vec3d, 4> floor{{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}};
  const std::array<Vec3d, 4> wall{{{3, -5, 0}, {3, 5, 0}, {3, 5, 2.5}, {3, -5, 2.5}}};
  const io::SceneDescription room = testing::sceneOf({}, {floor, wall});
  // The floor 0.05 under the robot's bottom; the wall 0.7 beside it.
  SceneClearance c = clearanceIn(room, {2, 0, 0.05, 1.2, 0.3});
  EXPECT_NEAR(c.clearance, 0.05, kExact);
  EXPECT_EQ(c.object, 0);  // quads[0]: no objects, so index 0
  EXPECT_TRUE(c.exact);
  c = clearanceIn(room, {2.6, 0, 0.2, 1.2, 0.3});
  EXPECT_NEAR(c.clearance, 0.1, kExact);
  EXPECT_EQ(c.object, 1);
  EXPECT_TRUE(c.exact);
  EXPECT_NEAR(c.point[0], 3, kExact);
  // Into the wall: depth 0.2 from the robot's side.
  c = clearanceIn(room, {2.9, 0, 0.2, 1.2, 0.3});
  EXPECT_NEAR(c.clearance, -0.2, kExact);
  EXPECT_TRUE(c.collides);
  EXPECT_TRUE(c.exact);
  // A lintel (a vertical rectangle from 1.4 up, 0.5 beside the robot's axis): the gaps 0.2 across
  // and 0.2 up combine. A table top 0.3 above the robot.
  const std::array<Vec3d, 4> lintel{{{2.5, -1, 1.4}, {2.5, 1, 1.4}, {2.5, 1, 2.5}, {2.5, -1, 2.5}}};
  const std::array<Vec3d, 4> top{{{-1, 4, 1.5}, {1, 4, 1.5}, {1, 6, 1.5}, {-1, 6, 1.5}}};
  const io::SceneDescription doorway = testing::sceneOf({}, {lintel, top});
  c = clearanceIn(doorway, {2, 0, 0.05, 1.2, 0.3});
  EXPECT_NEAR(c.clearance, std::hypot(0.2, 0.2), kExact);
  EXPECT_TRUE(c.exact);
  c = clearanceIn(doorway, {0.5, 5, 0.05, 1.2, 0.3});
  EXPECT_NEAR(c.clearance, 0.3, kExact);
  EXPECT_TRUE(c.exact);
}

// The least signed distance over dense samples of a placed profile's surface: an upper bound of
// the true clearance (samples are surface points), within the sampling's spacing of it.
double sampledClearance(const std::vector<Point2>& profile, const app::Transform& t, const RobotBody& robot) {
  const double theta = t.rotateDegrees * M_PI / 180, c = std::cos(theta), s = std::sin(theta);
  const auto& k = t.rotateAxis;
  const double r[3][3] = {
      {c + k[0] * k[0] * (1 - c), k[0] * k[1] * (1 - c) - k[2] * s, k[0] * k[2] * (1 - c) + k[1] * s},
      {k[1] * k[0] * (1 - c) + k[2] * s, c + k[1] * k[1] * (1 - c), k[1] * k[2] * (1 - c) - k[0] * s},
      {k[2] * k[0] * (1 - c) - k[1] * s, k[2] * k[1] * (1 - c) + k[0] * s, c + k[2] * k[2] * (1 - c)}};
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    for (int a = 0; a <= 200; ++a) {
      const double along = a / 200.0;
      const double pr = profile[i].r + along * (profile[i + 1].r - profile[i].r),
                   pz = profile[i].z + along * (profile[i + 1].z - profile[i].z);
      for (int b = 0; b < 1440; ++b) {
        const double phi = 2 * M_PI * b / 1440;
        const double local[3] = {pr * std::cos(phi) * t.scale[0], pr * std::sin(phi) * t.scale[1], pz * t.scale[2]};
        Vec3d w;
        for (int row = 0; row < 3; ++row)
          w[row] = r[row][0] * local[0] + r[row][1] * local[1] + r[row][2] * local[2] + t.translate[row];
        best = std::min(best, robot::signedDistance(robot, w));
      }
    }
  }
  return best;
}

TEST(ClearanceMapTest, PoleLyingOnItsSideIsTiltedButExactWhereTheGapIsPlain) {
  // A pole of radius 0.25 laid along -y (a quarter turn about x) with its axis at height 1.
  const app::Transform lying = placed({0, 0, 1}, {1, 0, 0, 90});
  const io::SceneDescription scene = testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), lying, "lying pole"}});
  // Beside it, the robot's heights spanning its axis: the gap is horizontal, 1 - 0.25 - 0.3.
  const RobotBody beside{1, -1, 0.5, 1.5, 0.3};
  SceneClearance c = clearanceIn(scene, beside);
  const double robotSize = 0.3 + 1.0;
  EXPECT_LE(c.clearance, 0.45 + kExact);                        // never more than there is
  EXPECT_GE(c.clearance, 0.45 - 0x1p-24 * robotSize - kExact);  // the search's tolerance
  EXPECT_TRUE(c.exact);
  // Under a bar laid the same way with its axis at height 1 (its underside at 0.75): a robot 0.6
  // tall, its top covering the bar's lowest line, leaves 0.15, which the bar's world box gives exactly.
  const io::SceneDescription high =
      testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), placed({0, 0, 1.0}, {1, 0, 0, 90}), "bar"}});
  c = clearanceIn(high, {0.1, -1, 0.1, 0.6, 0.3});
  EXPECT_NEAR(c.clearance, 0.15, 1e-9);
  EXPECT_LE(c.clearance, sampledClearance(testing::cylinderProfile(0.25, 0, 2), placed({0, 0, 1.0}, {1, 0, 0, 90}),
                                          {0.1, -1, 0.1, 0.6, 0.3}) +
                             kExact);
}

TEST(ClearanceMapTest, TiltedShapesAndSlopingQuadsNeverReportMoreThanThereIs) {
  std::mt19937_64 random(42);
  std::printf("seed 42\n");
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  // A cone tilted 50 degrees about a skew axis and unevenly scaled, and a barrel-like profile at 20 degrees.
  const std::vector<Point2> barrel{{0, 0}, {0.28, 0}, {0.33, 0.44}, {0.28, 0.88}, {0, 0.88}};
  const std::vector<std::pair<std::vector<Point2>, app::Transform>> cases{
      {kCone, placed({0, 0, 0.6}, {1, 2, 0.5, 50}, {1, 1.5, 0.8})}, {barrel, placed({0.2, -0.1, 0.1}, {0, 1, 0, 20})}};
  for (const auto& [profile, transform] : cases) {
    const io::SceneDescription scene = testing::sceneOf({{profile, transform, "tilted"}});
    const robot::ClearanceMap map(scene);
    double looseness = 0;
    for (int i = 0; i < 12; ++i) {
      const double z0 = u(random) / 3;
      const RobotBody robot{u(random), u(random), z0, z0 + 0.5 + std::abs(u(random)) / 2,
                            0.1 + std::abs(u(random)) / 5};
      const SceneClearance c = map.query(robot);
      const double sampled = sampledClearance(profile, transform, robot);
      EXPECT_LE(c.clearance, sampled + kExact) << "case " << i;
      looseness = std::max(looseness, sampled - c.clearance);
    }
    std::printf("largest margin below the sampled clearance: %.3g\n", looseness);
  }
  // A ramp: a quad rising 1 in 2 across the robot's path.
  const std::array<Vec3d, 4> ramp{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 1}, {-1, 1, 1}}};
  const robot::ClearanceMap map(testing::sceneOf({}, {ramp}));
  for (int i = 0; i < 20; ++i) {
    const double z0 = 0.2 + std::abs(u(random)) / 2;
    const RobotBody robot{u(random), u(random), z0, z0 + 0.6, 0.2};
    double sampled = INFINITY;
    for (int a = 0; a <= 400; ++a) {
      for (int b = 0; b <= 400; ++b) {
        const double s = a / 400.0, t = b / 400.0;
        sampled = std::min(sampled, robot::signedDistance(robot, Vec3d{-1 + 2 * s, -1 + 2 * t, t}));
      }
    }
    EXPECT_LE(map.query(robot).clearance, sampled + kExact) << "case " << i;
  }
}

TEST(ClearanceMapTest, TheBvhFindsWhatEveryObstacleGivesInRobotWorld) {
  const io::SceneDescription world = io::readScene(std::string(REVOLVE_SOURCE_DIR) + "/scenes/robot_world.json");
  const robot::ClearanceMap map(world);
  EXPECT_EQ(map.obstacleCount(), world.objects.size() + 2 * world.quads.size());
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> x(-0.5, 14.5), y(-0.5, 8.5);
  int collisions = 0;
  for (int i = 0; i < 150; ++i) {
    const RobotBody robot{x(random), y(random), 0.05, 1.2, 0.3};
    const SceneClearance viaBvh = map.query(robot), direct = map.queryAll(robot);
    EXPECT_EQ(viaBvh.clearance, direct.clearance) << i;
    EXPECT_EQ(viaBvh.object, direct.object) << i;
    collisions += viaBvh.collides ? 1 : 0;
  }
  EXPECT_GT(collisions, 0);
  EXPECT_LT(collisions, 150);
}

TEST(ClearanceMapTest, TheGroundIsNotAnObstacle) {
  // A floor at 0, a table top at 0.75 and a pole standing on the floor: with the ground at 0 the
  // floor is left out, the pole (reaching down to 0) and the table top are not.
  const std::array<Vec3d, 4> floor{{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}};
  const std::array<Vec3d, 4> top{{{2, -1, 0.75}, {3, -1, 0.75}, {3, 1, 0.75}, {2, 1, 0.75}}};
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), placed({-2, 0, 0}), "pole"}}, {floor, top});
  const robot::ClearanceMap grounded(scene, 0.0);
  EXPECT_EQ(grounded.obstacleCount(), 1u + 2);  // the pole and the table top's two triangles
  const SceneClearance c = grounded.query({0, 0, 0.05, 1.2, 0.3});
  EXPECT_NEAR(c.clearance, 2 - 0.25 - 0.3, kExact);
  EXPECT_EQ(c.object, 0);
  EXPECT_NEAR(robot::ClearanceMap(scene).query({0, 0, 0.05, 1.2, 0.3}).clearance, 0.05,
              kExact);  // the floor, by default
}

TEST(RobotArgumentTest, ReadsTheRobotAndNamesEachRule) {
  const robot::RobotDimensions r = robot::parseRobotArgument(" 0.3, 0.05 ,1.2");
  EXPECT_EQ(r.radius, 0.3);
  EXPECT_EQ(r.zMin, 0.05);
  EXPECT_EQ(r.zMax, 1.2);
  const std::pair<const char*, const char*> bad[] = {
      {"0.3,1.2", "--robot \"0.3,1.2\": expected RADIUS,ZMIN,ZMAX (3 comma-separated numbers), found 2"},
      {"0.3,low,1.2", "--robot: ZMIN = \"low\" is not a finite number"},
      {"0,0,1", "--robot: RADIUS = \"0\" is not positive"},
      {"-0.3,0,1", "--robot: RADIUS = \"-0.3\" is not positive"},
      {"0.3,1.2,0.05", "--robot: ZMAX = \"0.05\" is not above ZMIN = \"1.2\""},
      {"0.3,0.5,0.5", "--robot: ZMAX = \"0.5\" is not above ZMIN = \"0.5\""},
      {"0.3,0,inf", "--robot: ZMAX = \"inf\" is not a finite number"},
      {"nan,0,1", "--robot: RADIUS = \"nan\" is not a finite number"},
  };
  for (const auto& [text, expected] : bad) {
    SCOPED_TRACE(text);
    try {
      robot::parseRobotArgument(text);
      ADD_FAILURE() << "accepted";
    } catch (const std::runtime_error& error) {
      EXPECT_THAT(error.what(), ::testing::HasSubstr(expected));
    }
  }
}

TEST(ClearanceMapTest, EmptySceneHasInfiniteClearance) {
  const robot::ClearanceMap map(testing::sceneOf({}));
  const SceneClearance c = map.query({0, 0, 0, 1, 0.3});
  EXPECT_TRUE(std::isinf(c.clearance));
  EXPECT_EQ(c.object, -1);
  EXPECT_FALSE(c.collides);
}

}  // namespace
}  // namespace revolve
