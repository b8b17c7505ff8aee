#include "geometry/ray_limits.h"

#include <cstdio>

namespace revolve::app {
namespace {

std::string number(float x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(x));
  return text;
}

std::string componentFault(const char* what, const char* axis, float x, double limit, const char* limitText) {
  if (!std::isfinite(x)) return std::string(what) + " " + axis + " = " + number(x) + " is not finite";
  if (!(std::abs(x) <= float(limit))) {
    return std::string(what) + " " + axis + " = " + number(x) + " lies beyond +-" + limitText +
           ", the range revolve traces within (Embree's single-precision range, inside every placed shape)";
  }
  return "";
}

constexpr const char* kAxes[3] = {"x", "y", "z"};

}  // namespace

std::string queryPointFault(const float* p) {
  for (int i = 0; i < 3; ++i) {
    std::string fault = componentFault("point", kAxes[i], p[i], kMaxRayOrigin, "4.4e12 (4 x 2^40)");
    if (!fault.empty()) return fault;
  }
  return "";
}

std::string queryRayFault(const float* r) {
  for (int i = 0; i < 3; ++i) {
    std::string fault = componentFault("origin", kAxes[i], r[i], kMaxRayOrigin, "4.4e12 (4 x 2^40)");
    if (!fault.empty()) return fault;
  }
  for (int i = 0; i < 3; ++i) {
    std::string fault = componentFault("direction", kAxes[i], r[3 + i], kMaxWorldCoordinate, "1.1e12 (2^40)");
    if (!fault.empty()) return fault;
  }
  if (r[3] == 0 && r[4] == 0 && r[5] == 0) return "direction (0, 0, 0) is zero: a ray needs a direction";
  return "";
}

}  // namespace revolve::app
