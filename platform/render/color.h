// Linear RGB radiance and reflectance.
#pragma once

#include <algorithm>

namespace revolve::render {

struct Color {
  float r = 0, g = 0, b = 0;
  Color& operator+=(Color c) {
    r += c.r, g += c.g, b += c.b;
    return *this;
  }
  float max() const { return std::max({r, g, b}); }
  bool black() const { return r == 0 && g == 0 && b == 0; }
};
inline Color operator+(Color a, Color c) { return {a.r + c.r, a.g + c.g, a.b + c.b}; }
inline Color operator*(Color a, Color c) { return {a.r * c.r, a.g * c.g, a.b * c.b}; }
inline Color operator*(float s, Color c) { return {s * c.r, s * c.g, s * c.b}; }
inline Color operator*(Color c, float s) { return {s * c.r, s * c.g, s * c.b}; }

}  // namespace revolve::render
