#include "image_output.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace revolve::render {

ImageFormat imageFormatFor(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".png") return ImageFormat::png;
  if (extension == ".exr") return ImageFormat::exr;
  throw std::runtime_error(path + ": unsupported image extension \"" + extension + "\"; use .png (8-bit sRGB) or .exr (linear half float)");
}

void writeImage(const std::string& file, const std::string& output, const Image& image) {
  const ImageFormat format = imageFormatFor(output);
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf linear(spec);
  linear.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.pixels.data());
  OIIO::ImageBuf out;
  OIIO::TypeDesc type = OIIO::TypeDesc::HALF;
  if (format == ImageFormat::png) {
    // 8-bit PNG stores display values: convert to sRGB, or OIIO would only clamp and quantise.
    if (!OIIO::ImageBufAlgo::colorconvert(out, linear, "linear", "sRGB")) {
      throw std::runtime_error(output + ": colour conversion failed: " + out.geterror());
    }
    type = OIIO::TypeDesc::UINT8;
  } else {
    out.copy(linear);
    out.specmod().attribute("compression", "zip");
  }
  if (!out.write(file, type, format == ImageFormat::png ? "png" : "openexr")) {
    throw std::runtime_error(output + ": write failed: " + out.geterror());
  }
}

}  // namespace revolve::render
