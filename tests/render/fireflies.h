// Fireflies as the issue tracker and users count them: on the linear image, a pixel whose
// luminance (the mean of R, G, B) is above 0.8 and above twice the median of its 8 neighbours plus
// 0.05. Border pixels see the image extended by copies of its edge. The median of 8 values is the
// mean of the 4th and 5th.
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

namespace revolve::testing {

struct Pixel {
  int x, y;
};

// `luminance(x, y)` for 0 <= x < width, 0 <= y < height.
inline bool isFirefly(const std::function<float(int, int)>& luminance, int width, int height, int x, int y) {
  const float value = luminance(x, y);
  if (!(value > 0.8f)) return false;
  std::array<float, 8> neighbours{};
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      neighbours[n++] = luminance(std::clamp(x + dx, 0, width - 1), std::clamp(y + dy, 0, height - 1));
    }
  }
  std::sort(neighbours.begin(), neighbours.end());
  const float median = 0.5f * (neighbours[3] + neighbours[4]);
  return value > 2 * median + 0.05f;
}

// Every firefly of an RGB image (row 0 at the top), in row order.
inline std::vector<Pixel> fireflies(const std::vector<float>& rgb, int width, int height) {
  const auto luminance = [&](int x, int y) {
    const float* p = rgb.data() + 3 * (std::size_t(y) * width + x);
    return (p[0] + p[1] + p[2]) / 3;
  };
  std::vector<Pixel> found;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (isFirefly(luminance, width, height, x, y)) found.push_back({x, y});
    }
  }
  return found;
}

}  // namespace revolve::testing
