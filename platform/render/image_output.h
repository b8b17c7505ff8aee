// Writing the rendered image through OpenImageIO: PNG as 8-bit sRGB, EXR as linear half floats,
// chosen by the output's extension. OpenImageIO encodes the file into memory only; its bytes reach
// the output's temporary through the run's checked stream (io/output_set.h), so a failed write (a
// full disk) is an error, never a short file: OpenImageIO's own PNG writer does not report failed
// writes to a file it opened itself. The temporary is renamed into place with the run's other
// outputs, so a failed write leaves no partial image and an existing one untouched.
#pragma once

#include "io/output_set.h"
#include "render/renderer.h"

#include <string>
#include <vector>

namespace revolve::render {

enum class ImageFormat { png, exr };

// The format for `path`'s extension (case-insensitive), or std::runtime_error naming the file and
// the extensions supported. Call before rendering so a typo costs nothing.
ImageFormat imageFormatFor(const std::string& path);
// Encodes `image` in `output`'s format and writes it to `out` (the output's stream);
// std::runtime_error naming `output` when encoding or writing fails.
void writeImage(io::OutputStream& out, const std::string& output, const Image& image);

// A depth image: one float32 channel "Z" a pixel, row 0 at the top, in an EXR (any other extension
// is std::runtime_error naming `output`: depth needs its full precision); +inf where nothing was hit.
void checkDepthImageName(const std::string& output);
void writeDepthImage(io::OutputStream& out, const std::string& output, int width, int height,
                     const std::vector<float>& depth);

}  // namespace revolve::render
