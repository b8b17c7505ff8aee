// Range sensors on the robot: sonars and infrared rangers, each a cone on the robot reporting the
// distance to the nearest surface inside it (ROS's sensor_msgs/Range; io::RangeSensorDescription).
//
// The reading is exact (geometry/cone_nearest.h): for each surface of revolution, the nearest point
// of its profile polyline swept about its axis inside the cone, found in object space (a scene's
// placements are rotations, translations and equal scales, which keep angles and scale distances
// alike), and for each quad its two triangles. A spline traced exactly is taken as its polyline
// within SceneProfile::kDrawingFraction (1e-5) of its size: the reading is exact for a surface that
// close to the curve's. With Settings::mesh, every revolution is a tessellated mesh instead (the
// same mesh as revolve-lidar --geometry mesh: vertices on the profile's circles), to show the
// facets' error beside the exact reading.
//
// Then, as a lidar's return: the Gaussian noise (its own number for each pose and sensor, from the
// sensor's seed), and the range gate: a reading outside [min_range, max_range] is none (inf), as
// ROS's Range says of such values. The nearest surface decides the reading: one nearer than
// min_range hides what lies behind it.
#pragma once

#include "geometry/cone_nearest.h"
#include "geometry/placement.h"
#include "io/poses_file.h"
#include "io/range_readings.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace revolve::robot {

using app::Vec3d;

using io::RangeReading;

class RangeSensors {
 public:
  struct Settings {
    bool mesh = false;          // tessellate every revolution
    std::uint32_t slices = 64;  // its steps about the axis
  };

  // Throws std::invalid_argument naming an object placed with unequal scale factors (exact
  // readings need angles kept; Settings::mesh takes any placement).
  RangeSensors(const io::SceneDescription& scene, io::RangeSensorsDescription sensors, Settings settings);
  RangeSensors(const io::SceneDescription& scene, io::RangeSensorsDescription sensors)
      : RangeSensors(scene, std::move(sensors), Settings{}) {}

  const io::RangeSensorsDescription& description() const { return sensors_; }
  std::size_t sensorCount() const { return sensors_.sensors.size(); }

  // The reading of `sensor` at the robot's `pose`, the `poseNumber`-th of its path (which picks
  // the noise). Thread-safe.
  RangeReading read(std::size_t sensor, const io::RobotPose& pose, std::uint64_t poseNumber) const;

  // Every sensor at every pose, pose by pose: `sink(firstPose, readings)` receives blocks of whole
  // poses in order (readings[p x sensors + s] is sensor s at pose firstPose + p), so memory stays
  // flat in the number of poses. `firstPose` numbers poses[0] (its noise). threads: 0 = all.
  void readAll(std::span<const io::RobotPose> poses, int threads,
               const std::function<void(std::uint64_t, std::span<const RangeReading>)>& sink,
               std::uint64_t firstPose = 0) const;

 private:
  struct Revolution {
    std::size_t profile;  // index into profiles_
    app::Placement placement;
    double scale;  // world distance per object distance
    Vec3d centre;  // world ball holding the surface
    double radius;
    std::int64_t object;
  };
  struct Triangles {  // a quad's two, or a tessellated revolution's, in the world
    std::vector<std::array<Vec3d, 3>> triangles;
    Vec3d centre;
    double radius;
    std::int64_t object;
  };

  io::RangeSensorsDescription sensors_;
  std::vector<std::vector<Point2>> profiles_;
  std::vector<Revolution> revolutions_;
  std::vector<Triangles> meshes_;
};

}  // namespace revolve::robot
