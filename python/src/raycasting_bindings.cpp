// RaycastingScene for Python: Open3D's method names, argument names, result keys, shapes and
// dtypes (open3d.t.geometry.RaycastingScene, 0.19), numpy arrays in and out, the GIL released
// while the queries run.
#include "arguments.h"
#include "bindings.h"
#include "numpy_inputs.h"
#include "raycasting_scene.h"

#include "geometry/placement.h"
#include "geometry/ray_limits.h"
#include "io/curve_tolerance.h"
#include "io/scene_file.h"
#include "scene/degenerate_objects.h"

#include <pybind11/stl.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace revolve::python {
namespace {

using Scene = RaycastingScene;

// Throws the ValueError for a refused ray or point.
void refuse(const QueryArray& in, const char* name, std::size_t index, bool rays) {
  const float* item = in.data + (rays ? 6 : 3) * index;
  throw py::value_error(indexText(name, in.leadingShape, index) + ": " +
                        (rays ? app::queryRayFault(item) : app::queryPointFault(item)));
}

// The shape; `recipe` receives its points, spline and tolerance as taken (what a pickle keeps).
// The spline kind and tolerance add_revolution and add_revolutions take, checked: a tolerance
// needs a spline, and is held to the rule every tool applies (io/curve_tolerance.h).
struct CurveOptions {
  std::optional<std::string> spline;
  std::optional<SplineKind> kind;
  std::optional<double> tolerance;
};
CurveOptions curveOptionsOf(py::handle splineObject, py::handle toleranceObject) {
  CurveOptions options{optionalText(splineObject, "spline"), std::nullopt, optionalReal(toleranceObject, "tolerance")};
  if (options.tolerance) {
    if (const std::optional<std::string> fault =
            io::toleranceFault(*options.tolerance, std::string(py::repr(toleranceObject)))) {
      throw py::value_error("tolerance: " + *fault);
    }
  }
  if (!options.spline) {
    if (options.tolerance) {
      throw py::value_error(
          "tolerance applies to a spline profile (spline=\"catmull-rom\", ...), sampled within it; "
          "a polyline is traced as given");
    }
    return options;
  }
  options.kind = splineKindNamed(*options.spline);
  if (!options.kind) {
    throw py::value_error("spline = \"" + *options.spline + "\"" +
                          ": not a spline kind; expected linear, quadratic, bezier, catmull-rom or natural");
  }
  return options;
}

// The shape of one profile as `options` say; the points' warnings in `warnings`. Plain C++ (no
// Python object): add_revolutions runs it on TBB's threads without the GIL. Throws ProfileError,
// or std::invalid_argument for a tolerance this curve cannot take.
Shape builtShape(std::span<const Point2> points, const CurveOptions& options, std::vector<ProfileWarning>& warnings) {
  if (!options.kind) {
    Profile profile(points);
    warnings = profile.warnings();
    return Shape(std::move(profile));
  }
  Spline curve(*options.kind, points);
  warnings = curve.warnings();
  if (options.tolerance) return Shape(io::curvePolyline(curve, *options.tolerance));
  return Shape(std::move(curve));
}

Shape shapeOf(py::handle pointsObject, py::handle splineObject, py::handle toleranceObject,
              Scene::RevolutionRecipe& recipe) {
  const py::array_t<double> array = copiedMatrix(pointsObject, "points", -1, 2, 0, false);
  std::vector<Point2> points(std::size_t(array.shape(0)));
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {array.at(i, 0), array.at(i, 1)};
  const CurveOptions options = curveOptionsOf(splineObject, toleranceObject);
  recipe.points.assign(array.data(), array.data() + array.size());
  recipe.spline = options.spline;
  recipe.tolerance = options.tolerance;
  try {
    std::vector<ProfileWarning> warnings;
    Shape shape = builtShape(points, options, warnings);
    warnAbout(warnings, "points");
    return shape;
  } catch (const ProfileError& error) {
    throw ProfileError(error.rule(), error.index(), std::string("points: ") + error.what());
  } catch (const std::invalid_argument& error) {  // the tolerance, for this curve
    throw py::value_error(std::string("tolerance: ") + error.what());
  }
}

// The placement a 4x4 matrix gives, held to the placement rule and the coordinate limit (the
// shape's box placed, geometry/placement.h); `name` names it in messages.
app::Placement placementOf(const double rows[16], const Shape& shape, const char* name) {
  try {
    const app::Placement placement = app::Placement::fromRows(rows, name);
    const Bounds box = shape.bounds();
    const double reach =
        placement.reach({box.lower.x, box.lower.y, box.lower.z}, {box.upper.x, box.upper.y, box.upper.z});
    if (const std::optional<std::string> fault = app::reachFault(reach)) {
      throw app::PlacementError(std::string(name) + ": " + *fault);
    }
    return placement;
  } catch (const app::PlacementError& error) {
    throw py::value_error(error.what());
  }
}

// `rows` receives the matrix taken, row by row (what a pickle keeps).
app::Placement placementFrom(py::handle transform, const Shape& shape, std::array<double, 16>& rows) {
  static const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (transform.is_none()) {
    std::copy(identity, identity + 16, rows.begin());
    return placementOf(identity, shape, "transform");
  }
  const py::array_t<double> matrix = copiedMatrix(transform, "transform", 4, 4);
  std::copy(matrix.data(), matrix.data() + 16, rows.begin());
  return placementOf(matrix.data(), shape, "transform");
}

// add_revolutions: N profiles and N placements in one call. The arrays are read with the GIL, the
// shapes built on TBB's threads without it, then checked in order, so that the first bad object
// (by index) is the one named, and nothing is added unless every object can be.
py::array_t<std::uint32_t> addRevolutions(Scene& scene, py::handle pointsObject, py::handle transformsObject,
                                          py::handle splineObject, py::handle toleranceObject) {
  // The profiles: an array of shape (N, P, 2), or a sequence of N arrays of shape (P_i, 2).
  std::vector<std::vector<Point2>> profiles;
  const auto name = [](const char* what, std::size_t i) { return std::string(what) + "[" + std::to_string(i) + "]"; };
  if (py::isinstance<py::array>(pointsObject) && py::reinterpret_borrow<py::array>(pointsObject).ndim() == 3) {
    const py::array given = py::reinterpret_borrow<py::array>(pointsObject);
    if (given.dtype().kind() != 'f' && given.dtype().kind() != 'i' && given.dtype().kind() != 'u')
      throw py::type_error("points: dtype " + std::string(py::str(given.dtype())) + "; expected a real array");
    if (given.shape(2) != 2) throw py::value_error("points: shape " + shapeText(given) + "; expected (N, P, 2)");
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
    const std::size_t rows = std::size_t(given.shape(1));
    profiles.resize(std::size_t(given.shape(0)));
    for (std::size_t i = 0; i < profiles.size(); ++i) {
      profiles[i].resize(rows);
      for (std::size_t k = 0; k < rows; ++k) profiles[i][k] = {values.at(i, k, 0), values.at(i, k, 1)};
    }
  } else {
    if (!py::isinstance<py::sequence>(pointsObject) || py::isinstance<py::str>(pointsObject))
      throw py::type_error("points: expected an array of shape (N, P, 2) or a sequence of (P, 2) arrays");
    const py::sequence sequence = py::reinterpret_borrow<py::sequence>(pointsObject);
    profiles.resize(std::size_t(py::len(sequence)));
    for (std::size_t i = 0; i < profiles.size(); ++i) {
      const std::string label = name("points", i);
      const py::array_t<double> array = copiedMatrix(sequence[i], label.c_str(), -1, 2, 0, false);
      profiles[i].resize(std::size_t(array.shape(0)));
      for (std::size_t k = 0; k < profiles[i].size(); ++k) profiles[i][k] = {array.at(k, 0), array.at(k, 1)};
    }
  }
  const std::size_t count = profiles.size();
  // The placements: an array of shape (N, 4, 4), or none (the identity for all).
  std::vector<std::array<double, 16>> rows(count, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  if (!transformsObject.is_none()) {
    const py::array given = arrayArgument(transformsObject, "transforms", "a real array of shape (N, 4, 4)");
    if (given.dtype().kind() != 'f' && given.dtype().kind() != 'i' && given.dtype().kind() != 'u')
      throw py::type_error("transforms: dtype " + std::string(py::str(given.dtype())) + "; expected a real array");
    if (given.ndim() != 3 || std::size_t(given.shape(0)) != count || given.shape(1) != 4 || given.shape(2) != 4) {
      throw py::value_error("transforms: shape " + shapeText(given) + "; expected (" + std::to_string(count) +
                            ", 4, 4), one matrix a profile");
    }
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
    for (std::size_t i = 0; i < count; ++i)
      std::copy(values.data() + 16 * i, values.data() + 16 * (i + 1), rows[i].begin());
  }
  const CurveOptions options = curveOptionsOf(splineObject, toleranceObject);

  std::vector<std::optional<Shape>> shapes(count);
  std::vector<std::vector<ProfileWarning>> warnings(count);
  std::vector<std::exception_ptr> faults(count);
  {
    py::gil_scoped_release release;
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
      try {
        shapes[i].emplace(builtShape(profiles[i], options, warnings[i]));
      } catch (...) {
        faults[i] = std::current_exception();
      }
    });
  }
  std::vector<Shape> built;
  std::vector<app::Placement> placements;
  std::vector<Scene::RevolutionRecipe> recipes(count);
  built.reserve(count);
  placements.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::string label = name("points", i);
    if (faults[i]) {
      try {
        std::rethrow_exception(faults[i]);
      } catch (const ProfileError& error) {
        throw ProfileError(error.rule(), error.index(), label + ": " + error.what());
      } catch (const std::invalid_argument& error) {  // the tolerance, for this curve
        throw py::value_error("tolerance, for " + label + ": " + error.what());
      }
    }
    warnAbout(warnings[i], label.c_str());
    placements.push_back(placementOf(rows[i].data(), *shapes[i], name("transforms", i).c_str()));
    for (const Point2& p : profiles[i]) recipes[i].points.insert(recipes[i].points.end(), {p.r, p.z});
    recipes[i].spline = options.spline;
    recipes[i].tolerance = options.tolerance;
    recipes[i].rows = rows[i];
    built.push_back(std::move(*shapes[i]));
    shapes[i].reset();
  }
  std::uint32_t first = 0;
  {
    py::gil_scoped_release release;
    first = scene.addRevolutions(std::move(built), placements, std::move(recipes));
  }
  auto ids = py::array_t<std::uint32_t>(py::ssize_t(count));
  for (std::size_t i = 0; i < count; ++i) ids.mutable_data()[i] = first + std::uint32_t(i);
  return ids;
}

