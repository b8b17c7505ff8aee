// The one validation layer every binding takes its scalar arguments through: a path, a piece of
// text, a real number, a whole number within bounds, a thread count. Each takes the Python object
// as given (so that pybind's own conversion, whose failures read "Unable to cast" or list the
// signature over several lines, never runs) and returns the C++ value, or raises a TypeError (the
// kind is wrong) or a ValueError (the value is) naming the argument, the value and the rule, on
// one line. Arrays go through numpy_inputs.h.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>

namespace revolve::python {

namespace py = pybind11;

// A file's path: str, bytes (decoded as os.fsdecode does) or os.PathLike.
std::string pathArgument(py::handle value, const char* name);
// A str; None gives nothing where `optional`.
std::string textArgument(py::handle value, const char* name);
std::optional<std::string> optionalText(py::handle value, const char* name);
// A real number: int, float or a numpy real scalar (not bool, not a str, not a sequence). Not
// finite values are the caller's to refuse (some arguments take inf).
double realArgument(py::handle value, const char* name);
std::optional<double> optionalReal(py::handle value, const char* name);
// A whole number (int or numpy integer, not bool, not float) within [lo, hi]; a ValueError names
// the value, however large, and the range.
std::int64_t integerArgument(py::handle value, const char* name, std::int64_t lo, std::int64_t hi);
std::uint64_t unsignedArgument(py::handle value, const char* name, std::uint64_t lo, std::uint64_t hi);
// A thread count for the platform's arenas (threads/thread_arenas.h): 0 means all of this
// machine's threads, 1 to kMaxThreads that many. `negativeMeansAll`: Open3D's nthreads, for which
// a negative count also means all; otherwise a negative count is refused.
int threadsArgument(py::handle value, const char* name, bool negativeMeansAll);

}  // namespace revolve::python
