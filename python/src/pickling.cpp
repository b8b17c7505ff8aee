// What a pickle of a RaycastingScene keeps (revolve/_pickle.py): each addition, in id order, as the
// call that made it would take it again, so that replaying them rebuilds the scene with the same
// ids and the same answers. Nothing of Embree's or the search structures' memory: only what builds
// them.
#include "bindings.h"
#include "raycasting_scene.h"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace revolve::python {
namespace {

// ("revolution", points (N, 2) float64, transform (4, 4) float64, spline str or None, tolerance
// float or None) or ("triangles", vertex_positions (N, 3) float32, triangle_indices (M, 3) uint32).
py::list additions(const RaycastingScene& scene) {
  py::list out;
  const auto revolution = [&](const RaycastingScene::RevolutionRecipe& recipe) {
    py::array_t<double> points(std::vector<py::ssize_t>{py::ssize_t(recipe.points.size() / 2), 2});
    std::copy(recipe.points.begin(), recipe.points.end(), points.mutable_data());
    py::array_t<double> transform(std::vector<py::ssize_t>{4, 4});
    std::copy(recipe.rows.begin(), recipe.rows.end(), transform.mutable_data());
    const py::object spline = recipe.spline ? py::object(py::str(*recipe.spline)) : py::object(py::none());
    const py::object tolerance = recipe.tolerance ? py::object(py::float_(*recipe.tolerance)) : py::object(py::none());
    out.append(py::make_tuple("revolution", points, transform, spline, tolerance));
  };
  const auto mesh = [&](const scene::TriangleMesh& triangles) {
    // The vertex buffer holds one float past the last vertex (Embree reads 16 bytes at a time): the
    // vertices alone.
    const std::size_t count = triangles.vertexCount();
    py::array_t<float> vertices(std::vector<py::ssize_t>{py::ssize_t(count), 3});
    std::copy_n(triangles.vertices.begin(), 3 * count, vertices.mutable_data());
    py::array_t<std::uint32_t> indices(std::vector<py::ssize_t>{py::ssize_t(triangles.triangles.size() / 3), 3});
    std::copy(triangles.triangles.begin(), triangles.triangles.end(), indices.mutable_data());
    out.append(py::make_tuple("triangles", vertices, indices));
  };
  try {
    scene.forEachAddition(revolution, mesh);
  } catch (const std::logic_error& error) {
    throw py::value_error(std::string("cannot pickle this RaycastingScene: ") + error.what());
  }
  return out;
}

}  // namespace

void bindRaycastingPickling(py::class_<RaycastingScene>& scene) {
  scene.def("_additions", &additions,
            "Each addition in id order, as the call that made it takes it again (what a pickle keeps).");
}

}  // namespace revolve::python
