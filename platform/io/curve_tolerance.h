// A curve's polyline tolerance as every input gives it (a scene file's "tolerance",
// revolve-render's and revolve-trace's --tolerance, Python's tolerance=): one value type, one
// parser, one rule and its one message (the library's Profile::kToleranceRule), and the polyline a
// tool traces the curve as, refused only where the tolerance would lose the shape.
#pragma once

#include <revolve/core.h>

#include <optional>
#include <string>
#include <string_view>

namespace revolve::io {

struct CurveTolerance {
  bool pixel = false;  // "pixel" (revolve-render): the camera's pixel footprint at each object
  double value = 0;    // otherwise a distance in the profile's units, by the rule
  std::string text;    // as written, for the reports that echo it
};

// Why `value` cannot be a polyline tolerance ("<written> is out of range: " and the rule); nothing
// when it can. `written` is the value as the input wrote it (its number's shortest form when empty).
std::optional<std::string> toleranceFault(double value, std::string_view written = {});

// `text` as a tolerance: "pixel" where `pixelAllowed`, or a decimal number (an optional '+' first)
// held to the rule; nothing otherwise ("nan", "inf", "0", "-1", "1e-400", "", "abc").
std::optional<CurveTolerance> parseCurveTolerance(std::string_view text, bool pixelAllowed);
// Why parseCurveTolerance refuses `text`, as a sentence about the value as written (cut at 40
// bytes, control bytes shown as '?'); the caller names the option.
std::string toleranceTextFault(std::string_view text, bool pixelAllowed);

// Profile::fromCurve(curve, tolerance), or std::invalid_argument (stating the tolerance, the
// curve's largest radius and the rule) when every point of the polyline lies on the axis while the
// curve does not: a tolerance at or beyond the curve's largest radius may collapse it onto the axis,
// a surface of no area that nothing hits, where the curve had a shape. Also fromCurve's own
// std::invalid_argument for a tolerance it cannot take.
Profile curvePolyline(const Spline& curve, double tolerance);

// Whether `polyline` lies wholly on the axis (r = 0 at every point).
bool onTheAxis(const Profile& polyline);

}  // namespace revolve::io