std::uint32_t addTriangles(Scene& scene, py::handle verticesObject, py::handle trianglesObject) {
  const py::array_t<double> vertices = copiedMatrix(verticesObject, "vertex_positions", -1, 3);
  const py::array triangles = arrayArgument(trianglesObject, "triangle_indices", "an integer array of shape (M, 3)");
  if (triangles.dtype().kind() != 'i' && triangles.dtype().kind() != 'u') {
    throw py::type_error("triangle_indices: dtype " + std::string(py::str(triangles.dtype())) +
                         "; expected an integer array of shape (M, 3) (Open3D takes uint32)");
  }
  if (triangles.ndim() != 2 || triangles.shape(1) != 3) {
    throw py::value_error("triangle_indices: shape " + shapeText(triangles) + "; expected (M, 3)");
  }
  const py::array_t<std::int64_t> indices = alignedArray<std::int64_t>(triangles);
  if (triangles.dtype().kind() == 'u' && triangles.dtype().itemsize() == 8) {
    // uint64 beyond int64 would wrap in the conversion: refuse it by its own value.
    const py::array_t<std::uint64_t> raw = alignedArray<std::uint64_t>(triangles);
    for (py::ssize_t i = 0; i < raw.size(); ++i) {
      if (raw.data()[i] >= std::uint64_t(vertices.shape(0))) {
        throw py::value_error("triangle_indices[" + std::to_string(i / 3) + ", " + std::to_string(i % 3) +
                              "] = " + std::to_string(raw.data()[i]) + " is not a vertex: there are " +
                              std::to_string(vertices.shape(0)));
      }
    }
  }
  std::vector<float> positions(std::size_t(vertices.size()));
  for (py::ssize_t i = 0; i < vertices.size(); ++i) {
    const double x = vertices.data()[i];
    if (!(std::abs(x) <= app::kMaxWorldCoordinate)) {
      throw py::value_error("vertex_positions[" + std::to_string(i / 3) + ", " + std::to_string(i % 3) + "] = " +
                            std::to_string(x) + " is beyond the coordinate limit: " + app::kCoordinateLimitRule);
    }
    positions[std::size_t(i)] = float(x);
  }
  std::vector<std::uint32_t> corners(std::size_t(indices.size()));
  for (py::ssize_t i = 0; i < indices.size(); ++i) {
    const std::int64_t k = indices.data()[i];
    if (k < 0 || k >= vertices.shape(0)) {
      throw py::value_error("triangle_indices[" + std::to_string(i / 3) + ", " + std::to_string(i % 3) + "] = " +
                            std::to_string(k) + " is not a vertex: there are " + std::to_string(vertices.shape(0)));
    }
    corners[std::size_t(i)] = std::uint32_t(k);
  }
  if (vertices.shape(0) > py::ssize_t(std::numeric_limits<std::uint32_t>::max())) {
    throw py::value_error("vertex_positions: more than 2^32 - 1 vertices, beyond 32-bit triangle indices");
  }
  return scene.addTriangles(positions, corners);
}

