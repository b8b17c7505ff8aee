// The simulated lidar against closed forms, on every beam: ranges to a pole, a cone and a
// sphere-like profile from known poses, in 2-D and 3-D; a sensor at the centre of a cylinder; ROS's
// conventions (azimuths counter-clockwise from +X, both fan ends included, pitch down, inf for no
// return and for ranges outside [min, max], never clamped); noise statistics within confidence
// bounds and independent of the thread count; resolution; meshes against exact surfaces.
//
// Each beam's expected range comes from the closed form along the exact (double) beam; the lidar
// traces the float-rounded beam. The test re-solves the closed form for the beam's origin nudged
// by delta across the beam in four directions, delta = 2^-21 of the distances involved (over twice
// the float rounding of origin and direction, 2^-24 relative each, carried along the beam): the
// spread of those answers bounds what the rounding can change, and a beam whose nudges disagree
// on hit or miss grazes an edge, where either answer is right.
#include "robot/lidar.h"
#include "robot_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace revolve {
namespace {

using testing::Vec3d;
using Truth = std::function<std::optional<double>(const Vec3d& origin, const Vec3d& direction)>;

constexpr double kSceneSize = 8;  // every test scene lies within 8 m of the origin

double norm(const Vec3d& v) { return std::sqrt(testing::dot(v, v)); }

struct Tally {
  int hits = 0, misses = 0, grazing = 0;
};

// Checks one beam's return against the closed form (see the file comment).
void checkBeam(const io::BeamReturn& beam, const Vec3d& o, const Vec3d& u, const Truth& truth, Tally& tally) {
  const double delta = 0x1p-21 * (norm(o) + kSceneSize);
  // Two unit vectors across the beam.
  const Vec3d helper = std::abs(u[2]) < 0.9 ? Vec3d{0, 0, 1} : Vec3d{1, 0, 0};
  Vec3d e1{u[1] * helper[2] - u[2] * helper[1], u[2] * helper[0] - u[0] * helper[2],
           u[0] * helper[1] - u[1] * helper[0]};
  const double n1 = norm(e1);
  for (double& c : e1) c /= n1;
  const Vec3d e2{u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0]};
  const std::optional<double> exact = truth(o, u);
  std::vector<std::optional<double>> nudged;
  for (const Vec3d& e : {e1, e2}) {
    for (const double s : {-delta, delta})
      nudged.push_back(truth({o[0] + s * e[0], o[1] + s * e[1], o[2] + s * e[2]}, u));
  }
  bool agree = true;
  double low = exact ? *exact : INFINITY, high = exact ? *exact : -INFINITY;
  for (const auto& t : nudged) {
    agree = agree && t.has_value() == exact.has_value();
    if (t) low = std::min(low, *t), high = std::max(high, *t);
  }
  // The float t and the kernel add a few float ulps of the magnitudes involved.
  const double rounding = 0x1p-21 * (norm(o) + (exact ? *exact : 0.0) + kSceneSize);
  if (!agree) {
    ++tally.grazing;
    if (!std::isinf(beam.range)) {
      EXPECT_GE(beam.range, low - rounding);
      EXPECT_LE(beam.range, high + rounding);
    }
    return;
  }
  if (!exact) {
    ++tally.misses;
    EXPECT_TRUE(std::isinf(beam.range)) << "a return at " << beam.range << " where the closed form has none";
    return;
  }
  ++tally.hits;
  EXPECT_GE(beam.range, low - rounding);
  EXPECT_LE(beam.range, high + rounding);
  // The return point lies along the beam at its range.
  EXPECT_NEAR(beam.x, o[0] + beam.range * u[0], rounding);
  EXPECT_NEAR(beam.y, o[1] + beam.range * u[1], rounding);
  EXPECT_NEAR(beam.z, o[2] + beam.range * u[2], rounding);
}

