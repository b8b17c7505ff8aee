// revolve-render --tolerance: trace a scene's spline profiles as polylines (Profile::fromCurve)
// instead of exactly, within a given tolerance or within the smallest pixel footprint at which the
// camera sees any object made of them.
#pragma once

#include "io/curve_tolerance.h"
#include "io/scene_file.h"

#include <optional>
#include <string>
#include <vector>

namespace revolve::render {

struct CurvePolyline {
  std::string profile;
  double tolerance;  // in the profile's units
  std::size_t points;
};

// Replaces every exactly traced spline profile used by an object by its polyline within the
// tolerance (for `pixel`: 2 d tan(fov / 2) / height, d the distance from the camera to the nearest
// point of the object's bounding sphere, over the object's largest scale; the least over the
// profile's objects). A profile seen from inside an object's bounding sphere, or whose footprint is
// below 2^-30 of its size, or so wide that its polyline would lie on the axis (its objects span
// about a pixel), stays exact. A number is held to the scene file's rule (io/curve_tolerance.h):
// std::runtime_error naming the profile when it would collapse the curve onto the axis. The
// polylines shade with their curves' own normals (SceneProfile::curve).
std::vector<CurvePolyline> applyCurveTolerance(io::SceneDescription& scene, const io::CurveTolerance& tolerance,
                                               int height);

}  // namespace revolve::render