std::vector<std::uint32_t> load(Scene& scene, py::handle pathObject) {
  const std::string path = pathArgument(pathObject, "path");
  const io::SceneDescription description = io::readScene(path);
  for (const io::SceneProfile& profile : description.profiles) warnAbout(profile.warnings);
  warnAbout(scene::degenerateObjectWarnings(description, false));
  // Every object placed before any is added: a refused one leaves the scene as it was. Each by the
  // 4x4 of its transform, as add_revolution places a shape.
  std::vector<std::tuple<Shape, app::Placement, Scene::RevolutionRecipe>> placed;
  for (std::size_t i = 0; i < description.objects.size(); ++i) {
    const io::SceneObject& object = description.objects[i];
    const io::SceneProfile& profile = description.profiles[object.profile];
    Shape shape = profile.spline ? Shape(*profile.spline) : Shape(*profile.profile);
    const app::Matrix3d linear = app::linearPart(object.transform);
    double rows[16] = {};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) rows[4 * r + c] = linear[r][c];
      rows[4 * r + 3] = object.transform.translate[r];
    }
    rows[15] = 1;
    const std::string name = path + ": objects[" + std::to_string(i) + "]'s transform";
    const app::Placement placement = placementOf(rows, shape, name.c_str());
    // Kept as add_revolution would take it: the curve's points and kind, or the polyline traced.
    Scene::RevolutionRecipe recipe;
    const std::span<const Point2> points = profile.spline ? profile.spline->points() : profile.profile->points();
    for (const Point2& p : points) recipe.points.insert(recipe.points.end(), {p.r, p.z});
    if (profile.spline) recipe.spline = splineKindName(profile.spline->kind());
    std::copy(rows, rows + 16, recipe.rows.begin());
    placed.emplace_back(std::move(shape), placement, std::move(recipe));
  }
  std::vector<std::uint32_t> ids;
  for (auto& [shape, placement, recipe] : placed) {
    ids.push_back(scene.addRevolution(std::move(shape), placement, std::move(recipe)));
  }
  if (!description.quads.empty()) {
    std::vector<float> vertices;
    std::vector<std::uint32_t> triangles;
    for (std::size_t q = 0; q < description.quads.size(); ++q) {
      for (const app::Vec3d& corner : description.quads[q].corners) {
        for (const double x : corner) vertices.push_back(float(x));
      }
      const auto base = std::uint32_t(4 * q);
      for (const std::uint32_t k : {base, base + 1, base + 2, base, base + 2, base + 3}) triangles.push_back(k);
    }
    ids.push_back(scene.addTriangles(vertices, triangles));
  }
  return ids;
}

