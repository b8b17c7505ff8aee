#include "robot/sensor_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace revolve::robot {

SensorMotion::SensorMotion(const io::SensorPose& mount, std::span<const io::RobotPose> trajectory)
    : mount_(mount),
      mountRotation_(mountRotation(mount)),
      trajectory_(trajectory),
      moving_(trajectory.size() >= 2 && trajectory.front().timed()) {}

SensorFrame SensorMotion::atPose(std::size_t sweep) const {
  return sensorFrame(mount_, mountRotation_, trajectory_[sweep]);
}

SensorFrame SensorMotion::at(std::size_t sweep, double offset) const noexcept {
  if (!moving_ || offset == 0) return atPose(sweep);
  const double time = trajectory_[sweep].time + offset;
  // The segment [j, j + 1] holding `time`: j the last pose at or before it (from the sweep's own
  // pose on, since offsets are >= 0). At or after the last pose's time the robot stays there.
  const auto after = std::upper_bound(trajectory_.begin() + std::ptrdiff_t(sweep), trajectory_.end(), time,
                                      [](double t, const io::RobotPose& p) { return t < p.time; });
  if (after == trajectory_.end()) return atPose(trajectory_.size() - 1);
  const std::size_t j = std::size_t(after - trajectory_.begin()) - 1;
  const io::RobotPose& a = trajectory_[j];
  const io::RobotPose& b = trajectory_[j + 1];
  const double s = (time - a.time) / (b.time - a.time);
  // Each angle the shorter way from a's to b's: their difference brought into [-pi, pi].
  const auto turned = [s](double from, double to) {
    return from + s * std::remainder(to - from, 2 * std::numbers::pi);
  };
  io::RobotPose between;
  between.x = a.x + s * (b.x - a.x);
  between.y = a.y + s * (b.y - a.y);
  between.z = a.z + s * (b.z - a.z);
  between.yaw = turned(a.yaw, b.yaw);
  between.roll = turned(a.roll, b.roll);
  between.pitch = turned(a.pitch, b.pitch);
  return sensorFrame(mount_, mountRotation_, between);
}

}  // namespace revolve::robot
