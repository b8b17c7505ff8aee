// Writing the rendered image through OpenImageIO: PNG as 8-bit sRGB, EXR as linear half floats,
// chosen by the file's extension; written to a temporary file beside it and renamed into place, so
// a failed write leaves no partial image and an existing one untouched.
#pragma once

#include "renderer.h"

#include <string>

namespace revolve::render {

enum class ImageFormat { png, exr };

// The format for `path`'s extension (case-insensitive), or std::runtime_error naming the file and
// the extensions supported. Call before rendering so a typo costs nothing.
ImageFormat imageFormatFor(const std::string& path);
// Whether a file can be created in `path`'s folder: throws std::runtime_error naming it otherwise.
void checkWritable(const std::string& path);
void writeImage(const std::string& path, const Image& image);

}  // namespace revolve::render