py::dict castRays(Scene& scene, py::handle rays, py::handle nthreads) {
  const QueryArray in = queryArray(rays, "rays", 6, "ox, oy, oz, dx, dy, dz");
  const int threads = threadsArgument(nthreads, "nthreads", true);
  auto t = newArray<float>(in.leadingShape);
  auto geometry = newArray<std::uint32_t>(in.leadingShape), primitive = newArray<std::uint32_t>(in.leadingShape);
  auto uv = newArray<float>(in.leadingShape, 2), normal = newArray<float>(in.leadingShape, 3);
  const Scene::Hits out{t.mutable_data(), geometry.mutable_data(), primitive.mutable_data(), uv.mutable_data(),
                        normal.mutable_data()};
  std::optional<std::size_t> refused;
  {
    py::gil_scoped_release release;
    refused = scene.castRays(in.data, in.count, out, threads);
  }
  if (refused) refuse(in, "rays", *refused, true);
  py::dict result;
  result["t_hit"] = t;
  result["geometry_ids"] = geometry;
  result["primitive_ids"] = primitive;
  result["primitive_uvs"] = uv;
  result["primitive_normals"] = normal;
  return result;
}

py::array testOcclusions(Scene& scene, py::handle rays, py::handle tnearObject, py::handle tfarObject,
                         py::handle nthreads) {
  const QueryArray in = queryArray(rays, "rays", 6, "ox, oy, oz, dx, dy, dz");
  const double tnear = realArgument(tnearObject, "tnear"), tfar = realArgument(tfarObject, "tfar");
  const int threads = threadsArgument(nthreads, "nthreads", true);
  if (!(tnear >= 0 && tnear <= tfar)) {
    throw py::value_error("tnear = " + std::to_string(tnear) + ", tfar = " + std::to_string(tfar) +
                          ": need 0 <= tnear <= tfar");
  }
  auto occluded = newArray<bool>(in.leadingShape);
  bool* out = occluded.mutable_data();
  std::optional<std::size_t> refused;
  {
    py::gil_scoped_release release;
    refused = scene.testOcclusions(in.data, in.count, float(tnear), float(tfar), out, threads);
  }
  if (refused) refuse(in, "rays", *refused, true);
  return occluded;
}