io::SensorDescription sensor(int samples, double minAngle, double maxAngle, std::vector<double> elevations,
                             Vec3d position = {0, 0, 0}) {
  io::SensorDescription s;
  s.pose.position = position;
  s.horizontal = {samples, minAngle, maxAngle};
  s.planar = elevations.empty();
  s.elevations = elevations.empty() ? std::vector<double>{0.0} : elevations;
  s.rangeMin = 0;
  s.rangeMax = 100;
  return s;
}

// Every beam of every pose against `truth`, with the beams' world origins and directions written
// here from the conventions (robot yaw, then the mounting position; azimuth about +Z from +X,
// elevation up), not taken from the code under test.
Tally checkScan(const io::SceneDescription& description, const io::SensorDescription& s,
                const std::vector<io::RobotPose>& poses, const Truth& truth) {
  const scene::EmbreeScene built(description, {});
  const io::ScanTable scan = robot::Lidar(built, s).scan(poses);
  EXPECT_EQ(scan.poses, poses.size());
  Tally tally;
  const double step =
      s.horizontal.samples > 1 ? (s.horizontal.maxAngle - s.horizontal.minAngle) / (s.horizontal.samples - 1) : 0;
  for (std::size_t p = 0; p < poses.size(); ++p) {
    const io::RobotPose& pose = poses[p];
    const auto& m = s.pose.position;
    const Vec3d o{pose.x + m[0] * std::cos(pose.yaw) - m[1] * std::sin(pose.yaw),
                  pose.y + m[0] * std::sin(pose.yaw) + m[1] * std::cos(pose.yaw), pose.z + m[2]};
    for (std::size_t ring = 0; ring < s.elevations.size(); ++ring) {
      const double e = s.elevations[ring];
      for (int i = 0; i < s.horizontal.samples; ++i) {
        const double phi = pose.yaw + s.pose.yaw + s.horizontal.minAngle + i * step;
        const Vec3d u{std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e)};
        SCOPED_TRACE("pose " + std::to_string(p) + " ring " + std::to_string(ring) + " beam " + std::to_string(i));
        checkBeam(scan.at(p, ring, std::size_t(i)), o, u, truth, tally);
      }
    }
  }
  return tally;
}

void expectMostlyDecided(const Tally& tally) {
  // Grazing beams are the few within a nudge of a silhouette or an edge; the rest are checked tightly.
  EXPECT_GT(tally.hits, 0);
  EXPECT_LE(tally.grazing, (tally.hits + tally.misses) / 50) << tally.grazing << " grazing beams";
  std::printf("hits %d, misses %d, grazing %d\n", tally.hits, tally.misses, tally.grazing);
}

const std::vector<io::RobotPose> kPoses{{0, 0, 0, 0}, {-1, 3, 0, -0.7}, {4, -0.5, 0, 2.5}, {2.5, 1.5, 0.25, 4.0}};

TEST(LidarTest, RangesToAPoleFromKnownPosesOnEveryBeam) {
  // A pole of radius 0.25 from z = 0 to 2 at (2, 1); the sensor mounted 0.125 ahead of the robot's
  // origin at height 0.5: a 2-D scan (361 beams a turn) and a 3-D one (9 x 91, +-0.5 rad).
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, 0, 2), testing::at(2, 1), "pole"}});
  const Truth pole = [](const Vec3d& o, const Vec3d& u) { return testing::rayCappedCylinder(o, u, 2, 1, 0.25, 0, 2); };
  expectMostlyDecided(checkScan(scene, sensor(361, -M_PI, M_PI, {}, {0.125, 0, 0.5}), kPoses, pole));
  expectMostlyDecided(checkScan(
      scene, sensor(91, -M_PI, M_PI, {-0.5, -0.375, -0.25, -0.125, 0, 0.125, 0.25, 0.375, 0.5}, {0.125, 0, 0.5}),
      kPoses, pole));
}

