// Building a scene's profile from its points: shared by the scene file's named profiles and its
// object tables (io/object_table.h), so that a profile is one rule whichever way it is written.
// Internal to platform/io.
#pragma once

#include "io/json_reader.h"
#include "io/scene_file.h"

#include <revolve/revolve.h>

#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace revolve::io {

using SceneReader = json::Reader<SceneError>;

// How a profile's points are made into its curve: the "spline", "tolerance" and "crease" of a
// named profile, or an object table's row and keys; each with the key path its errors name.
struct ProfileRecipe {
  SplineKind kind = SplineKind::linear;
  double tolerance = 0;  // 0: a curved spline traced exactly
  double creaseDegrees = ShadingNormals::kDefaultCreaseDegrees;
  std::string splinePath, tolerancePath;
};

// The profile's points as read, with where each came from for messages: an element of "points",
// or a line of a CSV file.
struct ProfileSource {
  std::vector<Point2> points;
  std::function<std::string(std::size_t)> where;  // the key path or "file:line" of point i
  std::string path;                               // the key path of the points (or the csv key)
  std::string file;                               // the CSV as opened; empty for inline points
};

// The profile `name` from `source` as `recipe` makes it: its geometry checked by the Profile or
// Spline constructor, a bad point named where it came from. Throws SceneError through `in`.
SceneProfile buildSceneProfile(const SceneReader& in, std::string name, const ProfileRecipe& recipe,
                               const ProfileSource& source);

// Runs task(i) for i in [0, count) on TBB's threads, then rethrows the exception of the lowest i
// that threw: a reader working in parallel reports the error a reading in order would.
void forEachInParallel(std::size_t count, const std::function<void(std::size_t)>& task);

}  // namespace revolve::io