py::array countIntersections(Scene& scene, py::handle rays, py::handle nthreads) {
  const QueryArray in = queryArray(rays, "rays", 6, "ox, oy, oz, dx, dy, dz");
  const int threads = threadsArgument(nthreads, "nthreads", true);
  auto counts = newArray<std::int32_t>(in.leadingShape);
  std::int32_t* out = counts.mutable_data();
  std::optional<std::size_t> refused;
  {
    py::gil_scoped_release release;
    refused = scene.countIntersections(in.data, in.count, out, threads);
  }
  if (refused) refuse(in, "rays", *refused, true);
  return counts;
}

py::dict listIntersections(Scene& scene, py::handle rays, py::handle nthreads) {
  const QueryArray in = queryArray(rays, "rays", 6, "ox, oy, oz, dx, dy, dz");
  const int threads = threadsArgument(nthreads, "nthreads", true);
  std::vector<Scene::Crossing> crossings;
  std::vector<std::uint32_t> splits;
  std::optional<std::size_t> refused;
  try {
    py::gil_scoped_release release;
    refused = scene.listIntersections(
        in.data, in.count,
        [&](std::size_t total) {
          crossings.resize(total);
          return crossings.data();
        },
        splits, threads);
  } catch (const std::length_error& error) {
    throw py::value_error(std::string("rays: ") + error.what());
  }
  if (refused) refuse(in, "rays", *refused, true);
  const py::ssize_t n = py::ssize_t(crossings.size());
  py::array_t<std::uint32_t> raySplits(py::ssize_t(splits.size())), rayIds(n), geometryIds(n), primitiveIds(n);
  py::array_t<float> tHit(n), uvs(std::vector<py::ssize_t>{n, 2});
  std::copy(splits.begin(), splits.end(), raySplits.mutable_data());
  std::uint32_t* ray = rayIds.mutable_data();
  std::uint32_t* geometry = geometryIds.mutable_data();
  std::uint32_t* primitive = primitiveIds.mutable_data();
  float* t = tHit.mutable_data();
  float* uv = uvs.mutable_data();
  for (std::size_t r = 0; r + 1 < splits.size(); ++r) {
    for (std::size_t k = splits[r]; k < splits[r + 1]; ++k) {
      const Scene::Crossing& c = crossings[k];
      ray[k] = std::uint32_t(r);
      geometry[k] = c.geometry;
      primitive[k] = c.primitive;
      t[k] = c.t;
      uv[2 * k] = c.u;
      uv[2 * k + 1] = c.v;
    }
  }
  py::dict result;
  result["ray_splits"] = raySplits;
  result["ray_ids"] = rayIds;
  result["geometry_ids"] = geometryIds;
  result["primitive_ids"] = primitiveIds;
  result["primitive_uvs"] = uvs;
  result["t_hit"] = tHit;
  return result;
}

struct ClosestArrays {
  py::array_t<float> points, uv, normal, distance;
  py::array_t<std::uint32_t> geometry, primitive;
};

