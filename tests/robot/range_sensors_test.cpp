// Range sensors over a scene (robot/range_sensors.h): a ring reading a pole and the walls of a
// room against closed forms, a tessellated pole against the exact one (never nearer, and farther
// by at most the facets' sagitta where the cone looks straight at it), the noise's statistics,
// the range gate, and rotated, scaled objects read in their own frame.
#include "robot/range_sensors.h"

#include "io/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace revolve {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kExact = 1e-12;

// A pole of radius 0.25 about (2, 0), 4 m tall, an optional scale and rotation, no floor.
io::SceneDescription poleScene(const std::string& placement = "") {
  const std::string text = R"({
    "camera": {"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40},
    "profiles": {"pole": {"points": [[0, -2], [0.25, -2], [0.25, 2], [0, 2]]}},
    "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
    "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0])" +
                           placement + R"(}]
  })";
  return io::parseScene(text, "pole.json", ".");
}

io::RangeSensorsDescription sonar(double fieldOfView, double minRange = 0, double maxRange = 100, double stddev = 0) {
  io::RangeSensorsDescription d;
  io::RangeSensorDescription s;
  s.name = "sonar";
  s.fieldOfView = fieldOfView;
  s.minRange = minRange;
  s.maxRange = maxRange;
  s.noiseStddev = stddev;
  s.noiseSeed = 11;
  d.sensors.push_back(s);
  return d;
}

io::RobotPose at(double x, double y, double yaw) {
  io::RobotPose pose;
  pose.x = x, pose.y = y, pose.yaw = yaw;
  return pose;
}

TEST(RangeSensorsTest, MeshIsNeverNearerAndFartherByAtMostTheSagittaHeadOn) {
  const io::SceneDescription scene = poleScene();
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> angle(-kPi, kPi), distance(0.6, 4);
  for (const std::uint32_t slices : {8u, 16u, 64u}) {
    const robot::RangeSensors exact(scene, sonar(0.3));
    const robot::RangeSensors mesh(scene, sonar(0.3), {true, slices});
    const double sagitta = 0.25 * (1 - std::cos(kPi / slices));
    double largest = 0;
    for (int trial = 0; trial < 200; ++trial) {
      // Looking straight at the pole's axis from a random place around it: the nearest point is
      // the pole's, inside the cone.
      const double phi = angle(random), d = distance(random);
      const io::RobotPose pose = at(2 + d * std::cos(phi), d * std::sin(phi), phi + kPi);
      const robot::RangeReading e = exact.read(0, pose, 0), m = mesh.read(0, pose, 0);
      ASSERT_NEAR(e.range, d - 0.25, kExact * d);
      EXPECT_GE(m.range, e.range - kExact) << "the facets lie inside the cylinder";
      EXPECT_LE(m.range, e.range + sagitta + kExact) << slices << " slices";
      largest = std::max(largest, m.range - e.range);
    }
    // The facets' error shows: some direction meets a facet's middle.
    EXPECT_GT(largest, 0.5 * sagitta) << slices << " slices";
  }
}

TEST(RangeSensorsTest, ARingOfEightAroundThePole) {
  // Eight sonars 0.1 m about the robot's centre, facing out every 45 degrees.
  io::RangeSensorsDescription ring;
  for (int i = 0; i < 8; ++i) {
    io::RangeSensorDescription s;
    s.name = "sonar_" + std::to_string(i);
    s.pose.yaw = i * kPi / 4;
    s.pose.position = {0.1 * std::cos(s.pose.yaw), 0.1 * std::sin(s.pose.yaw), 0};
    s.fieldOfView = 0.4;
    s.maxRange = 10;
    ring.sensors.push_back(s);
  }
  const robot::RangeSensors sensors(poleScene(), ring);
  // The robot at (1, 0) facing +X, 1 m from the pole's axis: each sonar reads the pole along its
  // cone's boundary ray nearest the axis (the first hit of a circle of radius 0.25 at distance D
  // and angle beta from the sonar's axis), or nothing where that ray passes it by.
  for (std::size_t i = 0; i < 8; ++i) {
    const robot::RangeReading r = sensors.read(i, at(1, 0, 0), 0);
    const double yaw = double(i) * kPi / 4;
    const double ax = 1 + 0.1 * std::cos(yaw), ay = 0.1 * std::sin(yaw);
    const double D = std::hypot(2 - ax, -ay), toAxis = std::atan2(-ay, 2 - ax);
    double beta = std::abs(std::remainder(toAxis - yaw, 2 * kPi));
    const double gamma = std::max(beta - 0.2, 0.0), offset = D * std::sin(gamma);
    if (offset > 0.25 || gamma >= kPi / 2) {
      EXPECT_EQ(r.range, INFINITY) << "sonar " << i;
      EXPECT_EQ(r.object, -1);
      EXPECT_TRUE(std::isnan(r.point[0]));
    } else {
      EXPECT_NEAR(r.range, D * std::cos(gamma) - std::sqrt(0.0625 - offset * offset), kExact) << "sonar " << i;
      EXPECT_EQ(r.object, 0);
      EXPECT_NEAR(std::hypot(r.point[0] - 2, r.point[1]), 0.25, kExact) << "on the pole";
    }
  }
}

