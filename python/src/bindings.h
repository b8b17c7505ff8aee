// The parts of the Python module revolve._revolve (module.cpp), and what they share.
#pragma once

#include <revolve/revolve.h>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace revolve::python {

namespace py = pybind11;

void bindRaycastingScene(py::module_& m);
void bindRobot(py::module_& m);
// RaycastingScene's _additions(), what revolve's pickling (revolve/_pickle.py) keeps of it.
class RaycastingScene;
void bindRaycastingPickling(py::class_<RaycastingScene>& scene);

// Python warnings (UserWarning) for what the readers and profiles drop or doubt.
void warnAbout(const std::vector<std::string>& warnings);
void warnAbout(const std::vector<ProfileWarning>& warnings, const char* argument);

}  // namespace revolve::python
