#include "io/curve_tolerance.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>

namespace revolve::io {
namespace {

std::string shortest(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

// Control bytes as '?', and at most 40 bytes, so that a message stays one printable line.
std::string shown(std::string_view text) {
  std::string out = "\"";
  for (const char c : text.substr(0, 40)) out += (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) ? c : '?';
  return out + (text.size() > 40 ? "...\"" : "\"");
}

std::optional<double> decimal(std::string_view text) {
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || end != text.data() + text.size() || error != std::errc()) return std::nullopt;
  return value;
}

}  // namespace

std::optional<std::string> toleranceFault(double value, std::string_view written) {
  if (Profile::toleranceAllowed(value)) return std::nullopt;
  return (written.empty() ? shortest(value) : std::string(written)) + " is out of range: " + Profile::kToleranceRule;
}

std::optional<CurveTolerance> parseCurveTolerance(std::string_view text, bool pixelAllowed) {
  if (pixelAllowed && text == "pixel") return CurveTolerance{true, 0, std::string(text)};
  const std::optional<double> value = decimal(text);
  if (!value || toleranceFault(*value)) return std::nullopt;
  return CurveTolerance{false, *value, std::string(text)};
}

std::string toleranceTextFault(std::string_view text, bool pixelAllowed) {
  if (const std::optional<double> value = decimal(text)) {
    if (std::optional<std::string> fault = toleranceFault(*value, shown(text))) return *fault;
  }
  return shown(text) + (pixelAllowed ? " is neither \"pixel\" nor a number: " : " is not a number: ") +
         Profile::kToleranceRule;
}

bool onTheAxis(const Profile& polyline) {
  const std::span<const Point2> points = polyline.points();
  return std::all_of(points.begin(), points.end(), [](const Point2& p) { return p.r == 0.0; });
}

Profile curvePolyline(const Spline& curve, double tolerance) {
  Profile polyline = Profile::fromCurve(curve, tolerance);
  if (!onTheAxis(polyline)) return polyline;
  // The curve's largest radius lies at an end of one of its parts monotone in r: the points of a
  // shape's profile. Built only here, to say how far the tolerance must come down.
  const Shape shape(curve);  // named: the points belong to it
  double largest = 0;
  for (const Point2& p : shape.profile().points()) largest = std::max(largest, p.r);
  if (largest == 0) return polyline;  // the curve lies on the axis itself: its own (warned-of) business
  throw std::invalid_argument("polyline tolerance " + shortest(tolerance) + " collapses the " +
                              splineKindName(curve.kind()) +
                              " spline onto the axis: every point of its polyline has r = 0, a surface of no area that "
                              "nothing hits, where the curve reaches r = " +
                              shortest(largest) + "; a tolerance below that keeps the polyline off the axis");
}

}  // namespace revolve::io
