#include "render/image_output.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace revolve::render {

ImageFormat imageFormatFor(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".png") return ImageFormat::png;
  if (extension == ".exr") return ImageFormat::exr;
  throw std::runtime_error(path + ": unsupported image extension \"" + extension +
                           "\"; use .png (8-bit sRGB) or .exr (linear half float)");
}

void writeImage(io::OutputStream& out, const std::string& output, const Image& image) {
  const ImageFormat format = imageFormatFor(output);
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf linear(spec);
  linear.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.pixels.data());
  OIIO::ImageBuf converted;
  OIIO::TypeDesc type = OIIO::TypeDesc::HALF;
  if (format == ImageFormat::png) {
    // 8-bit PNG stores display values: convert to sRGB, or OIIO would only clamp and quantise.
    if (!OIIO::ImageBufAlgo::colorconvert(converted, linear, "linear", "sRGB")) {
      throw std::runtime_error(output + ": colour conversion failed: " + converted.geterror());
    }
    type = OIIO::TypeDesc::UINT8;
  } else {
    converted.copy(linear);
    converted.specmod().attribute("compression", "zip");
  }
  // Encoded into memory (the name only tells OpenImageIO the format), then written through the
  // checked stream.
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  converted.set_write_ioproxy(&memory);
  const std::string name = format == ImageFormat::png ? "image.png" : "image.exr";
  if (!converted.write(name, type, format == ImageFormat::png ? "png" : "openexr")) {
    throw std::runtime_error(output + ": encoding the image failed: " + converted.geterror());
  }
  out.write(bytes.data(), bytes.size());
}

void checkDepthImageName(const std::string& output) {
  if (imageFormatFor(output) != ImageFormat::exr) {
    throw std::runtime_error(output + ": a depth image is written as EXR (float32 metres); name it .exr");
  }
}

void writeDepthImage(io::OutputStream& out, const std::string& output, int width, int height,
                     const std::vector<float>& depth) {
  checkDepthImageName(output);
  OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"Z"};
  spec.attribute("compression", "zip");
  OIIO::ImageBuf buffer(spec);
  buffer.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, depth.data());
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  buffer.set_write_ioproxy(&memory);
  if (!buffer.write("depth.exr", OIIO::TypeDesc::FLOAT, "openexr")) {
    throw std::runtime_error(output + ": encoding the depth image failed: " + buffer.geterror());
  }
  out.write(bytes.data(), bytes.size());
}

}  // namespace revolve::render
