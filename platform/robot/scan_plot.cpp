#include "robot/scan_plot.h"

#include "geometry/placement.h"
#include "io/temporary_files.h"
#include "io/text_files.h"
#include "robot/placed_shape.h"
#include "robot/sensor_rig.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

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

// What the plot shows of the scene, projected onto the ground plane, as the plotter reads it:
// `surfaces` (non-vertical quads, lowest first, so higher ones are drawn on top), `walls`
// (vertical quads seen edge-on, as their widest pair of corners), `objects` (each object of
// revolution's outline from above) and `sections` (upright objects cut at the sensor's height).
nlohmann::json footprintOf(const io::SceneDescription& scene, double sensorHeight) {
  struct Surface {
    std::vector<Point> outline;
    double top;
  };
  std::vector<Surface> surfaces;
  nlohmann::json walls = nlohmann::json::array(), objects = nlohmann::json::array(), sections = nlohmann::json::array();
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
          if (d > widest)
            widest = d,
            ends = {Point{quad.corners[i][0], quad.corners[i][1]}, Point{quad.corners[j][0], quad.corners[j][1]}};
        }
      }
      walls.push_back(ends);
      continue;
    }
    Surface surface{{}, -INFINITY};
    for (const auto& c : quad.corners)
      surface.outline.push_back({c[0], c[1]}), surface.top = std::max(surface.top, c[2]);
    surfaces.push_back(surface);
  }
  std::stable_sort(surfaces.begin(), surfaces.end(), [](const Surface& a, const Surface& b) { return a.top < b.top; });

  for (const io::SceneObject& object : scene.objects) {
    const app::Matrix3d linear = app::linearPart(object.transform);
    const auto& t = object.transform.translate;
    std::vector<Point> samples;
    constexpr int kAzimuths = 96;  // outlines within 0.05% of a circle's radius
    for (const Point2 p : scene.profiles[object.profile].polyline().points()) {
      for (int k = 0; k < kAzimuths; ++k) {
        const double phi = 2 * std::numbers::pi * k / kAzimuths;
        const Vec3d w = linear.apply(Vec3d{p.r * std::cos(phi), p.r * std::sin(phi), p.z});
        samples.push_back({w[0] + t[0], w[1] + t[1]});
      }
    }
    objects.push_back(convexHull(samples));
    if (const std::optional<MeridianScale> upright = uprightScale(object.transform)) {
      const double z = (sensorHeight - t[2]) / upright->axial;  // the sensor's height in the profile's z
      const std::span<const Point2> points = scene.profiles[object.profile].polyline().points();
      for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const Point2 a = points[i], b = points[i + 1];
        if ((a.z <= z) == (b.z <= z) || a.z == b.z) continue;
        const double r = a.r + (z - a.z) / (b.z - a.z) * (b.r - a.r);
        if (r > 0) sections.push_back({{"centre", {t[0], t[1]}}, {"radius", r * upright->radial}});
      }
    }
  }
  nlohmann::json footprint{
      {"surfaces", nlohmann::json::array()}, {"walls", walls}, {"objects", objects}, {"sections", sections}};
  for (const Surface& surface : surfaces) footprint["surfaces"].push_back(surface.outline);
  return footprint;
}

// The plotter, copied beside the tools by the build (tools/lidar/revolve_lidar_plot.py).
std::filesystem::path plotterPath() {
  std::error_code code;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", code);
  if (code)
    throw std::runtime_error(std::string("cannot find this program's folder to run revolve-lidar-plot: ") +
                             code.message());
  return self.parent_path() / "revolve-lidar-plot";
}

// The last non-empty line of a file (what a failing Python program says last).
std::string lastLine(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

// Runs the plotter on the data file `input`, its PNG on standard output going to `png`.
void runPlotter(const std::string& input, std::FILE* png, const std::string& output) {
  const io::ScratchFile messages(".log");
  if (std::fflush(png) != 0) throw std::runtime_error(output + ": write failed: " + std::strerror(errno));
  const std::string plotter = plotterPath().string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fileno(png), STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, messages.path().c_str(), O_WRONLY | O_TRUNC, 0);
  std::string dash = "-";
  std::string inputPath = input;
  std::string program = plotter;
  char* argv[] = {program.data(), inputPath.data(), dash.data(), nullptr};
  pid_t child = 0;
  const int spawned = posix_spawn(&child, plotter.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(output + ": cannot run " + plotter + ": " + std::strerror(spawned));
  const io::ChildRegistration terminateOnSignal(child);
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(output + ": cannot wait for " + plotter + ": " + std::strerror(errno));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string said = lastLine(messages.path());
    throw std::runtime_error(output + ": revolve-lidar-plot failed" + (said.empty() ? std::string() : ": " + said));
  }
}

}  // namespace

void checkPlotPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".png")
    throw std::runtime_error(path + ": unsupported plot extension \"" + extension + "\"; the plot is a .png");
  const std::filesystem::path plotter = plotterPath();
  if (access(plotter.c_str(), X_OK) != 0) {
    throw std::runtime_error(path + ": cannot plot: the plotter " + plotter.string() + " is missing or not executable");
  }
}

struct ScanPlot::Data {
  const io::SensorDescription& sensor;
  std::span<const io::RobotPose> poses;
  const io::ScanLayout& layout;
  io::ScratchFile file{".json"};
  std::FILE* out = nullptr;
  std::int64_t pose = -1;  // the pose whose returns are being written
  bool firstReturn = true;
  std::optional<std::size_t> ring;  // only this ring's returns

  Data(const io::SensorDescription& s, std::span<const io::RobotPose> p, const io::ScanLayout& l)
      : sensor(s), poses(p), layout(l) {}
  ~Data() {
    if (out != nullptr) std::fclose(out);
  }
  void check() const {
    if (std::ferror(out))
      throw std::runtime_error(file.path() + ": cannot write the plot's data: " + std::strerror(errno));
  }
  // Closes the returns of the pose before and opens pose `next`'s entry.
  void startPose(std::size_t next) {
    if (pose >= 0) std::fputs("]},\n", out);
    const SensorFrame frame = sensorFrame(sensor.pose, poses[next]);
    const Vec3d heading = frame.rotate({1, 0, 0});
    const double h = std::hypot(heading[0], heading[1]);  // zero for a sensor looking straight up or down
    std::fprintf(out, "{\"origin\": [%.17g, %.17g], \"heading\": [%.17g, %.17g], \"returns\": [", frame.origin[0],
                 frame.origin[1], h > 0 ? heading[0] / h : 0.0, h > 0 ? heading[1] / h : 0.0);
    pose = std::int64_t(next);
    firstReturn = true;
  }
};

ScanPlot::ScanPlot(const io::SceneDescription& scene, const io::SensorDescription& sensor,
                   std::span<const io::RobotPose> poses, const io::ScanLayout& layout, std::optional<std::size_t> ring)
    : data_(std::make_unique<Data>(sensor, poses, layout)) {
  data_->ring = ring;
  data_->out = std::fopen(data_->file.path().c_str(), "w");
  if (data_->out == nullptr)
    throw std::runtime_error(data_->file.path() + ": cannot write the plot's data: " + std::strerror(errno));
  const double sensorHeight = poses.empty() ? 0.0 : sensorFrame(sensor.pose, poses.front()).origin[2];
  nlohmann::json header = footprintOf(scene, sensorHeight);
  std::ostringstream title;
  title << scene.file << ": ";
  if (ring) title << "ring " << *ring << " of ";
  if (layout.pattern)
    title << "a pattern of " << layout.columns();
  else
    title << layout.rings() << " x " << layout.columns();
  title << " beams from " << layout.poses << (layout.poses == 1 ? " pose" : " poses")
        << ", sensor at z = " << sensorHeight << " m";
  header["title"] = title.str();
  std::string text = header.dump();
  text.pop_back();  // the closing brace: the poses follow, as they are traced
  std::fputs(text.c_str(), data_->out);
  std::fputs(", \"poses\": [\n", data_->out);
  data_->check();
}

ScanPlot::~ScanPlot() = default;

void ScanPlot::add(std::uint64_t first, std::span<const io::BeamReturn> beams) {
  Data& d = *data_;
  for (std::size_t i = 0; i < beams.size(); ++i) {
    const io::ScanLayout::Place at = d.layout.place(first + i);
    while (d.pose < std::int64_t(at.pose)) d.startPose(std::size_t(d.pose + 1));
    const io::BeamReturn& b = beams[i];
    if (std::isinf(b.range) || (d.ring && at.ring != *d.ring)) continue;
    std::fprintf(d.out, d.firstReturn ? "[%.9g, %.9g, %.9g]" : ", [%.9g, %.9g, %.9g]", b.x, b.y, b.intensity);
    d.firstReturn = false;
  }
  d.check();
}

void ScanPlot::finish(io::OutputStream& png, const std::string& path) {
  Data& d = *data_;
  while (d.pose + 1 < std::int64_t(d.poses.size())) d.startPose(std::size_t(d.pose + 1));
  std::fputs(d.pose >= 0 ? "]}]}\n" : "]}\n", d.out);
  const bool closed = std::fclose(d.out) == 0;
  d.out = nullptr;
  if (!closed) throw std::runtime_error(d.file.path() + ": cannot write the plot's data: " + std::strerror(errno));
  runPlotter(d.file.path(), png.file(), path);
}

}  // namespace revolve::robot