TEST(LidarTest, RangesToAConeOnEveryBeam) {
  // A cone of base radius 0.5 and height 1 at (1.5, -0.5, 0.25): sloped side, apex, base disc.
  const io::SceneDescription scene =
      testing::sceneOf({{std::vector<Point2>{{0, 0}, {0.5, 0}, {0, 1}}, testing::at(1.5, -0.5, 0.25), "cone"}});
  const Truth cone = [](const Vec3d& o, const Vec3d& u) { return testing::rayCone(o, u, 1.5, -0.5, 0.25, 0.5, 1.0); };
  expectMostlyDecided(
      checkScan(scene, sensor(121, -M_PI, M_PI, {-0.3, -0.1, 0, 0.1, 0.3, 0.6}, {0, 0, 0.5}), kPoses, cone));
}

TEST(LidarTest, RangesToASphereLikeProfileLieBetweenItsSpheres) {
  // A half circle of radius 0.75 in 256 chords, about (1, 2, 0.75): the surface lies between the
  // sphere and the sphere of radius 0.75 cos(pi / 512). Every beam that meets the inner sphere hits
  // between the two entries; every beam missing the outer sphere returns nothing.
  const double radius = 0.75, inner = radius * std::cos(M_PI / 512);
  const Vec3d centre{1, 2, 0.75};
  const io::SceneDescription scene =
      testing::sceneOf({{testing::sphereProfile(radius, 256), testing::at(1, 2, 0.75), "ball"}});
  const scene::EmbreeScene built(scene, {});
  const io::SensorDescription s = sensor(181, -M_PI, M_PI, {-0.4, -0.2, 0, 0.2, 0.4}, {0, 0, 0.6});
  const io::ScanTable scan = robot::Lidar(built, s).scan(kPoses);
  int between = 0, outside = 0;
  for (std::size_t p = 0; p < kPoses.size(); ++p) {
    const Vec3d o{kPoses[p].x, kPoses[p].y, kPoses[p].z + 0.6};
    for (std::size_t ring = 0; ring < s.elevations.size(); ++ring) {
      for (int i = 0; i < 181; ++i) {
        const double phi = kPoses[p].yaw - M_PI + i * (2 * M_PI / 180), e = s.elevations[ring];
        const Vec3d u{std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e)};
        const io::BeamReturn& beam = scan.at(p, ring, std::size_t(i));
        const std::optional<double> outer = testing::raySphere(o, u, centre, radius + 0x1p-20);
        const std::optional<double> innerHit = testing::raySphere(o, u, centre, inner - 0x1p-20);
        // 2^-20 m: the float rounding of the beam (2^-24 of ~8 m) with room.
        if (innerHit) {
          ++between;
          EXPECT_GE(beam.range, *outer) << p << " " << ring << " " << i;
          EXPECT_LE(beam.range, *innerHit) << p << " " << ring << " " << i;
        } else if (!outer) {
          ++outside;
          EXPECT_TRUE(std::isinf(beam.range)) << p << " " << ring << " " << i;
        } else if (!std::isinf(beam.range)) {
          EXPECT_GE(beam.range, *outer);  // in the thin shell's shadow: a hit, if any, is in it
        }
      }
    }
  }
  EXPECT_GT(between, 100);
  EXPECT_GT(outside, 100);
}

