#include "robot/triangle_clearance.h"

#include <algorithm>
#include <cmath>

namespace revolve::robot {
namespace {

// A convex polygon of up to 8 vertices: a triangle cut by two planes has at most 5.
struct Polygon {
  std::array<Vec3d, 8> v{};
  int n = 0;
  void add(const Vec3d& p) { v[n++] = p; }
};

Vec3d lerp(const Vec3d& a, const Vec3d& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// Sutherland-Hodgman against one horizontal plane: keeps z >= level (above) or z <= level.
Polygon clip(const Polygon& in, double level, bool above) {
  Polygon out;
  const auto inside = [&](const Vec3d& p) { return above ? p[2] >= level : p[2] <= level; };
  for (int i = 0; i < in.n; ++i) {
    const Vec3d& a = in.v[i];
    const Vec3d& b = in.v[(i + 1) % in.n];
    if (inside(a)) out.add(a);
    if (inside(a) != inside(b)) {
      Vec3d crossing = lerp(a, b, (level - a[2]) / (b[2] - a[2]));
      crossing[2] = level;  // on the plane exactly, whatever the rounding of the interpolation
      out.add(crossing);
    }
  }
  return out;
}

struct Closest {
  double distance;
  Vec3d point;
};

// The point of segment a-b nearest to p, measured in the horizontal plane only or in 3-D.
Closest closestOnSegment(const Vec3d& a, const Vec3d& b, const Vec3d& p, bool horizontal) {
  const int axes = horizontal ? 2 : 3;
  double along = 0, length2 = 0;
  for (int k = 0; k < axes; ++k) {
    along += (p[k] - a[k]) * (b[k] - a[k]);
    length2 += (b[k] - a[k]) * (b[k] - a[k]);
  }
  const double t = length2 > 0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0;
  const Vec3d q = lerp(a, b, t);
  const double dz = horizontal ? 0.0 : q[2] - p[2];
  return {std::hypot(q[0] - p[0], q[1] - p[1], dz), q};
}

Closest closestOnEdges(const Polygon& polygon, const Vec3d& p, bool horizontal) {
  Closest best{INFINITY, polygon.v[0]};
  for (int i = 0; i < polygon.n; ++i) {
    const Closest c = closestOnSegment(polygon.v[i], polygon.v[(i + 1) % polygon.n], p, horizontal);
    if (c.distance < best.distance) best = c;
  }
  return best;
}

Vec3d newellNormal(const Polygon& polygon) {
  Vec3d n{0, 0, 0};
  for (int i = 0; i < polygon.n; ++i) {
    const Vec3d& a = polygon.v[i];
    const Vec3d& b = polygon.v[(i + 1) % polygon.n];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

// Whether p's projection along n falls inside the convex polygon (n its non-zero normal).
bool insideAlong(const Polygon& polygon, const Vec3d& n, const Vec3d& p) {
  bool positive = false, negative = false;
  for (int i = 0; i < polygon.n; ++i) {
    const Vec3d& a = polygon.v[i];
    const Vec3d& b = polygon.v[(i + 1) % polygon.n];
    const Vec3d e{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double side =
        n[0] * (e[1] * w[2] - e[2] * w[1]) + n[1] * (e[2] * w[0] - e[0] * w[2]) + n[2] * (e[0] * w[1] - e[1] * w[0]);
    positive |= side > 0;
    negative |= side < 0;
  }
  return !(positive && negative);
}

// The polygon's point nearest the vertical line through (x, y), horizontally: over it if the
// polygon is not vertical and the line passes through it, else on an edge.
Closest closestToVerticalLine(const Polygon& polygon, double x, double y) {
  const Vec3d n = newellNormal(polygon);
  const Vec3d p{x, y, polygon.v[0][2]};
  if (n[2] != 0 && insideAlong(polygon, {0, 0, 1}, p)) {
    const Vec3d& a = polygon.v[0];
    return {0.0, {x, y, a[2] - (n[0] * (x - a[0]) + n[1] * (y - a[1])) / n[2]}};
  }
  return closestOnEdges(polygon, p, true);
}

// The polygon's point nearest p in 3-D.
Closest closestInSpace(const Polygon& polygon, const Vec3d& p) {
  const Vec3d n = newellNormal(polygon);
  const double n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (n2 > 0) {
    const Vec3d& a = polygon.v[0];
    const double s = (n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2])) / n2;
    const Vec3d q{p[0] - s * n[0], p[1] - s * n[1], p[2] - s * n[2]};
    if (insideAlong(polygon, n, q)) return {std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]), q};
  }
  return closestOnEdges(polygon, p, false);
}

// The heights the polygon spans on the vertical line through p's (x, y) (p on the polygon).
std::array<double, 2> heightsAt(const Polygon& polygon, const Vec3d& p) {
  double low = p[2], high = p[2];
  for (int i = 0; i < polygon.n; ++i) {
    const Vec3d& a = polygon.v[i];
    const Vec3d& b = polygon.v[(i + 1) % polygon.n];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double length2 = ex * ex + ey * ey;
    double z;
    if (length2 == 0) {
      if (a[0] != p[0] || a[1] != p[1]) continue;  // a vertical edge elsewhere
      low = std::min({low, a[2], b[2]});
      high = std::max({high, a[2], b[2]});
      continue;
    }
    // The edge's point over (x, y), if its horizontal projection passes through it: p lies on the
    // polygon, so an edge through it misses only by the rounding of these few operations (2^-52
    // relative each); 2^-40 of the coordinates leaves room, and an edge farther off is elsewhere.
    const double t = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / length2;
    const double offX = a[0] + t * ex - p[0], offY = a[1] + t * ey - p[1];
    if (t < 0 || t > 1 || std::hypot(offX, offY) > 0x1p-40 * (std::abs(p[0]) + std::abs(p[1]) + std::sqrt(length2)))
      continue;
    z = a[2] + t * (b[2] - a[2]);
    low = std::min(low, z);
    high = std::max(high, z);
  }
  return {low, high};
}

// Keeps the candidate surface point of least signed distance as the one to report.
void consider(ObstacleClearance& result, const RobotBody& robot, const Vec3d& q) {
  const double achieved = signedDistance(robot, q);
  if (achieved < result.achieved) result.achieved = achieved, result.point = q;
}

// The part of the triangle within the robot's heights: exact apart, bounded when overlapping.
ObstacleClearance besidePart(const RobotBody& robot, const Polygon& part) {
  ObstacleClearance result;
  const Closest nearest = closestToVerticalLine(part, robot.x, robot.y);
  consider(result, robot, nearest.point);
  if (nearest.distance >= robot.radius) {
    result.value = nearest.distance - robot.radius;
    return result;
  }
  // Overlapping: depth = min(R - h, tent(z)) <= min(R - h_min, the tent's maximum over the part's
  // heights), which a point at h_min and that height attains when the part has one there.
  double low = part.v[0][2], high = low;
  for (int i = 1; i < part.n; ++i) low = std::min(low, part.v[i][2]), high = std::max(high, part.v[i][2]);
  const double middle = 0.5 * (robot.zMin + robot.zMax);
  const double peak = std::clamp(middle, low, high);
  result.value = -std::min(robot.radius - nearest.distance, std::min(peak - robot.zMin, robot.zMax - peak));
  const std::array<double, 2> span = heightsAt(part, nearest.point);
  consider(result, robot, {nearest.point[0], nearest.point[1], std::clamp(middle, span[0], span[1])});
  return result;
}

// The part above the robot's top (or below its bottom): a lower bound.
ObstacleClearance endPart(const RobotBody& robot, const Polygon& part, bool above) {
  ObstacleClearance result;
  const double end = above ? robot.zMax : robot.zMin;
  double gapZ = INFINITY;
  int nearestVertex = 0;
  for (int i = 0; i < part.n; ++i) {
    const double gap = std::abs(part.v[i][2] - end);
    if (gap < gapZ) gapZ = gap, nearestVertex = i;
  }
  const Closest horizontal = closestToVerticalLine(part, robot.x, robot.y);
  const Closest toCentre = closestInSpace(part, {robot.x, robot.y, end});
  result.value =
      std::max(std::hypot(std::max(horizontal.distance - robot.radius, 0.0), gapZ), toCentre.distance - robot.radius);
  consider(result, robot, horizontal.point);
  consider(result, robot, toCentre.point);
  consider(result, robot, part.v[nearestVertex]);
  return result;
}

}  // namespace

ObstacleClearance triangleClearance(const RobotBody& robot, const std::array<Vec3d, 3>& triangle) {
  Polygon whole;
  for (const Vec3d& p : triangle) whole.add(p);
  ObstacleClearance best;
  const auto keep = [&](const ObstacleClearance& part) {
    if (part.value < best.value) best = part;
  };
  const Polygon above = clip(whole, robot.zMax, true), below = clip(whole, robot.zMin, false);
  const Polygon beside = clip(clip(whole, robot.zMin, true), robot.zMax, false);
  if (beside.n > 0) keep(besidePart(robot, beside));
  if (above.n > 0) keep(endPart(robot, above, true));
  if (below.n > 0) keep(endPart(robot, below, false));
  // Exact when the bound is attained by a surface point: both come from a few dozen double
  // operations on coordinates up to `size`, each within 2^-52 of it; 2^-40 leaves 4096 times room.
  double size = std::abs(robot.x) + std::abs(robot.y) + std::abs(robot.zMin) + std::abs(robot.zMax) + robot.radius;
  for (const Vec3d& p : triangle) size = std::max({size, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  best.exact = best.achieved - best.value <= 0x1p-40 * size;
  return best;
}

}  // namespace revolve::robot
