// A small raster for plots: filled polygons, lines and discs composited "over" a white page,
// drawn at twice the resolution and filtered down (antialiasing), with text by OpenImageIO (the
// DejaVu Sans font, Debian's fonts-dejavu-core), written as an 8-bit PNG through a temporary file
// renamed into place. Coordinates are output pixels, (0, 0) the top left corner.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::robot {

struct Pixel {
  double x, y;
};
using Rgba = std::array<float, 4>;  // display (sRGB) values in [0, 1] and opacity

enum class TextAlign { left, centre, right };

class Canvas {
 public:
  Canvas(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Even-odd fill of a polygon.
  void fillPolygon(std::span<const Pixel> points, const Rgba& colour);
  void line(Pixel a, Pixel b, double thickness, const Rgba& colour);
  void disc(Pixel centre, double radius, const Rgba& colour);
  void circle(Pixel centre, double radius, double thickness, const Rgba& colour);
  // `at` is the baseline's left end, middle or right end.
  void text(Pixel at, std::string_view text, double size, const Rgba& colour, TextAlign align = TextAlign::left);

  // Throws std::runtime_error naming the file on failure; an existing file is then untouched.
  void writePng(const std::string& path) const;

 private:
  static constexpr int kSupersample = 2;
  struct Label {
    Pixel at;
    std::string text;
    double size;
    Rgba colour;
    TextAlign align;
  };
  int width_, height_;
  std::vector<float> rgb_;  // supersampled, row 0 at the top
  std::vector<Label> labels_;
};

}  // namespace revolve::robot