ClosestArrays closest(Scene& scene, const char* method, py::handle queryPoints, bool signedDistance,
                      py::handle nthreads) {
  const QueryArray in = queryArray(queryPoints, "query_points", 3, "x, y, z");
  const int threads = threadsArgument(nthreads, "nthreads", true);
  ClosestArrays a{newArray<float>(in.leadingShape, 3),      newArray<float>(in.leadingShape, 2),
                  newArray<float>(in.leadingShape, 3),      newArray<float>(in.leadingShape),
                  newArray<std::uint32_t>(in.leadingShape), newArray<std::uint32_t>(in.leadingShape)};
  const Scene::Closest out{a.points.mutable_data(), a.geometry.mutable_data(), a.primitive.mutable_data(),
                           a.uv.mutable_data(),     a.normal.mutable_data(),   a.distance.mutable_data()};
  std::optional<std::size_t> refused;
  try {
    py::gil_scoped_release release;
    refused = scene.closestPoints(in.data, in.count, out, signedDistance, threads);
  } catch (const std::invalid_argument& limitation) {  // what this scene cannot answer exactly
    throw py::value_error(std::string(method) + ": " + limitation.what());
  }
  if (refused) refuse(in, "query_points", *refused, false);
  return a;
}

py::array occupancy(Scene& scene, py::handle queryPoints, py::handle nthreads) {
  const QueryArray in = queryArray(queryPoints, "query_points", 3, "x, y, z");
  const int threads = threadsArgument(nthreads, "nthreads", true);
  auto inside = newArray<float>(in.leadingShape);
  float* out = inside.mutable_data();
  std::optional<std::size_t> refused;
  try {
    py::gil_scoped_release release;
    refused = scene.occupancy(in.data, in.count, out, threads);
  } catch (const std::invalid_argument& limitation) {  // what this scene cannot answer exactly
    throw py::value_error(std::string("compute_occupancy: ") + limitation.what());
  }
  if (refused) refuse(in, "query_points", *refused, false);
  return inside;
}

// Open3D's ray vote count: accepted (at least 1), not needed.
void checkSamples(py::handle nsamples) {
  (void)integerArgument(nsamples, "nsamples", 1, std::numeric_limits<std::int32_t>::max());
}

}  // namespace

