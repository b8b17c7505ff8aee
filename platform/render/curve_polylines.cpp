#include "render/curve_polylines.h"

#include "geometry/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace revolve::render {

using app::Vec3d;

std::vector<CurvePolyline> applyCurveTolerance(io::SceneDescription& scene, const io::CurveTolerance& choice,
                                               int height) {
  std::vector<double> tolerance(scene.profiles.size(), std::numeric_limits<double>::infinity());
  const double pixelAngle = 2.0 * std::tan(scene.camera.fovDegrees * std::numbers::pi / 360.0) / height;
  for (const io::SceneObject& object : scene.objects) {
    const io::SceneProfile& profile = scene.profiles[object.profile];
    if (!profile.spline) continue;
    if (!choice.pixel) {
      tolerance[object.profile] = choice.value;
      continue;
    }
    // The object's bounding sphere: the profile's box about its middle height, scaled and placed.
    double rMax = 0, zLow = INFINITY, zHigh = -INFINITY;
    for (const Point2& p : profile.polyline().points())
      rMax = std::max(rMax, p.r), zLow = std::min(zLow, p.z), zHigh = std::max(zHigh, p.z);
    const app::Transform& t = object.transform;
    const double scale = std::max({t.scale[0], t.scale[1], t.scale[2]});
    const Vec3d middle = app::rotate(t, {0, 0, t.scale[2] * 0.5 * (zLow + zHigh)});
    const double radius = scale * std::hypot(rMax, 0.5 * (zHigh - zLow));
    double distance = 0;
    for (int i = 0; i < 3; ++i) {
      const double d = t.translate[i] + middle[i] - scene.camera.from[i];
      distance += d * d;
    }
    distance = std::sqrt(distance) - radius;
    // Inside the sphere the object may come arbitrarily near: nothing coarser than exact will do.
    const double footprint = distance > 0 ? distance * pixelAngle / scale : 0;
    tolerance[object.profile] = std::min(tolerance[object.profile], footprint);
  }
  std::vector<CurvePolyline> polylines;
  for (std::size_t i = 0; i < scene.profiles.size(); ++i) {
    io::SceneProfile& profile = scene.profiles[i];
    if (!profile.spline || !(tolerance[i] > 0 && tolerance[i] < HUGE_VAL)) continue;
    // A footprint below 2^-30 of the curve's size (a camera almost touching it) asks for what
    // exact tracing gives anyway; a tolerance the user gave is taken as it is (and may be refused).
    double size = 0;
    for (const Point2& p : profile.spline->bezier()) size = std::max({size, std::abs(p.r), std::abs(p.z)});
    if (choice.pixel && tolerance[i] < 0x1p-30 * size) continue;
    std::optional<Profile> polyline;
    try {
      // A number is held to the scene file's rule (io/curve_tolerance.h). A footprint so wide that
      // the polyline would lie on the axis (every object made of the profile spans about a pixel)
      // would make the objects vanish: they stay exact instead.
      polyline.emplace(choice.pixel ? Profile::fromCurve(*profile.spline, tolerance[i])
                                    : io::curvePolyline(*profile.spline, tolerance[i]));
    } catch (const std::invalid_argument& error) {
      throw std::runtime_error("--tolerance: profiles." + profile.name + ": " + error.what());
    }
    if (io::onTheAxis(*polyline)) continue;
    profile.profile = std::move(*polyline);
    profile.spline.reset();  // traced as the polyline; profile.curve still gives its normals
    profile.tolerance = tolerance[i];
    polylines.push_back({profile.name, tolerance[i], profile.polyline().points().size()});
  }
  return polylines;
}

}  // namespace revolve::render