TEST(LidarTest, SensorAtTheCentreOfACylinderReadsItsRadius) {
  // An open tube of radius 2 around the sensor, 3 m above and below it: in 2-D every beam reads 2;
  // in 3-D a beam of elevation e reads 2 / cos(e), 2 horizontally.
  const double radius = 2;
  const io::SceneDescription scene =
      testing::sceneOf({{std::vector<Point2>{{radius, -3}, {radius, 3}}, testing::at(0, 0), "tube"}});
  const scene::EmbreeScene built(scene, {});
  const double tolerance = 0x1p-21 * 4 * radius;  // float ulps of the range (2^-23 of 4 m) with room
  const io::ScanTable planar = robot::Lidar(built, sensor(3600, -M_PI, M_PI, {})).scan(std::vector<io::RobotPose>{{}});
  ASSERT_EQ(planar.points.size(), 3600u);
  for (const io::BeamReturn& beam : planar.points) {
    EXPECT_NEAR(beam.range, radius, tolerance);
    EXPECT_NEAR(std::hypot(beam.x, beam.y), radius, tolerance);
    EXPECT_EQ(beam.object, 0);
  }
  std::vector<double> elevations;
  for (int k = 0; k < 16; ++k) elevations.push_back(-0.26 + k * 0.52 / 15);
  const io::ScanTable spatial = robot::Lidar(built, sensor(1800, -M_PI, M_PI * (1 - 2.0 / 1800), elevations))
                                    .scan(std::vector<io::RobotPose>{{}});
  ASSERT_EQ(spatial.points.size(), 16u * 1800);
  for (std::size_t ring = 0; ring < 16; ++ring) {
    for (std::size_t i = 0; i < 1800; ++i) {
      const io::BeamReturn& beam = spatial.at(0, ring, i);
      EXPECT_NEAR(beam.range, radius / std::cos(elevations[ring]), tolerance);
      EXPECT_NEAR(std::hypot(beam.x, beam.y), radius, tolerance);
      EXPECT_NEAR(beam.z, radius * std::tan(elevations[ring]), tolerance);
    }
  }
}

TEST(LidarTest, AnglesFollowRosConventions) {
  // Poles 3 m away on +Y and on -X, nothing elsewhere; a floor 0.5 below the sensor.
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, -1, 1), testing::at(0, 3), "north"},
                        {testing::cylinderProfile(0.25, -1, 1), testing::at(-3, 0), "west"}},
                       {{{{-20, -20, -0.5}, {20, -20, -0.5}, {20, 20, -0.5}, {-20, 20, -0.5}}}});
  const scene::EmbreeScene built(scene, {});
  // Four beams: 0, pi/2, pi, 3 pi/2 from +X (both fan ends included: 3 equal steps).
  io::SensorDescription s = sensor(4, 0, 1.5 * M_PI, {});
  const io::ScanTable scan = robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{}});
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(scan.azimuths[i], i * M_PI / 2);
  EXPECT_TRUE(std::isinf(scan.at(0, 0, 0).range));  // +X: nothing
  EXPECT_EQ(scan.at(0, 0, 1).object, 0);            // pi/2, counter-clockwise: +Y, the north pole
  EXPECT_NEAR(scan.at(0, 0, 1).range, 2.75, 1e-6);
  EXPECT_EQ(scan.at(0, 0, 2).object, 1);            // pi: -X, the west pole
  EXPECT_TRUE(std::isinf(scan.at(0, 0, 3).range));  // -Y: nothing
  // The robot turned a quarter turn left: its +X is the world's +Y.
  const io::ScanTable turned = robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{0, 0, 0, M_PI / 2}});
  EXPECT_EQ(turned.at(0, 0, 0).object, 0);
  EXPECT_EQ(turned.at(0, 0, 1).object, 1);
  // The sensor's own yaw composes with the robot's.
  s.pose.yaw = M_PI;
  EXPECT_EQ(robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{0, 0, 0, -M_PI / 2}}).at(0, 0, 0).object, 0);
  // ROS pitch is about +Y: positive pitch turns +X down (towards -Z), so the beam meets the floor
  // 0.5 below at range 0.5 / sin(pitch).
  io::SensorDescription pitched = sensor(1, 0, 0, {});
  pitched.pose.pitch = 0.25;
  const io::BeamReturn down = robot::Lidar(built, pitched).scan(std::vector<io::RobotPose>{{}}).at(0, 0, 0);
  EXPECT_EQ(down.object, 2);  // the floor quad: objects.size() + 0
  EXPECT_NEAR(down.range, 0.5 / std::sin(0.25), 1e-6);
  EXPECT_GT(down.x, 0);
  // Positive elevation is up: ring 0 (-0.25) meets the floor, ring 1 (+0.25) the sky.
  const io::ScanTable rings = robot::Lidar(built, sensor(1, 0, 0, {-0.25, 0.25})).scan(std::vector<io::RobotPose>{{}});
  EXPECT_NEAR(rings.at(0, 0, 0).range, 0.5 / std::sin(0.25), 1e-6);
  EXPECT_TRUE(std::isinf(rings.at(0, 1, 0).range));
  // Roll is about +X: a quarter turn back (-pi/2) maps the sensor's +Y to -Z, so the beam at azimuth
  // pi/2 looks down at the floor, 0.5 below.
  io::SensorDescription rolled = sensor(3, 0, M_PI, {});
  rolled.pose.roll = -M_PI / 2;
  EXPECT_NEAR(robot::Lidar(built, rolled).scan(std::vector<io::RobotPose>{{}}).at(0, 0, 1).range, 0.5, 1e-6);
}

