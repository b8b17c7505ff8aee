#include "image_compare.h"

#include "io/output_set.h"

#include "render/image_output.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace revolve::bench {
namespace {

float clamped(float value) { return std::clamp(value, 0.0f, 1.0f); }

constexpr int kGap = 4;                      // pixels between the panels
constexpr float kDifferenceScale = 4;        // the difference panel's gain
constexpr double kVisibleDifference = 0.05;  // linear; a few 8-bit sRGB steps in the mid-tones

}  // namespace

ImageDifference compareImages(const render::Image& reference, const render::Image& other) {
  if (reference.width != other.width || reference.height != other.height) {
    throw std::invalid_argument("images of different sizes: " + std::to_string(reference.width) + " x " +
                                std::to_string(reference.height) + " and " + std::to_string(other.width) + " x " +
                                std::to_string(other.height));
  }
  double dot = 0, square = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    dot += double(clamped(reference.pixels[i])) * clamped(other.pixels[i]);
    square += double(clamped(other.pixels[i])) * clamped(other.pixels[i]);
  }
  ImageDifference d;
  d.exposure = square > 0 ? dot / square : 1;
  std::size_t differing = 0;
  for (std::size_t p = 0; p < reference.pixels.size(); p += 3) {
    bool visible = false;
    for (std::size_t c = p; c < p + 3; ++c) {
      const double a = clamped(reference.pixels[c]), b = clamped(float(d.exposure * other.pixels[c]));
      d.meanAbsolute += std::abs(a - b);
      d.meanReference += a;
      visible = visible || std::abs(a - b) > kVisibleDifference;
    }
    differing += visible ? 1 : 0;
  }
  const double values = double(reference.pixels.size());
  d.meanAbsolute /= values;
  d.meanReference /= values;
  d.differingPixels = double(differing) / (values / 3);
  return d;
}

void writeSideBySide(const std::string& path, const render::Image& reference, const render::Image& other,
                     double exposure, const std::string& referenceLabel, const std::string& otherLabel) {
  const int w = reference.width, h = reference.height;
  render::Image combined;
  combined.width = 3 * w + 2 * kGap;
  combined.height = h;
  combined.pixels.assign(3 * std::size_t(combined.width) * h, 1.0f);  // white gaps
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t source = 3 * (std::size_t(y) * w + x);
      for (int c = 0; c < 3; ++c) {
        const float a = reference.pixels[source + c], b = float(exposure * other.pixels[source + c]);
        const std::size_t row = 3 * std::size_t(y) * combined.width;
        combined.pixels[row + 3 * std::size_t(x) + c] = a;
        combined.pixels[row + 3 * std::size_t(x + w + kGap) + c] = b;
        combined.pixels[row + 3 * std::size_t(x + 2 * (w + kGap)) + c] =
            kDifferenceScale * std::abs(clamped(a) - clamped(b));
      }
    }
  }
  // Labels in the panels' top left corners, if the font is there; the figure is whole without them.
  OIIO::ImageBuf buffer(OIIO::ImageSpec(combined.width, combined.height, 3, OIIO::TypeDesc::FLOAT),
                        combined.pixels.data());
  const float white[3] = {1, 1, 1};
  const int size = std::clamp(h / 24, 10, 24);
  const std::string labels[3] = {referenceLabel, otherLabel, "|difference| x 4"};
  for (int panel = 0; panel < 3; ++panel) {
    if (!OIIO::ImageBufAlgo::render_text(buffer, panel * (w + kGap) + size / 2, size + size / 3, labels[panel], size,
                                         "DejaVuSans", white)) {
      std::fprintf(stderr, "revolve-bench: note: %s has no labels (%s)\n", path.c_str(), buffer.geterror().c_str());
      break;
    }
  }
  io::OutputSet outputs;
  outputs.add("the side-by-side figure", path);
  render::writeImage(outputs.stream(path), path, combined);
  outputs.commit();
}

}  // namespace revolve::bench