TEST(RangeSensorsTest, RotatedAndScaledObjectsAreReadInTheirOwnFrame) {
  // The pole laid along Y (rotated 90 degrees about X) and scaled by 2: radius 0.5, its axis the
  // line x = 2, z = 0, its ends at y = -4 and 4. A sonar looking along +X reads 2 - 0.5 beside it;
  // at y = 4.5 its cone (half-angle 0.1) passes the end by (the nearest point of the end disc is
  // atan(0.5 / 1.5) = 0.32 off its axis).
  const io::SceneDescription scene = poleScene(R"(, "rotate": [1, 0, 0, 90], "scale": [2, 2, 2])");
  const robot::RangeSensors sensors(scene, sonar(0.2));
  EXPECT_NEAR(sensors.read(0, at(0, 0, 0), 0).range, 1.5, kExact);
  EXPECT_NEAR(sensors.read(0, at(0, 3.5, 0), 0).range, 1.5, kExact) << "along the laid pole";
  EXPECT_EQ(sensors.read(0, at(0, 4.5, 0), 0).range, INFINITY) << "past its end (y = 4)";
  // Unequal scales: refused for the exact reading, taken by the mesh.
  const io::SceneDescription stretched = poleScene(R"(, "scale": [1, 1, 2])");
  EXPECT_THROW(robot::RangeSensors(stretched, sonar(0.2)), std::invalid_argument);
  EXPECT_NO_THROW(robot::RangeSensors(stretched, sonar(0.2), {true, 64}));
}

TEST(RangeSensorsTest, AnObjectWhoseBallReachesTheConeButNotItsSurfaceNeverTakesTheReading) {
  // Found by an independent review: a double cone scaled by 1.3 whose bounding ball reaches the
  // cone beside the pole, its surface farther; the reading is always the pole's, on its surface.
  const std::string text = R"({
    "camera": {"from": [-3, 0, 1], "to": [2, 0, 1], "up": [0, 0, 1], "fov": 40},
    "profiles": {"pole": {"points": [[0, -2], [0.25, -2], [0.25, 2], [0, 2]]},
                 "spindle": {"points": [[0, -0.5], [0.5, 0], [0, 0.5]]}},
    "materials": {"grey": {"type": "diffuse", "color": [0.5, 0.5, 0.5]}},
    "objects": [{"profile": "pole", "material": "grey", "translate": [2, 0, 0]},
                {"profile": "spindle", "material": "grey", "translate": [2.53, 0.3, 0.2], "scale": [1.3, 1.3, 1.3]}]
  })";
  const robot::RangeSensors sensors(io::parseScene(text, "two.json", "."), sonar(0.3));
  const robot::RangeReading r = sensors.read(0, at(-0.2489, 0, 0), 0);
  EXPECT_EQ(r.object, 0);
  EXPECT_NEAR(r.range, 2.2489 - 0.25, kExact);
  for (int i = 0; i < 400; ++i) {
    const robot::RangeReading reading = sensors.read(0, at(-0.5 + 0.001 * i, 0, 0), 0);
    if (reading.object == 0) {
      EXPECT_NEAR(std::hypot(reading.point[0] - 2, reading.point[1]), 0.25, 1e-9) << "pose " << i;
    } else {
      ASSERT_EQ(reading.object, 1) << "pose " << i;
      // On the spindle: its meridian |r| / 0.5 + |z| / 0.5 = 1 in its own frame (scale 1.3).
      const double rr = std::hypot(reading.point[0] - 2.53, reading.point[1] - 0.3) / 1.3;
      const double zz = (reading.point[2] - 0.2) / 1.3;
      EXPECT_NEAR(rr + std::abs(zz), 0.5, 1e-9) << "pose " << i;
    }
  }
}

TEST(RangeSensorsTest, NoiseIsGaussianPerPoseAndTheGateDropsReadingsOutsideIt) {
  const io::SceneDescription scene = poleScene();
  const double stddev = 0.01;
  const robot::RangeSensors noisy(scene, sonar(0.3, 0, 100, stddev));
  std::vector<io::RobotPose> poses(4000, at(0, 0, 0));  // the same place: 1.75 to the pole
  double sum = 0, sum2 = 0;
  std::size_t count = 0;
  noisy.readAll(poses, 2, [&](std::uint64_t, std::span<const io::RangeReading> block) {
    for (const io::RangeReading& r : block) {
      sum += r.range - 1.75, sum2 += (r.range - 1.75) * (r.range - 1.75);
      ++count;
    }
  });
  ASSERT_EQ(count, poses.size());
  const double mean = sum / double(count), sd = std::sqrt(sum2 / double(count) - mean * mean);
  EXPECT_LT(std::abs(mean), 4 * stddev / std::sqrt(double(count)));  // 4 sigma of the mean
  EXPECT_NEAR(sd, stddev, 0.1 * stddev);                             // about 9 sigma of the estimate
  // The gate: a pole 1.75 away is no reading below min_range 2 or above max_range 1.5.
  EXPECT_EQ(robot::RangeSensors(scene, sonar(0.3, 2, 5)).read(0, at(0, 0, 0), 0).range, INFINITY);
  EXPECT_EQ(robot::RangeSensors(scene, sonar(0.3, 0, 1.5)).read(0, at(0, 0, 0), 0).range, INFINITY);
  EXPECT_EQ(robot::RangeSensors(scene, sonar(0.3, 1.75, 1.75)).read(0, at(0, 0, 0), 0).range, 1.75);
}

}  // namespace
}  // namespace revolve
