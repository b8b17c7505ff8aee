#include "revolution_set.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace revolve::ospray_module {

namespace {

std::string splineKindsList() {
  std::string names;
  for (SplineKind kind :
       {SplineKind::linear, SplineKind::quadratic, SplineKind::bezier, SplineKind::catmullRom, SplineKind::natural}) {
    names += std::string(names.empty() ? "" : ", ") + "\"" + splineKindName(kind) + "\"";
  }
  return names;
}

// The text as a message can show it: printable ASCII as is, a backslash and a double quote escaped,
// any other byte as \xNN (a string set through ospSetString's pointer mix-up is raw bytes).
std::string printable(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\\' || c == '"') {
      shown += '\\';
      shown += c;
    } else if (byte >= 0x20 && byte < 0x7f) {
      shown += c;
    } else {
      shown += "\\x";
      shown += kHex[byte >> 4];
      shown += kHex[byte & 0xf];
    }
  }
  return shown;
}

// The shortest text that reads back as the same float: the value as the caller set it.
std::string formatNumber(float value) {
  char text[32];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, value);
  return std::string(text, end.ptr);
}

// The parameters every profile shares, checked once: the spline kind, the tolerance.
std::optional<SplineKind> checkedSplineKind(const RevolutionParameters& parameters) {
  if (!parameters.spline) {
    if (parameters.tolerance) {
      throw std::invalid_argument("'tolerance' is given without a 'spline': a polyline profile is traced exactly");
    }
    return std::nullopt;
  }
  const std::optional<SplineKind> kind = splineKindNamed(*parameters.spline);
  if (!kind) {
    throw std::invalid_argument("'spline' is \"" + printable(*parameters.spline) + "\": it must be one of " +
                                splineKindsList());
  }
  if (parameters.tolerance && !Profile::toleranceAllowed(*parameters.tolerance)) {
    throw std::invalid_argument("'tolerance' is " + formatNumber(*parameters.tolerance) + ": " +
                                Profile::kToleranceRule);
  }
  return kind;
}

Revolution buildOne(std::span<const Point2> points, std::optional<SplineKind> kind, std::optional<float> tolerance) {
  if (!kind) return Revolution{Shape(Profile(points)), std::nullopt, {}};
  Spline curve(*kind, points);
  if (!tolerance || *kind == SplineKind::linear) return Revolution{Shape(std::move(curve)), std::nullopt, {}};
  Profile polyline = Profile::fromCurve(curve, *tolerance);
  ShadingNormals normals(polyline, curve);
  std::vector<float> segmentStart;
  const std::span<const double> arc = polyline.arcLength();
  for (std::size_t i = 0; i + 1 < arc.size(); ++i) segmentStart.push_back(float(arc[i] / arc.back()));
  return Revolution{Shape(std::move(polyline)), std::move(normals), std::move(segmentStart)};
}

}  // namespace

std::optional<Vec3> Revolution::shadingNormal(float u, float v) const noexcept {
  if (!curveNormals) return std::nullopt;
  // v rounds to float: a hit near a vertex may land in the neighbouring segment, whose clamped
  // curve normal there is the same point of the curve's (continuous away from its corners).
  const auto after = std::upper_bound(segmentStart.begin(), segmentStart.end(), v);
  const std::size_t segment = after == segmentStart.begin() ? 0 : std::size_t(after - segmentStart.begin()) - 1;
  return curveNormals->normal(std::uint32_t(segment), u, v);
}

std::vector<Revolution> buildRevolutions(const RevolutionParameters& parameters) {
  if (parameters.profiles.empty()) {
    throw std::invalid_argument("'profile' is missing or empty: a revolution needs a profile of (r, z) points");
  }
  const std::optional<SplineKind> kind = checkedSplineKind(parameters);
  std::vector<Revolution> revolutions;
  revolutions.reserve(parameters.profiles.size());
  for (std::size_t i = 0; i < parameters.profiles.size(); ++i) {
    try {
      revolutions.push_back(buildOne(parameters.profiles[i], kind, parameters.tolerance));
    } catch (const std::invalid_argument& error) {
      const std::string where =
          parameters.profiles.size() == 1 ? std::string("'profile'") : "'profile' " + std::to_string(i);
      throw std::invalid_argument(where + ": " + error.what());
    }
  }
  return revolutions;
}

}  // namespace revolve::ospray_module
