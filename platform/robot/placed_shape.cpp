#include "robot/placed_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <vector>

namespace revolve::robot {
std::optional<MeridianScale> uprightScale(const app::Transform& transform) {
  const auto& k = transform.rotateAxis;  // unit (the reader normalises it)
  const double turns = std::fmod(transform.rotateDegrees, 360.0);
  const bool aboutZ = k[0] == 0 && k[1] == 0, none = turns == 0;
  const bool flipped = k[2] == 0 && std::abs(turns) == 180;
  if (!(aboutZ || none || flipped) || transform.scale[0] != transform.scale[1]) return std::nullopt;
  return MeridianScale{transform.scale[0], (aboutZ || none ? 1.0 : -1.0) * transform.scale[2]};
}

PlacedShape::PlacedShape(const Shape& shape, const app::Transform& transform) : shape_(&shape), placement_(transform) {
  const app::Matrix3d& linear = placement_.linear();
  const Vec3d& translate = placement_.translate();
  smallestScale_ = std::min({transform.scale[0], transform.scale[1], transform.scale[2]});
  const std::optional<MeridianScale> upright = uprightScale(transform);
  upright_ = upright.has_value();
  if (upright) meridianScale_ = *upright;

  // The world box of the object box [-rmax, rmax]^2 x [zmin, zmax], padded by 2^-40 of its size
  // for the rounding of the corners' transformation (a few operations, 2^-52 relative each).
  double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
  for (const Point2 p : shape.profile().points())
    rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
  box_.lower = {INFINITY, INFINITY, INFINITY};
  box_.upper = {-INFINITY, -INFINITY, -INFINITY};
  double size = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d local{corner & 1 ? rMax : -rMax, corner & 2 ? rMax : -rMax, corner & 4 ? zHigh : zLow};
    const Vec3d rotated = linear.apply(local);
    for (int a = 0; a < 3; ++a) {
      const double w = rotated[a] + translate[a];
      box_.lower[a] = std::min(box_.lower[a], w);
      box_.upper[a] = std::max(box_.upper[a], w);
      size = std::max(size, std::abs(w) + std::abs(rotated[a]));
    }
  }
  for (int a = 0; a < 3; ++a) box_.lower[a] -= 0x1p-40 * size, box_.upper[a] += 0x1p-40 * size;
}

ObstacleClearance PlacedShape::clearance(const RobotBody& robot) const {
  return upright_ ? uprightClearance(robot) : tiltedClearance(robot);
}

ObstacleClearance PlacedShape::uprightClearance(const RobotBody& robot) const {
  const Vec3d& t = placement_.translate();
  const double dx = robot.x - t[0], dy = robot.y - t[1];
  const double d = std::hypot(dx, dy);
  const CylinderClearance c =
      cylinderClearance(*shape_, {d, robot.radius, robot.zMin - t[2], robot.zMax - t[2]}, meridianScale_);
  // The profile point lies in the half-plane towards the robot's axis (any, on the shape's axis).
  const double ux = d > 0 ? dx / d : 1.0, uy = d > 0 ? dy / d : 0.0;
  ObstacleClearance result;
  result.value = c.clearance;
  result.point = {t[0] + c.point.r * ux, t[1] + c.point.r * uy, c.point.z + t[2]};
  result.achieved = signedDistance(robot, result.point);
  result.exact = true;
  return result;
}

std::pair<double, Vec3d> PlacedShape::distanceFrom(const Vec3d& p) const {
  const Vec3d& t = placement_.translate();
  const Vec3d local = placement_.toObject(p);
  const double rho = std::hypot(local[0], local[1]);
  const MeridianPoint m = closestMeridianPoint(*shape_, {rho, local[2]});
  const double cosPhi = rho > 0 ? local[0] / rho : 1.0, sinPhi = rho > 0 ? local[1] / rho : 0.0;
  const Vec3d surface = placement_.linear().apply(Vec3d{m.point.r * cosPhi, m.point.r * sinPhi, m.point.z});
  // |L v| >= (smallest scale) |v| for L = rotation * scale: a lower bound, exact for equal scales.
  return {smallestScale_ * m.distance, {surface[0] + t[0], surface[1] + t[1], surface[2] + t[2]}};
}

ObstacleClearance PlacedShape::tiltedClearance(const RobotBody& robot) const {
  // Branch and bound over the axis segment for min g(z), g the distance from (x, y, z) to the
  // surface: g is 1-Lipschitz in z, so an interval's g(middle) - half its length bounds it below.
  struct Interval {
    double low, high, g;
    double bound() const { return g - 0.5 * (high - low); }
    bool operator<(const Interval& other) const { return bound() > other.bound(); }  // least bound first
  };
  // 2^-24 of the robot's size: the float resolution the clearance is printed at; the budget caps
  // work on a distance that is flat along the axis (the bound stays valid, only looser).
  const double tolerance = 0x1p-24 * (robot.radius + (robot.zMax - robot.zMin));
  constexpr int kBudget = 2048;
  ObstacleClearance result;
  double best = INFINITY;
  const auto evaluate = [&](double z) {
    const auto [g, point] = distanceFrom({robot.x, robot.y, z});
    if (g < best) best = g, result.point = point;
    return g;
  };
  std::priority_queue<Interval> open;
  open.push({robot.zMin, robot.zMax, evaluate(0.5 * (robot.zMin + robot.zMax))});
  double axisBound = open.top().bound();
  for (int evaluations = 1; !open.empty();) {
    const Interval interval = open.top();
    axisBound = interval.bound();  // the least bound over the intervals still open
    if (axisBound >= best - tolerance || evaluations + 2 > kBudget) break;
    open.pop();
    const double middle = 0.5 * (interval.low + interval.high);
    open.push({interval.low, middle, evaluate(0.5 * (interval.low + middle))});
    open.push({middle, interval.high, evaluate(0.5 * (middle + interval.high))});
    evaluations += 2;
    axisBound = open.top().bound();
  }
  result.value = std::max(axisBound - robot.radius, signedDistance(robot, box_));
  result.achieved = signedDistance(robot, result.point);
  const double size =
      std::abs(robot.x) + std::abs(robot.y) + std::abs(robot.zMin) + std::abs(robot.zMax) + robot.radius;
  // Exact to within the search's tolerance when the surface point found attains the bound.
  result.exact = result.achieved - result.value <= tolerance + 0x1p-40 * size;
  return result;
}

}  // namespace revolve::robot
