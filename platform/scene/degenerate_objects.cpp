#include "scene/degenerate_objects.h"

#include "geometry/placement.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace revolve::scene {
namespace {

std::string numberText(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 3).ptr);
}

// Whether (rho, z) lies inside the closed meridian polygon of `points` (its last point joined to
// its first), by the crossing rule: a ray from the point towards +r crosses the boundary an odd
// number of times. A point on the boundary counts as outside (the camera would sit on the surface).
bool insideMeridian(std::span<const Point2> points, double rho, double z) {
  bool inside = false;
  for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++) {
    const Point2 a = points[i], b = points[j];
    if ((a.z > z) == (b.z > z)) continue;
    const double r = a.r + (z - a.z) / (b.z - a.z) * (b.r - a.r);
    if (r > rho) inside = !inside;
  }
  return inside;
}

// The extent of a profile's curve, as its box's largest r and its z range.
struct Extent {
  double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
  explicit Extent(std::span<const Point2> points) {
    for (const Point2 p : points) rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
  }
  Extent() = default;
};

// Its world size: the largest extent of its placed box along a world axis.
double placedSize(const Extent& extent, const app::Matrix3d& linear) {
  double size = 0;
  for (int a = 0; a < 3; ++a) {
    // The box's extent along world axis a: |L_a0| + |L_a1| times 2 rmax, plus |L_a2| (zmax - zmin).
    size = std::max(size, (std::abs(linear[a][0]) + std::abs(linear[a][1])) * 2 * extent.rMax +
                              std::abs(linear[a][2]) * (extent.zHigh - extent.zLow));
  }
  return size;
}

}  // namespace

std::vector<std::string> degenerateObjectWarnings(const io::SceneDescription& scene, bool camera) {
  // An exact spline's polyline is drawn only for the checks that need its points (SceneProfile::
  // polyline: a scene of a million splines would otherwise draw them all). Its Bezier control
  // points decide the rest: every one on the axis exactly when the curve is (a cubic's Bernstein
  // coefficients vanish exactly when it does), and the points it passes through (its pieces' ends)
  // span no more than the curve, so an object whose ends span more than a float step does too.
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const io::SceneObject& object = scene.objects[i];
    const io::SceneProfile& source = scene.profiles[object.profile];
    std::string name = scene.file + ": objects[" + std::to_string(i) + "]";
    if (!object.name.empty()) name += " \"" + object.name + "\"";
    const std::span<const Point2> bounding = io::boundingPoints(source);

    if (std::all_of(bounding.begin(), bounding.end(), [](Point2 p) { return p.r == 0; })) {
      warnings.push_back(name + ": every point of profile \"" + source.name +
                         "\" lies on the axis (r = 0): the surface has no area and nothing can hit it");
      continue;
    }
    // Its world size against one float step (2^-23 relative) at its distance from the origin.
    const app::Matrix3d linear = app::linearPart(object.transform);
    const auto& t = object.transform.translate;
    const double distance = std::max({std::abs(t[0]), std::abs(t[1]), std::abs(t[2])});
    const double step = distance * 0x1p-23;
    Extent extent;
    if (!source.spline) {
      extent = Extent(source.polyline().points());
    } else {
      // The points the curve passes through, its pieces' ends; drawn only when those are small.
      const std::span<const Point2> bezier = source.spline->bezier();
      for (std::size_t k = 0; k < bezier.size(); k += 3) {
        const Point2 p = bezier[k];
        extent.rMax = std::max(extent.rMax, p.r), extent.zLow = std::min(extent.zLow, p.z);
        extent.zHigh = std::max(extent.zHigh, p.z);
      }
      if (placedSize(extent, linear) <= step) extent = Extent(source.polyline().points());
    }
    const double size = placedSize(extent, linear);
    if (size <= step) {
      warnings.push_back(name + ": placed, it spans " + numberText(size) +
                         ", less than one float step at its distance " + numberText(distance) +
                         " from the origin: Embree cannot place it, and its hits are lost to rounding");
      continue;
    }
    const bool closed = source.spline ? source.spline->closed() : source.polyline().closed();
    if (camera && closed) {
      // The camera in the object's frame: L^-1 (from - T), L^-1 = S^-1 R^T.
      const app::Matrix3d rotation = app::rotationOf(object.transform);
      const auto& from = scene.camera.from;
      const app::Vec3d d{from[0] - t[0], from[1] - t[1], from[2] - t[2]};
      app::Vec3d local{};
      for (int r = 0; r < 3; ++r) {
        local[r] = (rotation[0][r] * d[0] + rotation[1][r] * d[1] + rotation[2][r] * d[2]) / object.transform.scale[r];
      }
      if (insideMeridian(source.polyline().points(), std::hypot(local[0], local[1]), local[2])) {
        warnings.push_back(name + ": the camera (camera.from) lies inside it: the view shows its inside, or nothing");
      }
    }
  }
  return warnings;
}

}  // namespace revolve::scene
