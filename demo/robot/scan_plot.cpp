#include "robot/scan_plot.h"

#include "robot/canvas.h"
#include "robot/placed_shape.h"
#include "robot/sensor_rig.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <unistd.h>

namespace revolve::robot {
namespace {

using Point = std::array<double, 2>;

// Andrew's monotone chain: the convex hull, counter-clockwise.
std::vector<Point> convexHull(std::vector<Point> points) {
  std::sort(points.begin(), points.end());
  if (points.size() < 3) return points;
  const auto turn = [](const Point& o, const Point& a, const Point& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// What the plot shows of the scene, in world x, y.
struct Footprint {
  struct Surface {
    std::vector<Point> outline;
    double top;  // drawn in order of height, highest last
  };
  std::vector<Surface> surfaces;             // non-vertical quads
  std::vector<std::array<Point, 2>> walls;   // vertical quads, seen edge-on
  std::vector<std::vector<Point>> objects;   // objects of revolution from above
  struct Section {
    Point centre;
    double radius;
  };
  std::vector<Section> sections;  // upright objects cut at the sensor's height
};

Footprint footprintOf(const io::SceneDescription& scene, double sensorHeight) {
  Footprint footprint;
  for (const io::SceneQuad& quad : scene.quads) {
    // Newell's normal: a quad whose horizontal projection is under 1/1000 of its area is drawn as
    // a wall (a line) rather than as a sliver a pixel wide.
    double n[3] = {0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      const auto& a = quad.corners[i];
      const auto& b = quad.corners[(i + 1) % 4];
      n[0] += (a[1] - b[1]) * (a[2] + b[2]);
      n[1] += (a[2] - b[2]) * (a[0] + b[0]);
      n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    if (std::abs(n[2]) < 1e-3 * std::hypot(n[0], n[1], n[2])) {
      std::array<Point, 2> ends{};
      double widest = -1;
      for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
          const double d = std::hypot(quad.corners[i][0] - quad.corners[j][0], quad.corners[i][1] - quad.corners[j][1]);
          if (d > widest) widest = d, ends = {Point{quad.corners[i][0], quad.corners[i][1]}, Point{quad.corners[j][0], quad.corners[j][1]}};
        }
      }
      footprint.walls.push_back(ends);
      continue;
    }
    Footprint::Surface surface{{}, -INFINITY};
    for (const auto& c : quad.corners) surface.outline.push_back({c[0], c[1]}), surface.top = std::max(surface.top, c[2]);
    footprint.surfaces.push_back(surface);
  }
  std::sort(footprint.surfaces.begin(), footprint.surfaces.end(), [](const auto& a, const auto& b) { return a.top < b.top; });

  for (const io::SceneObject& object : scene.objects) {
    const Matrix3 linear = linearPart(object.transform);
    const auto& t = object.transform.translate;
    std::vector<Point> samples;
    constexpr int kAzimuths = 96;  // outlines within 0.05% of a circle's radius
    for (const Point2 p : scene.profiles[object.profile].profile.points()) {
      for (int k = 0; k < kAzimuths; ++k) {
        const double phi = 2 * std::numbers::pi * k / kAzimuths;
        const Vec3d w = mapVector(linear, {p.r * std::cos(phi), p.r * std::sin(phi), p.z});
        samples.push_back({w[0] + t[0], w[1] + t[1]});
      }
    }
    footprint.objects.push_back(convexHull(samples));
    if (const std::optional<MeridianScale> upright = uprightScale(object.transform)) {
      const double z = (sensorHeight - t[2]) / upright->axial;  // the sensor's height in the profile's z
      const std::span<const Point2> points = scene.profiles[object.profile].profile.points();
      for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Point2 a = points[i], b = points[i + 1];
        if ((a.z <= z) == (b.z <= z) || a.z == b.z) continue;
        const double r = a.r + (z - a.z) / (b.z - a.z) * (b.r - a.r);
        if (r > 0) footprint.sections.push_back({{t[0], t[1]}, r * upright->radial});
      }
    }
  }
  return footprint;
}

// A round step near range / 8: 1, 2 or 5 times a power of ten.
double tickStep(double range) {
  const double raw = range / 8, power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) return m * power;
  }
  return 10 * power;
}

