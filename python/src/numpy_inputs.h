// numpy arrays as the bindings take them. Query inputs (rays, points), which may be large, are
// read in place and so must be float32 and C-contiguous, as Open3D's RaycastingScene requires its
// tensors to be float32; small inputs (profiles, matrices, poses, meshes) are copied and may be any
// real dtype and layout. Every refusal is a TypeError (the dtype) or ValueError (shape, layout,
// value) naming the argument, what it got and the rule.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <vector>

namespace revolve::python {

namespace py = pybind11;

// `object` as an ndarray: an array itself, a tensor's .numpy(), or what numpy makes of a list or
// tuple; a ValueError naming `name` for a list numpy makes none of (a ragged one), a TypeError for
// anything else. `expected` says what was wanted, for the message.
py::array arrayArgument(py::handle object, const char* name, const std::string& expected);

// `array` converted to T (as numpy casts), C-contiguous and aligned: itself when it is all three,
// else a copy. An array that came through pickle or Dask may sit at any byte offset of its buffer,
// and reading a float at an odd address is undefined behaviour (the sanitizers' suite caught one).
template <class T>
py::array_t<T> alignedArray(const py::array& array) {
  return py::module_::import("numpy").attr("require")(array, py::dtype::of<T>(), "CA");
}

struct QueryArray {
  py::array array;  // holds the data alive
  const float* data = nullptr;
  std::size_t count = 0;                  // rows of `width` floats
  std::vector<py::ssize_t> leadingShape;  // the shape without its last axis: the results' shape
};

// `object`: a numpy array (or anything with .numpy(), as Open3D's tensors) of float32, C-contiguous,
// shape (..., width); `columns` names its columns for the message ("ox, oy, oz, dx, dy, dz").
QueryArray queryArray(py::handle object, const char* name, py::ssize_t width, const char* columns);

// "rays[3, 17]": the index of row `flat` of an array of that leading shape.
std::string indexText(const char* name, const std::vector<py::ssize_t>& leadingShape, std::size_t flat);

// A copy in double, C order, of a real array of exactly `rows` x `columns` (rows < 0: any number
// of rows, at least `minRows`); every entry finite unless the caller checks that itself.
py::array_t<double> copiedMatrix(py::handle object, const char* name, py::ssize_t rows, py::ssize_t columns,
                                 py::ssize_t minRows = 0, bool requireFinite = true);

// A new array of the given shape (the leading shape and, when non-zero, a last axis).
template <class T>
py::array_t<T> newArray(std::vector<py::ssize_t> shape, py::ssize_t last = 0) {
  if (last > 0) shape.push_back(last);
  return py::array_t<T>(shape);
}

// "(3, 4)".
std::string shapeText(const py::array& array);

}  // namespace revolve::python