TEST(LidarTest, NoReturnBeyondMaxOrBelowMinIsInfNeverClamped) {
  const io::SceneDescription scene =
      testing::sceneOf({{std::vector<Point2>{{2, -3}, {2, 3}}, testing::at(0, 0), "tube"}});
  const scene::EmbreeScene built(scene, {});
  io::SensorDescription s = sensor(100, -M_PI, M_PI, {});
  s.rangeMax = 1.5;  // the wall is at 2: beyond max
  for (const io::BeamReturn& beam : robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{}}).points) {
    EXPECT_TRUE(std::isinf(beam.range));
    EXPECT_EQ(beam.object, -1);
  }
  s.rangeMin = 2.5;  // below min
  s.rangeMax = 10;
  for (const io::BeamReturn& beam : robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{}}).points)
    EXPECT_TRUE(std::isinf(beam.range));
  s.rangeMin = 1.5;
  for (const io::BeamReturn& beam : robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{}}).points)
    EXPECT_NEAR(beam.range, 2, 1e-6);
}

TEST(LidarTest, NoiseHasItsMeanAndStddevWhateverTheThreadCount) {
  // 5 poses x 20,000 beams at a wall 2 away: range = 2 + mean + stddev g, g standard normal.
  const io::SceneDescription scene =
      testing::sceneOf({{std::vector<Point2>{{2, -3}, {2, 3}}, testing::at(0, 0), "tube"}});
  const scene::EmbreeScene built(scene, {});
  io::SensorDescription s = sensor(20000, -M_PI, M_PI, {});
  s.noiseMean = 0.05;
  s.noiseStddev = 0.1;
  s.noiseSeed = 7;
  const std::vector<io::RobotPose> poses(5, io::RobotPose{});
  const io::ScanTable one = robot::Lidar(built, s).scan(poses, 1);
  const io::ScanTable two = robot::Lidar(built, s).scan(poses, 2);
  ASSERT_EQ(one.points.size(), two.points.size());
  for (std::size_t i = 0; i < one.points.size(); ++i) {
    ASSERT_EQ(one.points[i].range, two.points[i].range) << "beam " << i;  // bit for bit
    ASSERT_EQ(one.points[i].x, two.points[i].x);
  }
  const double n = double(one.points.size());
  double sum = 0, sum2 = 0, within = 0;
  for (const io::BeamReturn& beam : one.points) {
    const double e = beam.range - 2.0;
    sum += e, sum2 += e * e;
    within += std::abs(e - s.noiseMean) <= s.noiseStddev ? 1 : 0;
  }
  const double mean = sum / n, stddev = std::sqrt((sum2 - n * mean * mean) / (n - 1));
  // Five standard errors: a correct sampler fails one seed in 1.7 million.
  EXPECT_NEAR(mean, s.noiseMean, 5 * s.noiseStddev / std::sqrt(n));
  EXPECT_NEAR(stddev, s.noiseStddev, 5 * s.noiseStddev / std::sqrt(2 * (n - 1)));
  const double p = std::erf(1 / std::sqrt(2.0));  // P(|g| <= 1) = 0.6827
  EXPECT_NEAR(within / n, p, 5 * std::sqrt(p * (1 - p) / n));
  // The seed decides the noise: another seed, other ranges (all 100,000 differ but a few).
  s.noiseSeed = 8;
  const io::ScanTable other = robot::Lidar(built, s).scan(poses, 2);
  int same = 0;
  for (std::size_t i = 0; i < one.points.size(); ++i) same += one.points[i].range == other.points[i].range ? 1 : 0;
  EXPECT_LT(same, 100);
  // Beams without a return get no noise: they stay inf.
  const io::SceneDescription empty =
      testing::sceneOf({{std::vector<Point2>{{2, 5}, {2, 6}}, testing::at(0, 0), "above"}});
  const scene::EmbreeScene nothing(empty, {});
  for (const io::BeamReturn& beam : robot::Lidar(nothing, s).scan(poses, 2).points) EXPECT_TRUE(std::isinf(beam.range));
}

