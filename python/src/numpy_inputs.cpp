#include "numpy_inputs.h"

#include <cmath>
#include <cstdio>

namespace revolve::python {
namespace {

std::string typeName(py::handle object) { return py::str(py::type::handle_of(object).attr("__name__")); }

}  // namespace

py::array arrayArgument(py::handle object, const char* name, const std::string& expected) {
  if (py::isinstance<py::array>(object)) return py::reinterpret_borrow<py::array>(object);
  if (!py::isinstance<py::str>(object) && py::hasattr(object, "numpy")) {
    py::object converted = object.attr("numpy")();
    if (py::isinstance<py::array>(converted)) return py::reinterpret_steal<py::array>(converted.release());
  }
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    // Lists are fine where the values are copied anyway; numpy decides their dtype. A ragged list
    // (rows of different lengths) makes no array: numpy says so, and nothing is read.
    try {
      return py::module_::import("numpy").attr("asarray")(object);
    } catch (py::error_already_set& error) {
      if (!error.matches(PyExc_Exception)) throw;  // a signal handler's SystemExit or KeyboardInterrupt
      const bool ragged = error.matches(PyExc_ValueError);
      throw py::value_error(std::string(name) + ": " +
                            (ragged ? "a ragged list (its rows differ in length)" : "a list numpy makes no array of") +
                            "; expected " + expected);
    }
  }
  throw py::type_error(std::string(name) + ": a " + typeName(object) + "; expected " + expected);
}

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) text += (i > 0 ? ", " : "") + std::to_string(array.shape(i));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

QueryArray queryArray(py::handle object, const char* name, py::ssize_t width, const char* columns) {
  const std::string expected = "a numpy array of float32 with shape (..., " + std::to_string(width) + ")";
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    throw py::type_error(std::string(name) + ": a " + typeName(object) + "; expected " + expected + " (numpy.asarray(" +
                         name + ", dtype=numpy.float32))");
  }
  py::array array = arrayArgument(object, name, expected);
  // float32 whatever dtype object says so (numpy's own, an unpickled one, '=f4'), read in place in
  // this machine's byte order: the other order would read as garbage.
  const py::dtype dtype = array.dtype();
  if (dtype.kind() != 'f' || dtype.itemsize() != 4) {
    throw py::type_error(std::string(name) + ": dtype " + std::string(py::str(py::handle(dtype))) +
                         "; expected float32, as Open3D's RaycastingScene (" + name + ".astype(numpy.float32))");
  }
  if (!dtype.attr("isnative").cast<bool>()) {
    throw py::type_error(std::string(name) + ": float32 in the other byte order (" +
                         std::string(py::str(dtype.attr("str"))) + "); revolve reads " + name +
                         " in place, in this machine's byte order: pass " + name + ".astype(numpy.float32)");
  }
  if (array.ndim() < 1 || array.shape(array.ndim() - 1) != width) {
    throw py::value_error(std::string(name) + ": shape " + shapeText(array) + "; the last axis must hold " +
                          std::to_string(width) + " numbers (" + columns + ")");
  }
  if (!(array.flags() & py::array::c_style)) {
    throw py::value_error(std::string(name) + ": not C-contiguous; revolve reads " + name +
                          " in place, without a copy: pass numpy.ascontiguousarray(" + name + ")");
  }
  // Read in place, but never at an odd address: an unaligned buffer (unpickled, from Dask) is copied.
  if (!(array.flags() & py::detail::npy_api::NPY_ARRAY_ALIGNED_)) array = alignedArray<float>(array);
  QueryArray result;
  result.leadingShape.assign(array.shape(), array.shape() + array.ndim() - 1);
  result.count = std::size_t(array.size() / width);
  result.data = static_cast<const float*>(array.data());
  result.array = std::move(array);
  return result;
}

std::string indexText(const char* name, const std::vector<py::ssize_t>& leadingShape, std::size_t flat) {
  std::vector<std::size_t> index(leadingShape.size());
  for (std::size_t k = leadingShape.size(); k-- > 0;) {
    index[k] = flat % std::size_t(leadingShape[k]);
    flat /= std::size_t(leadingShape[k]);
  }
  std::string text = std::string(name) + "[";
  for (std::size_t k = 0; k < index.size(); ++k) text += (k > 0 ? ", " : "") + std::to_string(index[k]);
  return text + "]";
}

py::array_t<double> copiedMatrix(py::handle object, const char* name, py::ssize_t rows, py::ssize_t columns,
                                 py::ssize_t minRows, bool requireFinite) {
  const std::string shape =
      "(" + (rows >= 0 ? std::to_string(rows) : std::string("N")) + ", " + std::to_string(columns) + ")";
  py::array array = arrayArgument(object, name, "a numpy array of shape " + shape);
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + ": dtype " + std::string(py::str(array.dtype())) +
                         "; expected real numbers (float or integer)");
  }
  if (array.ndim() != 2 || array.shape(1) != columns || (rows >= 0 && array.shape(0) != rows) ||
      array.shape(0) < minRows) {
    throw py::value_error(std::string(name) + ": shape " + shapeText(array) + "; expected " + shape +
                          (minRows > 0 ? " with at least " + std::to_string(minRows) + " rows" : std::string()));
  }
  const py::array_t<double> copy = alignedArray<double>(array);
  py::array_t<double> result(std::vector<py::ssize_t>{copy.shape(0), copy.shape(1)});
  std::copy(copy.data(), copy.data() + copy.size(), result.mutable_data());
  const double* values = result.data();
  for (py::ssize_t i = 0; requireFinite && i < result.size(); ++i) {
    if (!std::isfinite(values[i])) {
      char text[32];
      std::snprintf(text, sizeof text, "%.9g", values[i]);
      throw py::value_error(std::string(name) + "[" + std::to_string(i / columns) + ", " + std::to_string(i % columns) +
                            "] = " + text + " is not finite");
    }
  }
  return result;
}

}  // namespace revolve::python