std::string tickLabel(double value, double step) {
  char text[32];
  const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value) < 0.5 * step ? 0.0 : value);
  return text;
}

const Rgba kInk{0.1f, 0.1f, 0.1f, 1}, kGrid{0.86f, 0.86f, 0.86f, 1}, kSurface{0.93f, 0.9f, 0.83f, 1};
const Rgba kWall{0.3f, 0.3f, 0.32f, 1}, kObject{0.76f, 0.83f, 0.93f, 1}, kObjectEdge{0.45f, 0.55f, 0.72f, 1};
const Rgba kSection{0.1f, 0.2f, 0.55f, 1}, kBeam{0.95f, 0.35f, 0.2f, 0.1f}, kReturn{0.8f, 0.05f, 0.05f, 1};
const Rgba kSensor{0.05f, 0.55f, 0.15f, 1};

}  // namespace

void checkPlotPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".png") throw std::runtime_error(path + ": unsupported plot extension \"" + extension + "\"; the plot is a .png");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code code;
  if (std::filesystem::is_directory(path, code)) throw std::runtime_error(path + ": is a directory, not a plot file");
  const std::string where = folder.empty() ? "." : folder.string();
  if (access(where.c_str(), W_OK) != 0) throw std::runtime_error(path + ": cannot create a file in " + where);
}

