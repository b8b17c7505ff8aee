// Time and motion: a spinning sensor's beams carry their firing time (column k of a sweep at
// k / (samples x rotation_rate)), and with timed poses each beam is traced from where the moving
// sensor is when it fires. Checked against closed forms written here from those rules: a sensor
// driving at constant speed toward a wall, the interpolated frame (position linear, yaw the
// shorter way, the path ending at the last pose), and a scan traced in parts matching the whole.
#include "robot/lidar.h"
#include "robot/sensor_motion.h"
#include "robot_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

namespace revolve {
namespace {

using testing::Vec3d;

io::RobotPose timedPose(double time, double x, double y, double yaw) {
  io::RobotPose pose;
  pose.time = time, pose.x = x, pose.y = y, pose.yaw = yaw;
  return pose;
}

io::SensorDescription spinningSensor(int samples, double minAngle, double maxAngle, double rate,
                                     std::vector<double> elevations = {}) {
  io::SensorDescription s;
  s.pose.position = {0, 0, 0.5};
  s.horizontal = {samples, minAngle, maxAngle};
  s.planar = elevations.empty();
  s.elevations = elevations.empty() ? std::vector<double>{0.0} : elevations;
  s.rangeMin = 0;
  s.rangeMax = 100;
  s.rotationRate = rate;
  return s;
}

// A wall facing the sensor across the plane x = `at`, 12 m wide and 6 m high about the origin.
io::SceneDescription wallAt(double at) {
  return testing::sceneOf({}, {{Vec3d{at, -6, -3}, Vec3d{at, 6, -3}, Vec3d{at, 6, 3}, Vec3d{at, -6, 3}}});
}

TEST(LidarMotionTest, ASensorDrivingTowardAWallMeasuresFromWhereItIsWhenEachBeamFires) {
  const double wall = 6, speed = 3, rate = 10;
  const int samples = 401;
  const io::SensorDescription s = spinningSensor(samples, -0.5, 0.5, rate);
  // Along +x at `speed`, one pose every half second; the sweeps of the first two poses are traced
  // (the third only carries the path on), each lasting (samples - 1) / (samples rate) = 0.0998 s.
  const std::vector<io::RobotPose> path{timedPose(0, 0, 0, 0), timedPose(0.5, 1.5, 0, 0), timedPose(1, 3, 0, 0)};
  const scene::EmbreeScene built(wallAt(wall), {});
  const robot::Lidar lidar(built, s);
  std::vector<io::BeamReturn> beams(2 * std::size_t(samples));
  lidar.scan(
      path,
      [&](std::uint64_t first, std::span<const io::BeamReturn> block) {
        std::copy(block.begin(), block.end(), beams.begin() + std::ptrdiff_t(first));
      },
      0, nullptr, 0, 2);
  double largestShift = 0;
  for (std::size_t sweep = 0; sweep < 2; ++sweep) {
    for (int k = 0; k < samples; ++k) {
      SCOPED_TRACE("sweep " + std::to_string(sweep) + ", column " + std::to_string(k));
      const io::BeamReturn& beam = beams[sweep * std::size_t(samples) + std::size_t(k)];
      const double time = double(k) / (samples * rate);
      EXPECT_EQ(beam.time, float(time));
      const double azimuth = -0.5 + k * 1.0 / (samples - 1);
      const double x = speed * (path[sweep].time + time);  // where the sensor is when the beam fires
      const double range = (wall - x) / std::cos(azimuth);
      ASSERT_FALSE(std::isinf(beam.range));
      // Origin and direction rounded to float, the hit's distance and the range returned in float,
      // each within 2^-24 of the lengths involved: 2^-20 leaves a margin of four.
      const double tolerance = 0x1p-20 * (wall + range);
      EXPECT_NEAR(beam.range, range, tolerance);
      EXPECT_NEAR(beam.x, wall, tolerance);  // every return lies on the wall
      EXPECT_NEAR(beam.y, range * std::sin(azimuth), tolerance);
      EXPECT_NEAR(beam.z, 0.5, tolerance);
      largestShift = std::max(largestShift, (wall - speed * path[sweep].time) / std::cos(azimuth) - double(beam.range));
    }
  }
  // The distortion is there: the last beam of a sweep is 0.3 m (speed x sweep) nearer than at rest.
  EXPECT_GT(largestShift, 0.29);
}

TEST(LidarMotionTest, TheFrameMovesLinearlyTurnsTheShorterWayAndStopsAtTheLastPose) {
  io::SensorPose mount;
  mount.position = {1, 0, 0.25};
  // From yaw 3 to yaw -3 in 2 s: the shorter turn is 2 pi - 6 = 0.283 rad counter-clockwise,
  // through pi, not 6 rad clockwise.
  const std::vector<io::RobotPose> path{timedPose(0, 0, 0, 3), timedPose(2, 2, -4, -3)};
  const robot::SensorMotion motion(mount, path);
  ASSERT_TRUE(motion.moving());
  const auto expectFrame = [](const robot::SensorFrame& frame, double x, double y, double yaw) {
    EXPECT_NEAR(frame.origin[0], x + std::cos(yaw), 1e-14);  // the mounting offset turned with the robot
    EXPECT_NEAR(frame.origin[1], y + std::sin(yaw), 1e-14);
    EXPECT_NEAR(frame.origin[2], 0.25, 1e-14);
    const Vec3d forward = frame.rotate({1, 0, 0});
    EXPECT_NEAR(forward[0], std::cos(yaw), 1e-14);
    EXPECT_NEAR(forward[1], std::sin(yaw), 1e-14);
  };
  const double turn = 2 * std::numbers::pi - 6;
  expectFrame(motion.at(0, 0.5), 0.5, -1, 3 + 0.25 * turn);
  expectFrame(motion.at(0, 1.5), 1.5, -3, 3 + 0.75 * turn);
  expectFrame(motion.at(0, 3), 2, -4, -3);  // after the last pose's time: there, at rest
  expectFrame(motion.at(1, 0.1), 2, -4, -3);
  // At a pose's own time the frame is the pose's, bit for bit.
  EXPECT_EQ(motion.at(0, 0).origin, motion.atPose(0).origin);
  EXPECT_EQ(motion.at(0, 2).origin, motion.atPose(1).origin);
  EXPECT_EQ(motion.at(0, 2).rotation, motion.atPose(1).rotation);

  // Without times, or with a single pose, the sensor does not move.
  std::vector<io::RobotPose> untimed = path;
  for (io::RobotPose& p : untimed) p.time = std::nan("");
  EXPECT_FALSE(robot::SensorMotion(mount, untimed).moving());
  EXPECT_EQ(robot::SensorMotion(mount, untimed).at(0, 0.5).origin,
            robot::SensorMotion(mount, untimed).atPose(0).origin);
  EXPECT_FALSE(robot::SensorMotion(mount, std::span(path.data(), 1)).moving());
}

// A robot tilted by roll and pitch (R = Rz(yaw) Ry(pitch) Rx(roll), ROS's fixed axes): a level
// sensor h above the floor on it sees the floor along its forward beam at h / sin(pitch) (positive
// pitch turns +X down) and along its left beam at h / sin(-roll) (positive roll turns +Y up); and
// with timed poses the pitch, like the yaw, turns linearly between the poses.
TEST(LidarMotionTest, ATiltedRobotsBeamsFollowItsRollAndPitch) {
  const double h = 0.5;
  const scene::EmbreeScene built(
      testing::sceneOf({}, {{Vec3d{-50, -50, 0}, Vec3d{50, -50, 0}, Vec3d{50, 50, 0}, Vec3d{-50, 50, 0}}}), {});
  io::SensorDescription s = spinningSensor(2, 0, std::numbers::pi / 2, 0);  // forward, then left
  s.rangeMax = 1000;
  io::RobotPose pose;
  pose.x = 3, pose.y = -2, pose.yaw = 0.7;
  pose.pitch = 0.3;
  pose.roll = -0.2;
  const io::ScanTable scan = robot::Lidar(built, s).scan(std::vector<io::RobotPose>{pose});
  // The beams' directions in the world, by hand: Rz(yaw) Ry(pitch) Rx(roll) applied to +X and +Y.
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw), cp = std::cos(pose.pitch), sp = std::sin(pose.pitch);
  const double cr = std::cos(pose.roll), sr = std::sin(pose.roll);
  const Vec3d forward{cy * cp, sy * cp, -sp};
  const Vec3d left{cy * sp * sr - sy * cr, sy * sp * sr + cy * cr, cp * sr};
  for (const auto& [column, d] : {std::pair{0, forward}, std::pair{1, left}}) {
    SCOPED_TRACE(column);
    const io::BeamReturn& r = scan.at(0, 0, std::size_t(column));
    // The sensor sits h up the robot's own z axis: the robot's position plus R (0, 0, h).
    const Vec3d origin{3 + h * (cy * sp * cr + sy * sr), -2 + h * (sy * sp * cr - cy * sr), h * cp * cr};
    const double range = -origin[2] / d[2];
    ASSERT_FALSE(std::isinf(r.range));
    EXPECT_NEAR(r.range, range, 0x1p-20 * (range + 4));
    EXPECT_NEAR(r.x, origin[0] + range * d[0], 0x1p-20 * (range + 4));
    EXPECT_NEAR(r.y, origin[1] + range * d[1], 0x1p-20 * (range + 4));
    EXPECT_NEAR(r.z, 0, 0x1p-20 * (range + 4));
  }
  // Moving: the pitch from 0.1 to 0.3 and x from 0 to 1 in 1 s; half way, the frame is pitched
  // by 0.2 at x = 0.5.
  io::RobotPose a, b;
  a.time = 0, a.pitch = 0.1;
  b.time = 1, b.pitch = 0.3, b.x = 1;
  io::SensorPose mount;
  mount.position = {0, 0, h};
  const std::vector<io::RobotPose> path{a, b};  // the motion keeps a reference to it
  const robot::SensorMotion motion(mount, path);
  const robot::SensorFrame half = motion.at(0, 0.5);
  const Vec3d ahead = half.rotate({1, 0, 0});
  EXPECT_NEAR(ahead[0], std::cos(0.2), 1e-15);
  EXPECT_NEAR(ahead[2], -std::sin(0.2), 1e-15);
  EXPECT_NEAR(half.origin[0], 0.5 + h * std::sin(0.2), 1e-15);
  EXPECT_NEAR(half.origin[2], h * std::cos(0.2), 1e-15);
}

TEST(LidarMotionTest, BeamsCarryTheirColumnsTimeAndWithoutTimedPosesTheScanIsAtRest) {
  const int samples = 360;
  const double rate = 20;
  const io::SensorDescription spinning = spinningSensor(samples, -M_PI, M_PI * 358 / 360, rate, {-0.1, 0, 0.1});
  io::SensorDescription still = spinning;
  still.rotationRate = 0;
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.3, -1, 1), testing::at(2, 0.5), "pole"}});
  const scene::EmbreeScene built(scene, {});
  const std::vector<io::RobotPose> poses{{0, 0, 0, 0.3}, {0.5, -0.5, 0, 1.1}};  // no time column
  const io::ScanTable moving = robot::Lidar(built, spinning).scan(poses);
  const io::ScanTable rest = robot::Lidar(built, still).scan(poses);
  int returns = 0;
  for (std::size_t pose = 0; pose < 2; ++pose) {
    for (std::size_t ring = 0; ring < 3; ++ring) {
      for (std::size_t column = 0; column < std::size_t(samples); ++column) {
        const io::BeamReturn& a = moving.at(pose, ring, column);
        const io::BeamReturn& b = rest.at(pose, ring, column);
        EXPECT_EQ(a.time, float(double(column) / (samples * rate)));  // every ring of a column at once
        EXPECT_EQ(b.time, 0);
        EXPECT_EQ(a.range, b.range);  // today's scan, beam for beam
        if (!std::isinf(a.range)) {
          ++returns;
          EXPECT_EQ(a.x, b.x);
          EXPECT_EQ(a.intensity, b.intensity);
        }
      }
    }
  }
  EXPECT_GT(returns, 20);
}

