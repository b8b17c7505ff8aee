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

namespace {

std::string folderOf(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  return folder.empty() ? "." : folder.string();
}

// A fresh temporary file beside `path` (so the final rename stays within one file system).
std::string temporaryBeside(const std::string& path) {
  std::string temporary = (std::filesystem::path(folderOf(path)) / ".revolve-render-XXXXXX").string();
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) throw std::runtime_error(path + ": cannot create a file in " + folderOf(path) + ": " + std::strerror(errno));
  close(descriptor);
  return temporary;
}

}  // namespace

ImageFormat imageFormatFor(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".png") return ImageFormat::png;
  if (extension == ".exr") return ImageFormat::exr;
  throw std::runtime_error(path + ": unsupported image extension \"" + extension + "\"; use .png (8-bit sRGB) or .exr (linear half float)");
}

void checkWritable(const std::string& path) {
  std::error_code code;
  if (std::filesystem::is_directory(path, code)) throw std::runtime_error(path + ": is a directory, not an image file");
  std::remove(temporaryBeside(path).c_str());
}

void writeImage(const std::string& path, const Image& image) {
  const ImageFormat format = imageFormatFor(path);
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf linear(spec);
  linear.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.pixels.data());
  OIIO::ImageBuf out;
  OIIO::TypeDesc type = OIIO::TypeDesc::HALF;
  if (format == ImageFormat::png) {
    // 8-bit PNG stores display values: convert to sRGB, or OIIO would only clamp and quantise.
    if (!OIIO::ImageBufAlgo::colorconvert(out, linear, "linear", "sRGB")) {
      throw std::runtime_error(path + ": colour conversion failed: " + out.geterror());
    }
    type = OIIO::TypeDesc::UINT8;
  } else {
    out.copy(linear);
    out.specmod().attribute("compression", "zip");
  }
  const std::string temporary = temporaryBeside(path);
  const mode_t mask = umask(0);
  umask(mask);
  if (!out.write(temporary, type, format == ImageFormat::png ? "png" : "openexr")) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": write failed: " + out.geterror());
  }
  chmod(temporary.c_str(), 0666 & ~mask);  // mkstemp made it private; give it a plain file's mode
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot replace: " + std::strerror(error));
  }
}

}  // namespace revolve::render