TEST(LidarTest, ResolutionRoundsRangesToItsMultiples) {
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, -1, 1), testing::at(2.03, 0.41), "pole"}});
  const scene::EmbreeScene built(scene, {});
  io::SensorDescription s = sensor(2001, -0.5, 0.5, {});
  s.resolution = 0.01;
  int returns = 0;
  for (const io::BeamReturn& beam : robot::Lidar(built, s).scan(std::vector<io::RobotPose>{{}}).points) {
    if (std::isinf(beam.range)) continue;
    ++returns;
    // A multiple of 0.01 as stored in a float: within its rounding (2^-24 of the range).
    EXPECT_NEAR(beam.range, std::round(beam.range / 0.01) * 0.01, 0x1p-23 * beam.range);
  }
  EXPECT_GT(returns, 100);
}

TEST(LidarTest, MeshRangesAreLongerAndImproveWithSlices) {
  // A tessellated pole is inscribed in the exact one: its ranges are never shorter, and its mean
  // error falls with the slice count (the README measures how much).
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, -1, 1), testing::at(2, 0), "pole"}});
  const io::SensorDescription s = sensor(4001, -0.2, 0.2, {});
  const std::vector<io::RobotPose> poses{{}};
  const scene::EmbreeScene exactScene(scene, {});
  const io::ScanTable exact = robot::Lidar(exactScene, s).scan(poses);
  double previous = INFINITY;
  for (const std::uint32_t slices : {8u, 16u, 64u}) {
    scene::BuildSettings mesh;
    mesh.mesh = true;
    mesh.slices = slices;
    const scene::EmbreeScene meshScene(scene, mesh);
    const io::ScanTable meshed = robot::Lidar(meshScene, s).scan(poses);
    double sum = 0;
    int both = 0;
    for (std::size_t i = 0; i < exact.points.size(); ++i) {
      if (std::isinf(exact.points[i].range) || std::isinf(meshed.points[i].range)) continue;
      EXPECT_GE(meshed.points[i].range, exact.points[i].range - 1e-6);
      sum += meshed.points[i].range - exact.points[i].range, ++both;
    }
    ASSERT_GT(both, 1000);
    EXPECT_LT(sum / both, previous);
    previous = sum / both;
  }
}

