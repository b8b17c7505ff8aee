// Writing the rendered image through OpenImageIO: PNG as 8-bit sRGB, EXR as linear half floats,
// chosen by the output's extension. The tool writes it into its output's temporary file
// (io/output_set.h), renamed into place with the run's other outputs, so a failed write leaves no
// partial image and an existing one untouched.
#pragma once

#include "renderer.h"

#include <string>

namespace revolve::render {

enum class ImageFormat { png, exr };

// The format for `path`'s extension (case-insensitive), or std::runtime_error naming the file and
// the extensions supported. Call before rendering so a typo costs nothing.
ImageFormat imageFormatFor(const std::string& path);
// Writes `image` in `output`'s format into `file` (its temporary); std::runtime_error naming
// `output` when OpenImageIO fails (a full disk, say).
void writeImage(const std::string& file, const std::string& output, const Image& image);

}  // namespace revolve::render
