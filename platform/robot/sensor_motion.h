// Where a moving sensor is when each beam fires. A spinning sensor (io::SensorDescription's
// rotation_rate) fires column k of a sweep k / (samples x rate) seconds after the sweep starts;
// when the poses carry times, sweep i starts at pose i's time and every beam is traced from the
// sensor where the robot is at the beam's own firing time: the position interpolated linearly
// between the two poses around that time, the yaw (and roll and pitch) each turned the shorter
// way between theirs. The path
// ends at the last pose: beams fired after its time are traced from it (the robot stops there).
// A beam's frame depends only on the poses from its sweep's to the first after its firing time, so
// a scan traced in parts gives the whole scan's beams bit for bit when each part's poses reach that
// far (robot/lidar.h's `sweeps`).
//
// Without times, or without a rate, every beam of sweep i is traced from pose i: a scan at rest.
#pragma once

#include "io/poses_file.h"
#include "io/sensor_file.h"
#include "robot/sensor_rig.h"

#include <span>

namespace revolve::robot {

class SensorMotion {
 public:
  // Keeps references to `mount` and `trajectory`: both must outlive the motion.
  SensorMotion(const io::SensorPose& mount, std::span<const io::RobotPose> trajectory);

  // Whether beams of one sweep are traced from different frames.
  bool moving() const { return moving_; }

  // The sensor's frame at the start of sweep `sweep` (pose `sweep`).
  SensorFrame atPose(std::size_t sweep) const;
  // The sensor's frame `offset` seconds after sweep `sweep` starts.
  SensorFrame at(std::size_t sweep, double offset) const noexcept;

 private:
  const io::SensorPose& mount_;
  app::Matrix3d mountRotation_;
  std::span<const io::RobotPose> trajectory_;
  bool moving_ = false;
};

}  // namespace revolve::robot
