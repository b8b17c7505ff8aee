// Two renderings of one scene compared after matching exposure, and shown side by side.
#pragma once

#include "render/renderer.h"

#include <string>

namespace revolve::bench {

struct ImageDifference {
  // The factor the other image is scaled by to match the reference: the least-squares fit of
  // k * other to reference (1 when the two renderers' light units agree).
  double exposure = 1;
  // Over every pixel and channel, linear values clamped to [0, 1] (what an 8-bit picture shows):
  double meanAbsolute = 0;     // mean |reference - k * other|
  double meanReference = 0;    // mean of the reference, for scale
  double differingPixels = 0;  // fraction of pixels with some channel differing by more than 0.05
};

// The images must have the same size (std::invalid_argument otherwise).
ImageDifference compareImages(const render::Image& reference, const render::Image& other);

// reference | k * other | |difference| x 4, side by side, each labelled (when the DejaVu Sans font
// is installed), written atomically as an 8-bit sRGB PNG.
void writeSideBySide(const std::string& path, const render::Image& reference, const render::Image& other,
                     double exposure, const std::string& referenceLabel, const std::string& otherLabel);

}  // namespace revolve::bench
