// The lidar's beams traced in packets equal single beams, bit for bit: the bundled robot world's
// fans (every ring of the 3-D example sensor from every pose of the example path) through
// EmbreeScene's 8-wide query against its one-ray query, packets starting at every offset of a
// ring so that partial packets at a ring's end are covered; and a whole scan of a sensor whose
// rings end part-way through a packet against the single ray of each beam. The expected values are
// the single-ray peers' (the contract: scans stay what single rays gave).
#include "io/poses_file.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "robot/lidar.h"
#include "robot/sensor_rig.h"
#include "scene/embree_scene.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace revolve {
namespace {

const std::string kSource = REVOLVE_SOURCE_DIR;
constexpr std::size_t kLanes = scene::EmbreeScene::kPacketRays;

// The float ray of the beam at (azimuth, elevation) from `frame`, as a range-finder makes it.
Ray beamRay(const robot::SensorFrame& frame, double azimuth, double elevation) {
  const robot::Vec3d d = frame.rotate(robot::beamDirection(azimuth, elevation));
  Ray ray;
  ray.origin = {float(frame.origin[0]), float(frame.origin[1]), float(frame.origin[2])};
  ray.direction = {float(d[0]), float(d[1]), float(d[2])};
  return ray;
}

TEST(LidarPacketTest, FanPacketsEqualSingleBeams) {
  const io::SceneDescription world = io::readScene(kSource + "/scenes/robot_world.json");
  for (const bool mesh : {false, true}) {
    scene::BuildSettings build;
    build.mesh = mesh;
    const scene::EmbreeScene built(world, build);
    const io::SensorDescription sensor = io::readSensor(kSource + "/examples/robot/lidar_3d.json");
    const std::vector<io::RobotPose> poses = io::readPosesCsv(kSource + "/examples/robot/path.csv");
    const std::vector<double> azimuths = io::fanAngles(sensor.horizontal);
    std::size_t hits = 0, beams = 0;
    for (std::size_t p = 0; p < poses.size(); ++p) {
      const robot::SensorFrame frame = robot::sensorFrame(sensor.pose, poses[p]);
      for (std::size_t ring = 0; ring < sensor.elevations.size(); ++ring) {
        // A first packet of (ring + p) % 8 beams (none, or 1 to 7), then packets of 8, the last partial.
        std::size_t start = 0;
        const std::size_t first = (ring + p) % kLanes;
        while (start < azimuths.size()) {
          const std::size_t count = std::min(start == 0 && first > 0 ? first : kLanes, azimuths.size() - start);
          std::vector<Ray> rays;
          for (std::size_t k = 0; k < count; ++k)
            rays.push_back(beamRay(frame, azimuths[start + k], sensor.elevations[ring]));
          std::optional<scene::RangeHit> packet[kLanes];
          built.nearest(rays, std::span(packet, count));
          for (std::size_t k = 0; k < count; ++k) {
            const std::optional<scene::RangeHit> single = built.nearest(rays[k]);
            ASSERT_EQ(packet[k].has_value(), single.has_value())
                << "pose " << p << " ring " << ring << " column " << start + k;
            if (single) {
              EXPECT_EQ(std::bit_cast<std::uint32_t>(packet[k]->t), std::bit_cast<std::uint32_t>(single->t))
                  << "pose " << p << " ring " << ring << " column " << start + k;
              EXPECT_EQ(packet[k]->object, single->object);
              // The normal and reflectivity intensity is made of, bit for bit too.
              EXPECT_EQ(std::bit_cast<std::uint32_t>(packet[k]->normal.x),
                        std::bit_cast<std::uint32_t>(single->normal.x));
              EXPECT_EQ(std::bit_cast<std::uint32_t>(packet[k]->normal.y),
                        std::bit_cast<std::uint32_t>(single->normal.y));
              EXPECT_EQ(std::bit_cast<std::uint32_t>(packet[k]->normal.z),
                        std::bit_cast<std::uint32_t>(single->normal.z));
              EXPECT_EQ(packet[k]->reflectivity, single->reflectivity);
              ++hits;
            }
            ++beams;
          }
          start += count;
        }
      }
    }
    // The robot's world surrounds it: most beams hit something, the ones aimed at the sky miss.
    EXPECT_GT(hits, beams / 2);
    EXPECT_LT(hits, beams);
    EXPECT_EQ(built.refusedRays(), 0u);
  }
}

// 13 azimuths a ring and 3 rings: packets of 8 end at each ring's end (8 + 5 beams), and the
// scan's blocks split rings anywhere. No noise, no rounding, ranges without limit: each return is
// the single beam's hit, at t |d| along the float beam (lidar.h), on the object it hit.
TEST(LidarPacketTest, ScanEqualsSingleBeamsWhereRingsEndMidPacket) {
  const io::SceneDescription world = io::readScene(kSource + "/scenes/robot_world.json");
  const scene::EmbreeScene built(world, {});
  const io::SensorDescription sensor = io::parseSensor(R"({
    "pose": {"position": [0.1, 0.0, 0.5], "yaw": 0.3},
    "horizontal": {"samples": 13, "min_angle": -3.0, "max_angle": 3.0},
    "vertical": {"samples": 3, "min_angle": -0.3, "max_angle": 0.1},
    "range": {"min": 0.0, "max": 1000.0}
  })",
                                                       "sensor.json");
  const std::vector<io::RobotPose> poses = io::readPosesCsv(kSource + "/examples/robot/path.csv");
  const io::ScanTable scan = robot::Lidar(built, sensor).scan(poses, 2);
  const std::vector<double> azimuths = io::fanAngles(sensor.horizontal);
  int returns = 0;
  for (std::size_t p = 0; p < poses.size(); ++p) {
    const robot::SensorFrame frame = robot::sensorFrame(sensor.pose, poses[p]);
    for (std::size_t ring = 0; ring < sensor.elevations.size(); ++ring) {
      for (std::size_t column = 0; column < azimuths.size(); ++column) {
        const Ray ray = beamRay(frame, azimuths[column], sensor.elevations[ring]);
        const std::optional<scene::RangeHit> single = built.nearest(ray);
        const io::BeamReturn& beam = scan.at(p, ring, column);
        const std::string where =
            "pose " + std::to_string(p) + " ring " + std::to_string(ring) + " column " + std::to_string(column);
        if (!single) {
          EXPECT_TRUE(std::isinf(beam.range)) << where;
          EXPECT_EQ(beam.object, -1) << where;
          continue;
        }
        const double length =
            std::sqrt(double(ray.direction.x) * ray.direction.x + double(ray.direction.y) * ray.direction.y +
                      double(ray.direction.z) * ray.direction.z);
        EXPECT_EQ(beam.range, float(double(single->t) * length)) << where;
        EXPECT_EQ(beam.object, std::int32_t(single->object)) << where;
        ++returns;
      }
    }
  }
  EXPECT_GT(returns, int(scan.points.size()) / 2);
}

}  // namespace
}  // namespace revolve
