// Rendering a scene given as JSON text, in process, for the renderer's tests.
#pragma once

#include "io/scene_file.h"
#include "render/image_output.h"
#include "render/renderer.h"
#include "scene/embree_scene.h"

#include <cmath>
#include <string>

namespace revolve::testing {

struct RenderRun {
  io::SceneDescription description;
  render::RenderResult result;
};

inline RenderRun renderText(const std::string& json, const render::RenderSettings& settings,
                            const scene::BuildSettings& build = {}, const std::string& directory = ".") {
  RenderRun run{io::parseScene(json, "test.json", directory), {}};
  const scene::EmbreeScene built(run.description, build);
  run.result = render::render(run.description, built, settings);
  return run;
}

inline RenderRun renderFile(const std::string& path, const render::RenderSettings& settings,
                            const scene::BuildSettings& build = {}) {
  RenderRun run{io::readScene(path), {}};
  const scene::EmbreeScene built(run.description, build);
  run.result = render::render(run.description, built, settings);
  return run;
}

// Mean over pixels and channels of |a - b|, each value clamped to [0, 1] first (what a display shows).
inline double meanAbsoluteDifference(const render::Image& a, const render::Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    sum += std::abs(std::clamp(double(a.pixels[i]), 0.0, 1.0) - std::clamp(double(b.pixels[i]), 0.0, 1.0));
  }
  return sum / double(a.pixels.size());
}

// Points of a half circle of radius `radius` about the origin, `segments` chords, as JSON [[r, z], ...].
inline std::string spherePointsJson(double radius, int segments) {
  std::string text = "[";
  for (int i = 0; i <= segments; ++i) {
    const double theta = 3.14159265358979323846 * i / segments;
    const double r = (i == 0 || i == segments) ? 0.0 : radius * std::sin(theta);
    char buffer[80];
    std::snprintf(buffer, sizeof buffer, "%s[%.17g, %.17g]", i == 0 ? "" : ", ", r, -radius * std::cos(theta));
    text += buffer;
  }
  return text + "]";
}

}  // namespace revolve::testing
