// A simulated laser range-finder (the GLBot simulator's laser): every beam of a sensor (io::SensorDescription)
// traced from every robot pose into a scene built in Embree, the first hit taken as the return, with
// ROS LaserScan semantics: a beam with no hit, or whose measured range lies outside [min, max], is
// no return (+inf), never clamped; Gaussian noise (from the seed, per beam) is added to returns
// only; ranges are then rounded to the resolution.
#pragma once

#include "io/poses_file.h"
#include "io/scan_files.h"
#include "io/sensor_file.h"
#include "scene/embree_scene.h"

#include <span>
#include <vector>

namespace revolve::robot {

class Lidar {
 public:
  // Keeps references to both: they must outlive the Lidar.
  Lidar(const scene::EmbreeScene& scene, const io::SensorDescription& sensor);

  // Traces every beam of every pose on `threads` threads (0: all). The result does not depend on
  // the thread count: each beam's noise comes from its own counter-based stream.
  io::ScanTable scan(std::span<const io::RobotPose> poses, int threads = 0) const;

  std::size_t beamsPerPose() const { return azimuths_.size() * elevations_.size(); }

 private:
  struct Angle {
    double radians, cosine, sine;
  };
  const scene::EmbreeScene& scene_;
  const io::SensorDescription& sensor_;
  std::vector<Angle> azimuths_, elevations_;
};

}  // namespace revolve::robot