// A scan traced in parts, each part's poses reaching to the first pose after its last sweep's end
// (what revolve.shard_poses gives the Dask example), equals the whole scan bit for bit, on 1 or 2
// threads. The poses come every 0.04 s and a sweep lasts 0.1 s: a sweep spans three segments.
TEST(LidarMotionTest, AScanTracedInPartsIsTheWholeScanBitForBit) {
  const int samples = 500;
  const double rate = 10, sweep = double(samples - 1) / (samples * rate);
  const io::SensorDescription s = spinningSensor(samples, -M_PI, M_PI, rate, {-0.05, 0.05});
  const io::SceneDescription scene =
      testing::sceneOf({{testing::cylinderProfile(0.4, -1, 1), testing::at(2, 0), "pole"},
                        {testing::cylinderProfile(0.3, -1, 1), testing::at(-1, 1.5), "pole"}});
  std::vector<io::RobotPose> path;
  for (int i = 0; i < 9; ++i) path.push_back(timedPose(0.04 * i, 0.1 * i, 0.02 * i * i, 0.3 * i));
  const scene::EmbreeScene built(scene, {});
  const robot::Lidar lidar(built, s);
  const io::ScanTable whole = lidar.scan(path, 2);
  for (const auto& [first, count] : {std::pair<std::size_t, std::size_t>{0, 3}, {3, 4}, {7, 2}}) {
    std::size_t end = first + count;
    while (end < path.size() && path[end - 1].time <= path[first + count - 1].time + sweep) ++end;
    const std::span<const io::RobotPose> part(path.data() + first, end - first);
    for (const int threads : {1, 2}) {
      SCOPED_TRACE("part from pose " + std::to_string(first) + ", threads " + std::to_string(threads));
      std::vector<io::BeamReturn> beams(count * lidar.beamsPerPose());
      lidar.scan(
          part,
          [&](std::uint64_t at, std::span<const io::BeamReturn> block) {
            std::copy(block.begin(), block.end(), beams.begin() + std::ptrdiff_t(at));
          },
          threads, nullptr, first, count);
      for (std::size_t b = 0; b < beams.size(); ++b) {
        const io::BeamReturn& want = whole.points[first * lidar.beamsPerPose() + b];
        ASSERT_EQ(std::memcmp(&beams[b], &want, sizeof want), 0) << "beam " << b;
      }
    }
  }
}

}  // namespace
}  // namespace revolve