void bindRaycastingScene(py::module_& m) {
  py::class_<Scene> scene(m, "RaycastingScene",
                          R"(Surfaces of revolution traced exactly, and triangle meshes, in one Embree scene.

Open3D's RaycastingScene (open3d.t.geometry, 0.19) with its method names, arguments, result keys,
shapes and dtypes; numpy arrays in and out. Rays are float32 arrays of shape (..., 6) (origin,
direction), query points float32 (..., 3), both C-contiguous (read in place). Geometry ids count
0, 1, ... in the order geometries are added.)");
  scene.def(py::init<>());
  scene.attr("INVALID_ID") = py::int_(Scene::kInvalidId);
  scene.def(
      "add_revolution",
      [](Scene& s, py::handle points, py::handle transform, py::handle spline, py::handle tolerance) {
        Scene::RevolutionRecipe recipe;
        Shape shape = shapeOf(points, spline, tolerance, recipe);
        const app::Placement placement = placementFrom(transform, shape, recipe.rows);
        return s.addRevolution(std::move(shape), placement, std::move(recipe));
      },
      py::arg("points"), py::arg("transform") = py::none(), py::arg("spline") = py::none(),
      py::arg("tolerance") = py::none(),
      R"(Adds the surface swept by a profile about the z axis; returns its geometry id.

points: (N, 2) array of (r, z), r >= 0, a polyline, or a spline's points with `spline`.
transform: 4x4 affine object-to-world matrix (default: the identity).
spline: "linear", "quadratic", "bezier", "catmull-rom" or "natural": the curve is traced exactly,
    or, with `tolerance`, as the fewest polyline points within that distance of it.
Raises ProfileError (a ValueError) naming the point and the rule for a bad profile.)");
  scene.def("add_revolutions", &addRevolutions, py::arg("points"), py::arg("transforms") = py::none(),
            py::arg("spline") = py::none(), py::arg("tolerance") = py::none(),
            R"(Adds many surfaces of revolution in one call; returns their geometry ids (uint32, consecutive).

points: (N, P, 2) array of profiles, or a sequence of N (P_i, 2) arrays, each as add_revolution's.
transforms: (N, 4, 4) array of object-to-world matrices (default: the identity for all).
spline, tolerance: as add_revolution's, the same for every profile.
The shapes are built in parallel. Nothing is added if any profile or matrix is refused: the error
names the first (points[i] or transforms[i]) and the rule it breaks.)");
  scene.def("add_triangles", &addTriangles, py::arg("vertex_positions"), py::arg("triangle_indices"),
            "Adds a triangle mesh ((N, 3) vertices, (M, 3) vertex indices); returns its geometry id.");
  scene.def("load", &load, py::arg("path"),
            "Adds a scene file's objects (each a geometry, in order) and its quads (one mesh); returns their ids.");
  scene.def("cast_rays", &castRays, py::arg("rays"), py::arg("nthreads") = py::int_(0),
            "The first hit of each ray: dict of t_hit, geometry_ids, primitive_ids, primitive_uvs, primitive_normals.");
  scene.def("test_occlusions", &testOcclusions, py::arg("rays"), py::arg("tnear") = py::float_(0.0),
            py::arg("tfar") = py::float_(std::numeric_limits<double>::infinity()), py::arg("nthreads") = py::int_(0),
            "Whether each ray hits anything with tnear <= t <= tfar (bool array).");
  scene.def("count_intersections", &countIntersections, py::arg("rays"), py::arg("nthreads") = py::int_(0),
            "The number of surface crossings along each ray (t >= 0), int32 array.");
  scene.def("list_intersections", &listIntersections, py::arg("rays"), py::arg("nthreads") = py::int_(0),
            R"(Every surface crossing along each ray (t >= 0), as Open3D 0.19's list_intersections: a dict of
ray_splits (uint32, rays + 1: ray i's crossings are [ray_splits[i], ray_splits[i + 1]), rays taken in
C order whatever their leading shape), ray_ids, geometry_ids, primitive_ids (uint32), t_hit (float32)
and primitive_uvs (float32, (n, 2)), each ray's crossings nearest first (ties by geometry, then
primitive). Its crossings are count_intersections' own: a surface of revolution's each crossing
(a tangent touch as the boundary rules decide), a mesh's edge shared by two triangles once.)");
  scene.def(
      "compute_closest_points",
      [](Scene& s, py::handle points, py::handle threads) {
        const ClosestArrays a = closest(s, "compute_closest_points", points, false, threads);
        py::dict result;
        result["points"] = a.points;
        result["geometry_ids"] = a.geometry;
        result["primitive_ids"] = a.primitive;
        result["primitive_uvs"] = a.uv;
        result["primitive_normals"] = a.normal;
        return result;
      },
      py::arg("query_points"), py::arg("nthreads") = py::int_(0),
      "Exact closest surface points: dict of points, geometry_ids, primitive_ids, primitive_uvs, primitive_normals.");
  scene.def(
      "compute_distance",
      [](Scene& s, py::handle points, py::handle threads) {
        return closest(s, "compute_distance", points, false, threads).distance;
      },
      py::arg("query_points"), py::arg("nthreads") = py::int_(0), "Exact distance to the nearest surface (float32).");
  scene.def(
      "compute_signed_distance",
      [](Scene& s, py::handle points, py::handle threads, py::handle nsamples) {
        checkSamples(nsamples);
        return closest(s, "compute_signed_distance", points, true, threads).distance;
      },
      py::arg("query_points"), py::arg("nthreads") = py::int_(0), py::arg("nsamples") = py::int_(1),
      "Exact distance, negative inside a closed profile's solid (decided from the profile; nsamples, Open3D's ray "
      "vote, is not needed).");
  scene.def(
      "compute_occupancy",
      [](Scene& s, py::handle points, py::handle threads, py::handle nsamples) {
        checkSamples(nsamples);
        return occupancy(s, points, threads);
      },
      py::arg("query_points"), py::arg("nthreads") = py::int_(0), py::arg("nsamples") = py::int_(1),
      "1 inside a closed profile's solid, 0 outside (float32), decided from the profile.");
  scene.def("geometry_count", &Scene::geometryCount, "The number of geometries added.");
  scene.def("memory_bytes", &Scene::memoryBytes,
            "Heap bytes the scene holds: revolve's shapes, the meshes' arrays, and Embree's allocations for the scene "
            "(its BVHs; the device's own set-up included).");
  bindRaycastingPickling(scene);
}

}  // namespace revolve::python
