// POV-Ray 3.7 run as a separate process on an exported scene (io/pov_scene.h), the way the
// comparison needs it: one sample a pixel (-A), a linear OpenEXR image, a given thread count, and
// its own statistics file, whose Trace Time (the rendering alone, not the ~0.65 s start-up and
// parsing) is what is compared.
#pragma once

#include "render/renderer.h"

#include <cstdint>
#include <optional>
#include <string>

namespace revolve::bench {

// The povray executable found on PATH, or nothing.
std::optional<std::string> findPovray();

struct PovrayRequest {
  std::string directory;  // POV-Ray runs here: it writes only below its working directory
  std::string scene;      // the .pov file's name in `directory`
  std::string image;      // the .exr to write there
  int width = 0, height = 0, threads = 1;
  int depth = 4;  // Revolve_Depth
  bool shadows = true;
};

struct PovrayRun {
  double traceSeconds = 0, parseSeconds = 0, boundingSeconds = 0, wallSeconds = 0;
  std::uint64_t rays = 0, shadowRayTests = 0, latheTests = 0;
  render::Image image;  // linear RGB, row 0 at the top
};

// Runs POV-Ray and reads its statistics and image. Throws std::runtime_error with POV-Ray's last
// message when it fails or its output is missing.
PovrayRun runPovray(const std::string& povray, const PovrayRequest& request);

// Reads an image file (any format OpenImageIO reads) as linear RGB floats.
render::Image readImage(const std::string& path);

}  // namespace revolve::bench
