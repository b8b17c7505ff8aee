// revolve._revolve: the compiled half of the Python package (python/revolve/ is the other).
#include "bindings.h"

#include "io/input_file.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"

#include <revolve/revolve.h>

#include <pybind11/pybind11.h>

#include <cstring>

namespace revolve::python {
namespace {

const char* ruleName(ProfileError::Rule rule) {
  switch (rule) {
    case ProfileError::Rule::tooFewPoints:
      return "too_few_points";
    case ProfileError::Rule::nonFinite:
      return "non_finite";
    case ProfileError::Rule::negativeRadius:
      return "negative_radius";
    case ProfileError::Rule::selfIntersecting:
      return "self_intersecting";
    case ProfileError::Rule::tooManyPoints:
      return "too_many_points";
    case ProfileError::Rule::outOfRange:
      return "out_of_range";
    case ProfileError::Rule::segmentTooShort:
      return "segment_too_short";
    case ProfileError::Rule::badPointCount:
      return "bad_point_count";
    case ProfileError::Rule::crossesAxis:
      return "crosses_axis";
  }
  return "unknown";
}

// A message as a Python str: a file's bytes quoted in it need not be UTF-8, and a message that
// fails to decode would reach the user empty.
py::str messageText(const char* message) {
  PyObject* text = PyUnicode_DecodeUTF8(message, Py_ssize_t(std::strlen(message)), "replace");
  if (text == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(text);
}

void setError(PyObject* type, const char* message) { PyErr_SetObject(type, messageText(message).ptr()); }

void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 2) != 0) throw py::error_already_set();
}

}  // namespace

void warnAbout(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) warn(warning);
}

void warnAbout(const std::vector<ProfileWarning>& warnings, const char* argument) {
  for (const ProfileWarning& warning : warnings) warn(std::string(argument) + ": " + warning.message);
}

}  // namespace revolve::python

PYBIND11_MODULE(_revolve, m) {
  namespace py = pybind11;
  using namespace revolve;
  m.doc() = "revolve's compiled core: exact surfaces of revolution in Embree (see the package revolve).";
  m.attr("embree_version") = py::int_(embree::kMajorVersion);

  // A bad profile: a ValueError carrying the point's index and the rule's name.
  static py::exception<ProfileError> profileError(m, "ProfileError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const ProfileError& error) {
      py::object instance = py::reinterpret_borrow<py::object>(profileError.ptr())(python::messageText(error.what()));
      instance.attr("index") = error.index();
      instance.attr("rule") = python::ruleName(error.rule());
      PyErr_SetObject(profileError.ptr(), instance.ptr());
    } catch (const io::SceneError& error) {
      python::setError(PyExc_ValueError, error.what());
    } catch (const io::SensorError& error) {
      python::setError(PyExc_ValueError, error.what());
    } catch (const io::InputError& error) {
      python::setError(PyExc_ValueError, error.what());
    } catch (const py::value_error& error) {  // the bindings' own, their messages made printable too
      python::setError(PyExc_ValueError, error.what());
    } catch (const py::type_error& error) {
      python::setError(PyExc_TypeError, error.what());
    }
  });

  python::bindRaycastingScene(m);
  python::bindRobot(m);
}
