#include "arguments.h"

#include "threads/thread_arenas.h"

#include <cmath>

namespace revolve::python {
namespace {

std::string typeName(py::handle value) { return py::str(py::type::handle_of(value).attr("__name__")); }

[[noreturn]] void wrongType(py::handle value, const char* name, const char* expected) {
  throw py::type_error(std::string(name) + ": a " + typeName(value) + "; expected " + expected);
}

// The object's integer value (operator.index: int, numpy integers), or nothing.
std::optional<py::int_> indexOf(py::handle value) {
  if (PyBool_Check(value.ptr())) return std::nullopt;  // True is no count
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    return std::nullopt;
  }
  return py::reinterpret_steal<py::int_>(index);
}

}  // namespace

std::string pathArgument(py::handle value, const char* name) {
  if (!py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) && !py::hasattr(value, "__fspath__")) {
    wrongType(value, name, "a path (str or os.PathLike)");
  }
  py::object text;
  try {
    text = py::module_::import("os").attr("fsdecode")(value);
  } catch (py::error_already_set& error) {       // an __fspath__ that returned neither str nor bytes, say
    if (!error.matches(PyExc_Exception)) throw;  // a signal handler's SystemExit or KeyboardInterrupt
    throw py::type_error(std::string(name) + ": not a path: " + std::string(py::str(error.value())));
  }
  const std::string path = py::str(text);
  if (path.find('\0') != std::string::npos) {
    throw py::value_error(std::string(name) + ": the path holds a NUL character, which no file name may");
  }
  if (path.empty()) throw py::value_error(std::string(name) + ": the path is empty");
  return path;
}

std::string textArgument(py::handle value, const char* name) {
  if (!py::isinstance<py::str>(value)) wrongType(value, name, "a str");
  return py::str(value);
}

std::optional<std::string> optionalText(py::handle value, const char* name) {
  if (value.is_none()) return std::nullopt;
  return textArgument(value, name);
}

double realArgument(py::handle value, const char* name) {
  const bool real = PyFloat_Check(value.ptr()) || PyLong_Check(value.ptr()) ||
                    py::isinstance(value, py::module_::import("numpy").attr("floating")) ||
                    py::isinstance(value, py::module_::import("numpy").attr("integer"));
  if (!real || PyBool_Check(value.ptr())) wrongType(value, name, "a real number");
  const double x = PyFloat_AsDouble(value.ptr());
  if (x == -1.0 && PyErr_Occurred()) {  // an int beyond double's range
    PyErr_Clear();
    throw py::value_error(std::string(name) + " = " + std::string(py::str(value)) + ": beyond double's range");
  }
  return x;
}

std::optional<double> optionalReal(py::handle value, const char* name) {
  if (value.is_none()) return std::nullopt;
  return realArgument(value, name);
}

std::int64_t integerArgument(py::handle value, const char* name, std::int64_t lo, std::int64_t hi) {
  const std::optional<py::int_> index = indexOf(value);
  if (!index) wrongType(value, name, "a whole number (int)");
  if (*index < py::int_(lo) || *index > py::int_(hi)) {
    throw py::value_error(std::string(name) + " = " + std::string(py::str(py::handle(*index))) + ": must lie in [" +
                          std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return index->cast<std::int64_t>();
}

std::uint64_t unsignedArgument(py::handle value, const char* name, std::uint64_t lo, std::uint64_t hi) {
  const std::optional<py::int_> index = indexOf(value);
  if (!index) wrongType(value, name, "a whole number (int)");
  if (*index < py::int_(lo) || *index > py::int_(hi)) {
    throw py::value_error(std::string(name) + " = " + std::string(py::str(py::handle(*index))) + ": must lie in [" +
                          std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return index->cast<std::uint64_t>();
}

int threadsArgument(py::handle value, const char* name, bool negativeMeansAll) {
  const std::optional<py::int_> index = indexOf(value);
  if (!index) wrongType(value, name, "a whole number of threads (int)");
  if (negativeMeansAll && *index < py::int_(0)) return 0;
  if (*index < py::int_(0) || *index > py::int_(app::kMaxThreads)) {
    throw py::value_error(std::string(name) + " = " + std::string(py::str(py::handle(*index))) +
                          ": a thread count lies in [0, " + std::to_string(app::kMaxThreads) + "] (0" +
                          (negativeMeansAll ? " or less" : "") + ": all of this machine's threads)");
  }
  return index->cast<int>();
}

}  // namespace revolve::python