void writeScanPlot(const std::string& path, const ScanPlotInput& input) {
  std::vector<SensorFrame> frames;
  for (const io::RobotPose& pose : input.poses) frames.push_back(sensorFrame(input.sensor.pose, pose));
  const double sensorHeight = frames.empty() ? 0.0 : frames.front().origin[2];
  const Footprint footprint = footprintOf(input.scene, sensorHeight);

  // The extent of everything drawn, padded by 4%.
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  const auto include = [&](double x, double y) { x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y); };
  for (const auto& s : footprint.surfaces) for (const Point& p : s.outline) include(p[0], p[1]);
  for (const auto& w : footprint.walls) include(w[0][0], w[0][1]), include(w[1][0], w[1][1]);
  for (const auto& o : footprint.objects) for (const Point& p : o) include(p[0], p[1]);
  for (const SensorFrame& f : frames) include(f.origin[0], f.origin[1]);
  for (const io::BeamReturn& b : input.scan.beams) {
    if (!std::isinf(b.range)) include(b.x, b.y);
  }
  if (!(x1 > x0)) x0 -= 1, x1 += 1;
  if (!(y1 > y0)) y0 -= 1, y1 += 1;
  const double padX = 0.04 * (x1 - x0), padY = 0.04 * (y1 - y0);
  x0 -= padX, x1 += padX, y0 -= padY, y1 += padY;

  // Equal scales on both axes, the plot at most 1100 x 700 pixels, with margins for the labels.
  const double scale = std::min(1100 / (x1 - x0), 700 / (y1 - y0));
  const double left = 80, right = 30, top = 78, bottom = 62;
  const double plotW = scale * (x1 - x0), plotH = scale * (y1 - y0);
  Canvas canvas(int(std::ceil(left + plotW + right)), int(std::ceil(top + plotH + bottom)));
  const auto at = [&](double x, double y) { return Pixel{left + (x - x0) * scale, top + (y1 - y) * scale}; };
  const auto polygon = [&](const std::vector<Point>& points) {
    std::vector<Pixel> out;
    for (const Point& p : points) out.push_back(at(p[0], p[1]));
    return out;
  };

  // Grid and ticks.
  const double step = tickStep(std::max(x1 - x0, y1 - y0));
  for (double x = std::ceil(x0 / step) * step; x <= x1; x += step) {
    canvas.line(at(x, y0), at(x, y1), 1, kGrid);
    canvas.text({at(x, y0).x, top + plotH + 20}, tickLabel(x, step), 13, kInk, TextAlign::centre);
  }
  for (double y = std::ceil(y0 / step) * step; y <= y1; y += step) {
    canvas.line(at(x0, y), at(x1, y), 1, kGrid);
    canvas.text({left - 8, at(x0, y).y + 5}, tickLabel(y, step), 13, kInk, TextAlign::right);
  }

  // The scene.
  for (const auto& s : footprint.surfaces) canvas.fillPolygon(polygon(s.outline), kSurface);
  for (const auto& o : footprint.objects) {
    const std::vector<Pixel> outline = polygon(o);
    canvas.fillPolygon(outline, kObject);
    for (std::size_t i = 0; i < outline.size(); ++i) canvas.line(outline[i], outline[(i + 1) % outline.size()], 1.2, kObjectEdge);
  }
  for (const auto& s : footprint.sections) canvas.circle(at(s.centre[0], s.centre[1]), s.radius * scale, 2, kSection);
  for (const auto& w : footprint.walls) canvas.line(at(w[0][0], w[0][1]), at(w[1][0], w[1][1]), 4, kWall);

  // The scan.
  for (std::size_t pose = 0; pose < input.scan.poses; ++pose) {
    const Pixel origin = at(frames[pose].origin[0], frames[pose].origin[1]);
    for (std::size_t i = 0; i < input.scan.rings() * input.scan.azimuths.size(); ++i) {
      const io::BeamReturn& b = input.scan.beams[pose * input.scan.rings() * input.scan.azimuths.size() + i];
      if (!std::isinf(b.range)) canvas.line(origin, at(b.x, b.y), 1, kBeam);
    }
  }
  for (const io::BeamReturn& b : input.scan.beams) {
    if (!std::isinf(b.range)) canvas.disc(at(b.x, b.y), 1.8, kReturn);
  }
  for (const SensorFrame& f : frames) {
    const Vec3d heading = f.rotate({1, 0, 0});
    const Pixel o = at(f.origin[0], f.origin[1]);
    const double h = std::hypot(heading[0], heading[1]);
    // White under the marker, so that it stands out of the beams' fan.
    if (h > 0) {
      canvas.line(o, {o.x + 28 * heading[0] / h, o.y - 28 * heading[1] / h}, 6, {1, 1, 1, 1});
      canvas.line(o, {o.x + 26 * heading[0] / h, o.y - 26 * heading[1] / h}, 3, kSensor);
    }
    canvas.disc(o, 8.5, {1, 1, 1, 1});
    canvas.disc(o, 6.5, kSensor);
  }

  // Frame, axis labels, title and legend.
  const Pixel corners[4] = {at(x0, y1), at(x1, y1), at(x1, y0), at(x0, y0)};
  for (int i = 0; i < 4; ++i) canvas.line(corners[i], corners[(i + 1) % 4], 1.5, kInk);
  canvas.text({left + plotW / 2, top + plotH + 48}, "x [m]", 15, kInk, TextAlign::centre);
  canvas.text({14, top + plotH / 2}, "y [m]", 15, kInk, TextAlign::left);
  char title[256];
  std::snprintf(title, sizeof title, "%s: %zu x %zu beams from %zu pose%s, sensor at z = %.3g m", input.scene.file.c_str(),
                input.scan.rings(), input.scan.azimuths.size(), input.scan.poses, input.scan.poses == 1 ? "" : "s", sensorHeight);
  canvas.text({left, 24}, title, 16, kInk);
  double x = left;
  const auto legend = [&](const Rgba& colour, const char* label, int kind) {
    const double y = 52;
    if (kind == 0) canvas.fillPolygon(std::vector<Pixel>{{x, y - 10}, {x + 18, y - 10}, {x + 18, y + 2}, {x, y + 2}}, colour);
    if (kind == 1) canvas.line({x, y - 4}, {x + 18, y - 4}, 4, colour);
    if (kind == 2) canvas.disc({x + 9, y - 4}, 4, colour);
    if (kind == 3) canvas.circle({x + 9, y - 4}, 6, 2, colour);
    canvas.text({x + 24, y + 1}, label, 13, kInk);
    x += 24 + 8.2 * std::char_traits<char>::length(label) + 22;
  };
  legend(kSurface, "floor", 0);
  legend(kWall, "wall", 1);
  legend(kObject, "object (top view)", 0);
  legend(kSection, "section at sensor height", 3);
  legend({kBeam[0], kBeam[1], kBeam[2], 0.5f}, "beam", 1);
  legend(kReturn, "return", 2);
  legend(kSensor, "sensor", 2);
  canvas.writePng(path);
}

}  // namespace revolve::robot