// Intensity: a pole of radius a (axis at (c, 0)), reflectivity 0.6, scanned in its mid-plane from
// the origin. Every return's intensity is r |n . d| / range^2 with the pole's radial normal at the
// returned point and the beam's direction written here from the conventions; to float rounding for
// the exact surface, and the facets' error for meshes, which falls with the slices and is reported.
// The rounding: the returned point is a float, within 2^-23 of its coordinates (about 2.5 here) of
// the surface, so the radial normal made from it is off by up to 2^-23 * 2.5 / a, and the
// library's float normal by a few 2^-24: |n . d| is known to 2^-18 absolute, the intensity to 2^-18
// of the head-on intensity r / range^2 (the range itself, to 2^-22, adds 2^-21 relative).
TEST(LidarTest, IntensityIsReflectivityTimesCosineOverRangeSquared) {
  const double a = 0.25, c = 2, reflectivity = 0.6;
  io::SceneDescription scene = testing::sceneOf({{testing::cylinderProfile(a, -1, 1), testing::at(c, 0), "pole"}});
  scene.objects[0].reflectivity = reflectivity;
  const io::SensorDescription s = sensor(2001, -0.2, 0.2, {});
  const std::vector<io::RobotPose> poses{{}};
  const auto expected = [&](const io::BeamReturn& beam, double phi) {
    const Vec3d d{std::cos(phi), std::sin(phi), 0};
    const Vec3d n{(double(beam.x) - c) / a, double(beam.y) / a, 0};  // radial, unit on the surface
    const double range = double(beam.range);
    return reflectivity * std::abs(testing::dot(n, d)) / (range * range);
  };
  double previousError = INFINITY;
  for (const std::uint32_t slices : {0u, 16u, 64u, 256u}) {  // 0: the exact surface
    scene::BuildSettings build;
    build.mesh = slices > 0;
    build.slices = slices > 0 ? slices : 64;
    const scene::EmbreeScene built(scene, build);
    const io::ScanTable scan = robot::Lidar(built, s).scan(poses);
    double worst = 0;
    int returns = 0;
    for (int i = 0; i < s.horizontal.samples; ++i) {
      const io::BeamReturn& beam = scan.at(0, 0, std::size_t(i));
      if (std::isinf(beam.range)) continue;
      ++returns;
      const double phi =
          s.horizontal.minAngle + i * (s.horizontal.maxAngle - s.horizontal.minAngle) / (s.horizontal.samples - 1);
      const double want = expected(beam, phi);
      EXPECT_GE(beam.intensity, 0);
      if (slices == 0) {
        const double range = double(beam.range);
        EXPECT_NEAR(beam.intensity, want, 0x1p-18 * reflectivity / (range * range) + 0x1p-21 * want) << "beam " << i;
      }
      worst = std::max(worst, std::abs(double(beam.intensity) - want) / (reflectivity / (c * c)));
    }
    ASSERT_GT(returns, 400);
    std::printf("intensity, %s: largest error %.3g of the head-on intensity\n",
                slices == 0 ? "exact" : (std::to_string(slices) + "-slice mesh").c_str(), worst);
    if (slices > 0) {
      EXPECT_LT(worst, previousError);  // the facet banding shrinks as the facets narrow
      previousError = worst;
    } else {
      EXPECT_LT(worst, 1e-5);
    }
  }
}

TEST(LidarTest, IntensityNoiseIsRelativeSeededAndLeavesRangesAlone) {
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.25, -1, 1), testing::at(2, 0), "pole"}});
  io::SensorDescription s = sensor(2001, -0.1, 0.1, {});
  const scene::EmbreeScene built(scene, {});
  const std::vector<io::RobotPose> poses{{}};
  const io::ScanTable quiet = robot::Lidar(built, s).scan(poses);
  s.intensityNoiseStddev = 0.1;
  s.intensityNoiseSeed = 7;
  const io::ScanTable noisy = robot::Lidar(built, s).scan(poses, 1);
  const io::ScanTable again = robot::Lidar(built, s).scan(poses, 2);
  double sum = 0, sumSquares = 0;
  int n = 0;
  for (std::size_t i = 0; i < quiet.points.size(); ++i) {
    EXPECT_EQ(noisy.points[i].range, quiet.points[i].range);          // ranges untouched
    EXPECT_EQ(noisy.points[i].intensity, again.points[i].intensity);  // seeded per beam, not per thread
    if (std::isinf(quiet.points[i].range)) continue;
    const double z = (double(noisy.points[i].intensity) / quiet.points[i].intensity - 1) / 0.1;
    sum += z, sumSquares += z * z, ++n;
  }
  ASSERT_GT(n, 1000);
  const double mean = sum / n, stddev = std::sqrt(sumSquares / n - mean * mean);
  // Standard normal deviates: the mean within 4 / sqrt(n), the standard deviation within 10%.
  EXPECT_LT(std::abs(mean), 4 / std::sqrt(double(n)));
  EXPECT_NEAR(stddev, 1, 0.1);
}

}  // namespace
}  // namespace revolve
