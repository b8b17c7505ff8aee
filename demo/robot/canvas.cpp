#include "robot/canvas.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace revolve::robot {

Canvas::Canvas(int width, int height)
    : width_(width), height_(height), rgb_(std::size_t(3) * width * height * kSupersample * kSupersample, 1.0f) {}

void Canvas::fillPolygon(std::span<const Pixel> points, const Rgba& colour) {
  if (points.size() < 3) return;
  const int w = width_ * kSupersample, h = height_ * kSupersample;
  double top = INFINITY, bottom = -INFINITY;
  for (const Pixel& p : points) top = std::min(top, p.y * kSupersample), bottom = std::max(bottom, p.y * kSupersample);
  const int firstRow = std::max(0, int(std::floor(top))), lastRow = std::min(h - 1, int(std::ceil(bottom)));
  std::vector<double> crossings;
  for (int row = firstRow; row <= lastRow; ++row) {
    const double y = row + 0.5;  // sample at the (supersampled) pixel's centre
    crossings.clear();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Pixel a{points[i].x * kSupersample, points[i].y * kSupersample};
      const Pixel b{points[(i + 1) % points.size()].x * kSupersample, points[(i + 1) % points.size()].y * kSupersample};
      if ((a.y <= y) != (b.y <= y)) crossings.push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
      const int from = std::max(0, int(std::ceil(crossings[i] - 0.5))), to = std::min(w - 1, int(std::floor(crossings[i + 1] - 0.5)));
      for (int x = from; x <= to; ++x) {
        float* p = rgb_.data() + 3 * (std::size_t(row) * w + x);
        for (int c = 0; c < 3; ++c) p[c] = colour[3] * colour[c] + (1 - colour[3]) * p[c];
      }
    }
  }
}

void Canvas::line(Pixel a, Pixel b, double thickness, const Rgba& colour) {
  const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
  if (!(length > 0)) return;
  const double nx = -dy / length * 0.5 * thickness, ny = dx / length * 0.5 * thickness;
  const Pixel quad[4] = {{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
  fillPolygon(quad, colour);
}

void Canvas::disc(Pixel centre, double radius, const Rgba& colour) {
  std::array<Pixel, 48> points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double a = 2 * std::numbers::pi * double(i) / double(points.size());
    points[i] = {centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
  }
  fillPolygon(points, colour);
}

void Canvas::circle(Pixel centre, double radius, double thickness, const Rgba& colour) {
  // A ring as one even-odd polygon (outer loop, then inner loop), so segments do not overlap.
  constexpr int kSides = 96;
  std::vector<Pixel> ring;
  for (const double r : {radius + 0.5 * thickness, std::max(radius - 0.5 * thickness, 0.0)}) {
    for (int i = 0; i <= kSides; ++i) {
      const double a = 2 * std::numbers::pi * i / kSides;
      ring.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
    }
  }
  fillPolygon(ring, colour);
}

void Canvas::text(Pixel at, std::string_view text, double size, const Rgba& colour, TextAlign align) {
  labels_.push_back({at, std::string(text), size, colour, align});
}

void Canvas::writePng(const std::string& path) const {
  const int w = width_ * kSupersample, h = height_ * kSupersample;
  OIIO::ImageBuf big(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
  big.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb_.data());
  for (const Label& label : labels_) {
    const auto alignX = label.align == TextAlign::left    ? OIIO::ImageBufAlgo::TextAlignX::Left
                        : label.align == TextAlign::centre ? OIIO::ImageBufAlgo::TextAlignX::Center
                                                           : OIIO::ImageBufAlgo::TextAlignX::Right;
    const float colour[3] = {label.colour[0], label.colour[1], label.colour[2]};
    if (!OIIO::ImageBufAlgo::render_text(big, int(label.at.x * kSupersample), int(label.at.y * kSupersample), label.text,
                                         int(label.size * kSupersample), "DejaVuSans", colour, alignX)) {
      throw std::runtime_error(path + ": cannot draw text (is the DejaVu Sans font installed? Debian: fonts-dejavu-core): " +
                               big.geterror());
    }
  }
  // A box filter of the supersample's size: each output pixel averages its 2 x 2 samples.
  const OIIO::ImageBuf small = OIIO::ImageBufAlgo::resize(big, "box", float(kSupersample), OIIO::ROI(0, width_, 0, height_, 0, 1, 0, 3));
  if (small.has_error()) throw std::runtime_error(path + ": cannot filter the plot: " + small.geterror());

  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::string temporary = ((folder.empty() ? std::filesystem::path(".") : folder) / ".revolve-plot-XXXXXX").string();
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) throw std::runtime_error(path + ": cannot create a file beside it: " + std::strerror(errno));
  close(descriptor);
  if (!small.write(temporary, OIIO::TypeDesc::UINT8, "png")) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": write failed: " + small.geterror());
  }
  const mode_t mask = umask(0);
  umask(mask);
  chmod(temporary.c_str(), 0666 & ~mask);  // mkstemp made it private; give it a plain file's mode
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot replace: " + std::strerror(error));
  }
}

}  // namespace revolve::robot
