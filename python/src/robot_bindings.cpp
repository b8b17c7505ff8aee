// The robot tools' code for Python: a scene file built as the tools build it (Scene), the laser
// range-finder of revolve-lidar (Lidar) and its scan files (ScanFile), and revolve-clearance's
// cylinder clearance. The same library code the tools run (platform/robot, platform/io, platform/scene), so
// that the answers are theirs bit for bit.
#include "arguments.h"
#include "bindings.h"
#include "numpy_inputs.h"

#include "geometry/ray_limits.h"
#include "io/input_file.h"
#include "io/output_set.h"
#include "io/poses_file.h"
#include "io/scan_files.h"
#include "io/scene_file.h"
#include "io/sensor_file.h"
#include "io/temporary_files.h"
#include "robot/clearance_map.h"
#include "robot/lidar.h"
#include "robot/range_sensors.h"
#include "scene/degenerate_objects.h"
#include "scene/embree_scene.h"
#include "threads/thread_arenas.h"

#include <pybind11/stl.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace revolve::python {
namespace {

// The build settings, checked before a scene file is read.
void checkSettings(const std::string& geometry, std::uint32_t slices) {
  if (geometry != "mibit" && geometry != "mesh") {
    throw py::value_error("geometry = \"" + geometry +
                          "\": expected \"mibit\" (exact) or \"mesh\" (tessellated, as --geometry mesh)");
  }
  if (slices < 3 || slices > (1u << 16))
    throw py::value_error("slices = " + std::to_string(slices) + ": must lie in [3, 65536]");
}

// A scene file as revolve-lidar (--geometry mibit or mesh) and revolve-clearance build it.
struct ToolScene {
  std::string path;
  std::string geometry;
  std::uint32_t slices;
  // What built it, as a pickle keeps it: the scene file's text and every profile CSV's, by its path
  // as opened.
  std::string text;
  io::FileTexts csvs;
  io::SceneDescription description;
  std::unique_ptr<scene::EmbreeScene> built;
  std::mutex clearanceMutex;
  std::map<double, std::unique_ptr<robot::ClearanceMap>> clearanceMaps;  // by ground height

  robot::RangeSensors::Settings rangeSettings;  // the same geometry for range sensors' cones

  ToolScene(const std::string& file, const std::string& geometryName, std::uint32_t sliceCount)
      : path(file),
        geometry(geometryName),
        slices(sliceCount),
        description((checkSettings(geometryName, sliceCount), io::readScene(file, text, csvs))) {
    build();
  }

  // From the texts a pickle keeps, reading no file; messages name the files as the original did.
  ToolScene(const std::string& file, const std::string& geometryName, std::uint32_t sliceCount, std::string sceneText,
            io::FileTexts texts)
      : path(file),
        geometry(geometryName),
        slices(sliceCount),
        text(std::move(sceneText)),
        csvs(std::move(texts)),
        description((checkSettings(geometryName, sliceCount), csvs.readFiles = false,
                     io::parseScene(text, file, std::filesystem::path(file).parent_path().string(), csvs))) {
    build();
  }

  void build() {
    rangeSettings.mesh = geometry == "mesh";
    rangeSettings.slices = slices;
    for (const io::SceneProfile& profile : description.profiles) warnAbout(profile.warnings);
    warnAbout(scene::degenerateObjectWarnings(description, false));
    scene::BuildSettings settings;
    settings.mesh = geometry == "mesh";
    settings.slices = slices;
    built = std::make_unique<scene::EmbreeScene>(description, settings);
  }

  const robot::ClearanceMap& clearanceMap(double ground) {
    std::lock_guard lock(clearanceMutex);
    std::unique_ptr<robot::ClearanceMap>& map = clearanceMaps[ground];
    if (!map) map = std::make_unique<robot::ClearanceMap>(description, ground);
    return *map;
  }
};

std::shared_ptr<ToolScene> sceneOf(py::handle scene) {
  if (py::isinstance<ToolScene>(scene)) return scene.cast<std::shared_ptr<ToolScene>>();
  return std::make_shared<ToolScene>(pathArgument(scene, "scene"), "mibit", 64);
}

// Poses from a POSES.csv path (the tools' reader) or an (N, 3) [x, y, yaw], (N, 4) [x, y, z, yaw] or
// (N, 5) [x, y, z, yaw, time] array, checked by the reader's rules.
// The layouts of a poses array, by its number of columns (docs/python.md).
constexpr const char* kPoseLayouts =
    "(N, 3) [x, y, yaw], (N, 4) [x, y, z, yaw], (N, 5) [x, y, z, yaw, time], (N, 6) [x, y, z, roll, pitch, yaw] or "
    "(N, 7) [x, y, z, roll, pitch, yaw, time]";

std::vector<io::RobotPose> posesOf(py::handle poses) {
  if (py::isinstance<py::str>(poses) || py::isinstance<py::bytes>(poses) || py::hasattr(poses, "__fspath__")) {
    return io::readPosesCsv(pathArgument(poses, "poses"));
  }
  const py::array array = arrayArgument(poses, "poses", "an (N, 3) to (N, 7) array of poses, or a POSES.csv path");
  const py::ssize_t columns = array.ndim() == 2 ? array.shape(1) : 0;
  if (columns < 3 || columns > 7) {
    throw py::value_error("poses: shape " + shapeText(array) + "; expected " + kPoseLayouts + ", or a POSES.csv path");
  }
  const py::array_t<double> values = copiedMatrix(array, "poses", -1, columns, 1);
  std::vector<io::RobotPose> result(std::size_t(values.shape(0)));
  const bool withZ = columns >= 4, tilted = columns >= 6, timed = columns == 5 || columns == 7;
  const py::ssize_t yawColumn = tilted ? 5 : withZ ? 3 : 2, timeColumn = columns - 1;
  const char* names[3] = {"x", "y", "z"};
  for (std::size_t i = 0; i < result.size(); ++i) {
    for (py::ssize_t c = 0; c < (withZ ? 3 : 2); ++c) {  // the positions; angles may be any finite value
      if (!(std::abs(values.at(i, c)) <= app::kMaxWorldCoordinate)) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", values.at(i, c));
        throw py::value_error("poses[" + std::to_string(i) + ", " + std::to_string(c) + "]: " + names[c] + " = " +
                              text + " is beyond the coordinate limit: " + app::kCoordinateLimitRule);
      }
    }
    io::RobotPose& p = result[i];
    p.x = values.at(i, 0), p.y = values.at(i, 1);
    p.z = withZ ? values.at(i, 2) : 0.0;
    p.yaw = values.at(i, yawColumn);
    if (tilted) p.roll = values.at(i, 3), p.pitch = values.at(i, 4);
    if (timed) {
      p.time = values.at(i, timeColumn);
      if (const char* problem = io::poseTimeProblem(p.time, i == 0 ? std::nan("") : result[i - 1].time)) {
        const std::string column = std::to_string(timeColumn);
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", p.time);
        std::string message = "poses[" + std::to_string(i) + ", " + column + "]: time = " + text + " " + problem;
        if (i > 0) {
          std::snprintf(text, sizeof text, "%.17g", result[i - 1].time);
          message += std::string(" (poses[") + std::to_string(i - 1) + ", " + column + "] = " + text + ")";
        }
        throw py::value_error(message);
      }
    }
  }
  return result;
}

// Poses as read_poses returns them: (N, 4) [x, y, z, yaw], with roll and pitch (N, 6) [x, y, z,
// roll, pitch, yaw] where any pose is tilted, and the time last where the poses carry one.
py::array_t<double> posesArray(const std::vector<io::RobotPose>& poses) {
  const bool timed = !poses.empty() && poses.front().timed();
  const bool tilted = std::any_of(poses.begin(), poses.end(), [](const io::RobotPose& p) { return !p.level(); });
  const py::ssize_t columns = (tilted ? 6 : 4) + (timed ? 1 : 0);
  py::array_t<double> array(std::vector<py::ssize_t>{py::ssize_t(poses.size()), columns});
  double* out = array.mutable_data();
  for (const io::RobotPose& p : poses) {
    *out++ = p.x, *out++ = p.y, *out++ = p.z;
    if (tilted) *out++ = p.roll, *out++ = p.pitch;
    *out++ = p.yaw;
    if (timed) *out++ = p.time;
  }
  return array;
}

struct PySensor {
  io::SensorDescription sensor;
  // What built it, as a pickle keeps it: the sensor's JSON text, the name it goes by in messages
  // (its path, or "sensor" for a dict) and its beam pattern's text, if any, by its path.
  std::string file, text;
  io::FileTexts patterns;
};

// A sensor dict as the sensor file's JSON text, value by value: numpy scalars and arrays stand for
// numbers and lists; a value JSON cannot hold (nan, inf, an object of another kind) is refused
// naming its key path, as the sensor file's reader names a bad value's.
void appendJson(std::string& out, py::handle value, const std::string& path) {
  const py::module_ numpy = py::module_::import("numpy");
  const auto where = [&] { return "sensor: " + (path.empty() ? std::string("the sensor") : path); };
  if (py::isinstance<py::array>(value)) return appendJson(out, value.attr("tolist")(), path);
  if (py::isinstance(value, numpy.attr("generic"))) return appendJson(out, value.attr("item")(), path);
  if (py::isinstance<py::dict>(value)) {
    out += '{';
    bool first = true;
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!py::isinstance<py::str>(key)) {
        throw py::type_error(where() + ": a key " + std::string(py::repr(key)) + "; keys are str");
      }
      const std::string name = py::str(key);
      if (!first) out += ',';
      first = false;
      out += std::string(py::str(py::module_::import("json").attr("dumps")(key))) + ':';
      appendJson(out, item, path.empty() ? name : path + "." + name);
    }
    out += '}';
    return;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    out += '[';
    std::size_t i = 0;
    for (const py::handle item : value) {
      if (i > 0) out += ',';
      appendJson(out, item, path + "[" + std::to_string(i++) + "]");
    }
    out += ']';
    return;
  }
  if (value.is_none()) {
    out += "null";
  } else if (PyBool_Check(value.ptr())) {
    out += value.ptr() == Py_True ? "true" : "false";
  } else if (PyLong_Check(value.ptr())) {
    out += std::string(py::str(value));
  } else if (PyFloat_Check(value.ptr())) {
    const double x = value.cast<double>();
    if (!std::isfinite(x)) throw py::value_error(where() + " = " + std::string(py::repr(value)) + ": not finite");
    out += std::string(py::repr(value));
  } else if (py::isinstance<py::str>(value)) {
    out += std::string(py::str(py::module_::import("json").attr("dumps")(value)));
  } else {
    throw py::type_error(where() + ": a " + std::string(py::str(py::type::handle_of(value).attr("__name__"))) +
                         "; a sensor holds numbers, strings, lists and dicts");
  }
}

PySensor sensorOf(py::handle sensor) {
  PySensor made;
  if (py::isinstance<py::dict>(sensor)) {
    appendJson(made.text, sensor, "");
    made.file = "sensor";
    made.sensor = io::parseSensor(made.text, made.file, made.patterns);
    return made;
  }
  if (!py::isinstance<py::str>(sensor) && !py::isinstance<py::bytes>(sensor) && !py::hasattr(sensor, "__fspath__")) {
    throw py::type_error("sensor: a " + std::string(py::str(py::type::handle_of(sensor).attr("__name__"))) +
                         "; expected a sensor file's path or its JSON as a dict");
  }
  made.file = pathArgument(sensor, "sensor");
  made.sensor = io::readSensor(made.file, made.text, made.patterns);
  return made;
}

// A Lidar from what a pickle keeps, reading no file.
PySensor sensorFromTexts(const std::string& file, const std::string& text, io::FileTexts patterns) {
  PySensor made{{}, file, text, std::move(patterns)};
  made.patterns.readFiles = false;
  made.sensor = io::parseSensor(made.text, made.file, made.patterns);
  return made;
}

struct PyRangeSensors {
  io::RangeSensorsDescription sensors;
  std::string file, text;  // what built it, as a pickle keeps it (as PySensor's)
};

PyRangeSensors rangeSensorsOf(py::handle sensor) {
  PyRangeSensors made;
  if (py::isinstance<py::dict>(sensor)) {
    appendJson(made.text, sensor, "");
    made.file = "sensor";
    made.sensors = io::parseRangeSensors(made.text, made.file);
    return made;
  }
  if (!py::isinstance<py::str>(sensor) && !py::isinstance<py::bytes>(sensor) && !py::hasattr(sensor, "__fspath__")) {
    throw py::type_error("sensor: a " + std::string(py::str(py::type::handle_of(sensor).attr("__name__"))) +
                         "; expected a range sensor file's path or its JSON as a dict");
  }
  made.file = pathArgument(sensor, "sensor");
  try {
    made.text = io::readTextFile(made.file, io::kMaxJsonFileBytes, "a JSON file");
  } catch (const io::InputError& error) {  // as readRangeSensors says it
    throw io::SensorError(error.what());
  }
  made.sensors = io::parseRangeSensors(made.text, made.file);
  return made;
}

py::dict readRanges(const PyRangeSensors& self, py::handle sceneObject, py::handle posesObject,
                    py::handle threadsObject, py::handle firstPoseObject) {
  const int threads = threadsArgument(threadsObject, "threads", false);
  const std::uint64_t firstPose = unsignedArgument(firstPoseObject, "first_pose", 0, io::kMaxScanPoints);
  const std::vector<io::RobotPose> poses = posesOf(posesObject);
  const std::shared_ptr<ToolScene> scene = sceneOf(sceneObject);
  std::optional<robot::RangeSensors> ranging;
  try {
    ranging.emplace(scene->description, self.sensors, scene->rangeSettings);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(error.what());
  }
  const py::ssize_t n = py::ssize_t(poses.size()), count = py::ssize_t(self.sensors.sensors.size());
  py::array_t<double> range(std::vector<py::ssize_t>{n, count}), point(std::vector<py::ssize_t>{n, count, 3});
  py::array_t<std::int64_t> object(std::vector<py::ssize_t>{n, count});
  double* ranges = range.mutable_data();
  double* points = point.mutable_data();
  std::int64_t* objects = object.mutable_data();
  {
    py::gil_scoped_release release;
    ranging->readAll(
        poses, threads,
        [&](std::uint64_t first, std::span<const io::RangeReading> block) {
          const std::size_t at = std::size_t(first - firstPose) * std::size_t(count);
          for (std::size_t i = 0; i < block.size(); ++i) {
            ranges[at + i] = block[i].range;
            for (std::size_t k = 0; k < 3; ++k) points[3 * (at + i) + k] = block[i].point[k];
            objects[at + i] = block[i].object;
          }
        },
        firstPose);
  }
  py::dict result;
  result["range"] = range;
  result["point"] = point;
  result["object"] = object;
  return result;
}

// A scan's points in numpy arrays shaped (poses, rings, azimuths), or (poses, returns, rings,
// azimuths) for a sensor reporting several returns a beam (io::ScanLayout's point order), written
// block by block.
struct ScanArrays {
  py::array_t<float> ranges, points, intensity, time;
  py::array_t<std::int32_t> ids;
  py::array_t<std::uint16_t> rings;
  py::array_t<std::uint8_t> returns;
};

std::vector<py::ssize_t> scanShape(const io::ScanLayout& layout) {
  std::vector<py::ssize_t> shape{py::ssize_t(layout.poses)};
  if (layout.layers > 1) shape.push_back(py::ssize_t(layout.layers));
  shape.push_back(py::ssize_t(layout.rings()));
  shape.push_back(py::ssize_t(layout.columns()));
  return shape;
}

ScanArrays newScanArrays(const io::ScanLayout& layout) {
  const std::vector<py::ssize_t> shape = scanShape(layout);
  return {newArray<float>(shape),       newArray<float>(shape, 3),     newArray<float>(shape),
          newArray<float>(shape),       newArray<std::int32_t>(shape), newArray<std::uint16_t>(shape),
          newArray<std::uint8_t>(shape)};
}

py::dict scan(const PySensor& self, py::handle sceneObject, py::handle posesObject, py::handle threadsObject,
              py::handle firstPoseObject, py::handle sweepsObject) {
  const int threads = threadsArgument(threadsObject, "threads", false);
  // A scan holds fewer than 2^31 points: no pose number beyond that has a beam of its own.
  const std::uint64_t firstPose = unsignedArgument(firstPoseObject, "first_pose", 0, io::kMaxScanPoints);
  const std::vector<io::RobotPose> poses = posesOf(posesObject);
  const std::size_t sweeps =
      sweepsObject.is_none() ? poses.size() : std::size_t(unsignedArgument(sweepsObject, "sweeps", 0, poses.size()));
  const std::shared_ptr<ToolScene> scene = sceneOf(sceneObject);
  const robot::Lidar lidar(*scene->built, self.sensor);
  const io::ScanLayout layout = lidar.layout(sweeps);
  ScanArrays a = newScanArrays(layout);
  float* ranges = a.ranges.mutable_data();
  float* intensity = a.intensity.mutable_data();
  float* times = a.time.mutable_data();
  float* points = a.points.mutable_data();
  std::int32_t* ids = a.ids.mutable_data();
  std::uint16_t* ringOf = a.rings.mutable_data();
  std::uint8_t* returnOf = a.returns.mutable_data();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  {
    py::gil_scoped_release release;
    lidar.scan(
        poses,
        [&](std::uint64_t first, std::span<const io::BeamReturn> beams) {
          for (std::size_t i = 0; i < beams.size(); ++i) {
            const std::uint64_t b = first + i;
            const io::BeamReturn& beam = beams[i];
            const bool hit = !std::isinf(beam.range);
            ranges[b] = beam.range;
            points[3 * b] = hit ? beam.x : nan;
            points[3 * b + 1] = hit ? beam.y : nan;
            points[3 * b + 2] = hit ? beam.z : nan;
            ids[b] = beam.object;
            intensity[b] = hit ? beam.intensity : nan;
            times[b] = beam.time;
            const io::ScanLayout::Place at = layout.place(b);
            ringOf[b] = std::uint16_t(at.ring);
            returnOf[b] = std::uint8_t(at.layer);
          }
        },
        threads, nullptr, firstPose, sweeps);
  }
  py::dict result;
  result["points"] = a.points;
  result["ranges"] = a.ranges;
  result["rings"] = a.rings;
  result["ids"] = a.ids;
  result["intensity"] = a.intensity;
  result["time"] = a.time;
  result["return"] = a.returns;
  return result;
}

// One scan file written in pose order, shard by shard, through a temporary renamed into place on
// commit() (io/output_set.h): whole or absent.
struct ScanFile {
  io::OutputSet outputs;
  std::string path;
  io::ScanLayout layout;
  std::optional<io::ScanWriter> writer;
  std::uint64_t nextPose = 0;
  bool committed = false;

  ScanFile(const std::string& file, const PySensor& sensor, std::uint64_t poses, const std::string& data,
           const std::vector<std::string>& inputs)
      : path(file) {
    // SIGTERM or SIGHUP while it is written removes its temporary, as revolve-lidar's does
    // (SIGINT raises KeyboardInterrupt, whose unwinding removes it).
    io::removeTemporariesOnTermination();
    if (data != "ascii" && data != "binary")
      throw py::value_error("data = \"" + data + "\": expected \"ascii\" or \"binary\"");
    const io::ScanFormat format = io::scanFormatFor(path);
    if (data == "binary" && format != io::ScanFormat::pcd) {
      throw py::value_error(path + ": data=\"binary\" applies to .pcd outputs, and this one is a CSV table");
    }
    layout = io::scanLayout(sensor.sensor, std::size_t(poses));
    // Compared by division: poses x points would wrap a 64-bit count (2^54 poses of 1,024 is 0).
    if (poses == 0 || poses > io::kMaxScanPoints / layout.pointsPerPose()) {
      throw py::value_error("poses = " + std::to_string(poses) + " x " + std::to_string(layout.pointsPerPose()) +
                            " points: a scan holds 1 to 2^31 - 1 points (PCD's point count, as PCL indexes it)");
    }
    for (const std::string& input : inputs) outputs.addInput("an input", input);
    outputs.add("", path);
    writer.emplace(outputs.stream(path), format, data == "binary" ? io::PcdData::binary : io::PcdData::ascii, layout);
  }

  void write(py::handle firstPoseObject, py::handle scanObject) {
    if (committed) throw py::value_error(path + ": already committed");
    const std::uint64_t firstPose = unsignedArgument(firstPoseObject, "first_pose", 0, layout.poses);
    std::string shape;
    for (const py::ssize_t n : scanShape(layout)) shape += ", " + std::to_string(n);
    const std::string expected = "a scan dict of Lidar.scan for this sensor (ranges (P" +
                                 shape.substr(shape.find(',', 1)) + "), points, ids, intensity, time)";
    if (!py::isinstance<py::dict>(scanObject)) {
      throw py::type_error("scan: a " + std::string(py::str(py::type::handle_of(scanObject).attr("__name__"))) +
                           "; expected " + expected);
    }
    const py::dict scan = py::reinterpret_borrow<py::dict>(scanObject);
    for (const char* key : {"ranges", "points", "ids", "intensity", "time"}) {
      if (!scan.contains(key)) throw py::value_error(std::string("scan: no \"") + key + "\"; expected " + expected);
    }
    const auto array = [&](const char* key) {
      return arrayArgument(scan[key], (std::string("scan[\"") + key + "\"]").c_str(), expected);
    };
    if (firstPose != nextPose) {
      throw py::value_error(path + ": poses are written in order: expected pose " + std::to_string(nextPose) +
                            ", got first_pose = " + std::to_string(firstPose));
    }
    const auto converted = [&](auto type, const char* key) {
      try {
        return alignedArray<decltype(type)>(array(key));
      } catch (py::error_already_set& error) {  // values numpy cannot cast (strings, objects)
        // Anything else (a signal handler's SystemExit or KeyboardInterrupt raised meanwhile) goes on.
        if (!error.matches(PyExc_TypeError) && !error.matches(PyExc_ValueError)) throw;
        throw py::value_error(path + ": scan[\"" + key + "\"] holds no numbers; " + expected + " is expected");
      }
    };
    const py::array_t<float> ranges = converted(float{}, "ranges"), points = converted(float{}, "points"),
                             intensity = converted(float{}, "intensity"), times = converted(float{}, "time");
    const py::array_t<std::int32_t> ids = converted(std::int32_t{}, "ids");
    const std::size_t perPose = layout.pointsPerPose();
    const std::vector<py::ssize_t> want = scanShape(layout);
    bool shaped = ranges.ndim() == py::ssize_t(want.size());
    for (std::size_t d = 1; shaped && d < want.size(); ++d) shaped = ranges.shape(py::ssize_t(d)) == want[d];
    if (!shaped || points.size() != 3 * ranges.size() || ids.size() != ranges.size() ||
        intensity.size() != ranges.size() || times.size() != ranges.size()) {
      throw py::value_error(path + ": " + expected + " is expected");
    }
    const std::uint64_t poses = std::uint64_t(ranges.shape(0));
    if (firstPose + poses > layout.poses) {
      throw py::value_error(path + ": poses " + std::to_string(firstPose) + " to " +
                            std::to_string(firstPose + poses - 1) + " lie beyond the file's " +
                            std::to_string(layout.poses));
    }
    std::vector<io::BeamReturn> beams(std::size_t(ranges.size()));
    for (std::size_t b = 0; b < beams.size(); ++b) {
      beams[b] = {ranges.data()[b], points.data()[3 * b], points.data()[3 * b + 1], points.data()[3 * b + 2],
                  ids.data()[b],    intensity.data()[b],  times.data()[b]};
    }
    writer->write(firstPose * perPose, beams);
    nextPose += poses;
  }

  void commit() {
    if (committed) return;
    if (nextPose != layout.poses) {
      throw py::value_error(path + ": " + std::to_string(nextPose) + " of " + std::to_string(layout.poses) +
                            " poses written; a scan file is committed whole");
    }
    outputs.commit();
    committed = true;
  }
};

py::dict cylinderClearance(py::handle sceneObject, py::handle posesObject, py::handle radiusObject,
                           py::handle zMinObject, py::handle zMaxObject, py::handle groundObject,
                           py::handle threadsObject) {
  const double radius = realArgument(radiusObject, "radius");
  const double zMin = realArgument(zMinObject, "z_min"), zMax = realArgument(zMaxObject, "z_max");
  const std::optional<double> ground = optionalReal(groundObject, "ground");
  const int threads = threadsArgument(threadsObject, "threads", false);
  if (!(radius > 0 && std::isfinite(radius)))
    throw py::value_error("radius = " + std::to_string(radius) + ": must be positive and finite");
  if (!(std::isfinite(zMin) && std::isfinite(zMax) && zMin < zMax)) {
    throw py::value_error("z_min = " + std::to_string(zMin) + ", z_max = " + std::to_string(zMax) +
                          ": need finite z_min < z_max");
  }
  if (ground && !std::isfinite(*ground)) throw py::value_error("ground: must be a finite height (or None)");
  const std::vector<io::RobotPose> poses = posesOf(posesObject);
  try {
    robot::requireLevelPoses(poses, "poses: pose");
  } catch (const std::invalid_argument& error) {
    throw py::value_error(error.what());
  }
  const std::shared_ptr<ToolScene> scene = sceneOf(sceneObject);
  const robot::ClearanceMap& map = scene->clearanceMap(ground.value_or(-INFINITY));
  std::vector<robot::SceneClearance> results(poses.size());
  {
    py::gil_scoped_release release;
    app::threadArena(threads).execute([&] {
      tbb::parallel_for(std::size_t{0}, poses.size(), [&](std::size_t i) {
        const io::RobotPose& p = poses[i];
        results[i] = map.query({p.x, p.y, p.z + zMin, p.z + zMax, radius});
      });
    });
  }
  const py::ssize_t n = py::ssize_t(poses.size());
  py::array_t<double> clearance(n), point(std::vector<py::ssize_t>{n, 3});
  py::array_t<bool> collides(n), exact(n);
  py::array_t<std::int64_t> object(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const robot::SceneClearance& r = results[std::size_t(i)];
    clearance.mutable_at(i) = r.clearance;
    collides.mutable_at(i) = r.collides;
    object.mutable_at(i) = r.object;
    exact.mutable_at(i) = r.exact;
    for (int k = 0; k < 3; ++k)
      point.mutable_at(i, k) = r.object >= 0 ? r.point[k] : std::numeric_limits<double>::quiet_NaN();
  }
  py::dict result;
  result["clearance"] = clearance;
  result["collides"] = collides;
  result["object"] = object;
  result["point"] = point;
  result["exact"] = exact;
  return result;
}

}  // namespace

void bindRobot(py::module_& m) {
  py::class_<ToolScene, std::shared_ptr<ToolScene>>(
      m, "Scene", R"(A scene file (JSON, revolve-render's format) built as revolve-lidar and revolve-clearance build it.

geometry: "mibit" traces every surface of revolution exactly; "mesh" tessellates each into `slices`
azimuthal steps (revolve-lidar --geometry mesh --slices K).)")
      .def(py::init([](py::handle path, py::handle geometry, py::handle slices) {
             return std::make_shared<ToolScene>(pathArgument(path, "path"), textArgument(geometry, "geometry"),
                                                std::uint32_t(unsignedArgument(slices, "slices", 3, 1u << 16)));
           }),
           py::arg("path"), py::arg("geometry") = py::str("mibit"), py::arg("slices") = py::int_(64))
      .def(
          "_sources",
          [](const ToolScene& s) {
            py::dict csvs;
            for (const auto& [path, text] : s.csvs.texts) csvs[py::str(path)] = py::bytes(text);
            return py::make_tuple(s.path, py::bytes(s.text), csvs, s.geometry, s.slices);
          },
          "(path, scene text, {CSV path: text}, geometry, slices): what rebuilds the scene (what a pickle keeps)")
      .def_static(
          "_from_sources",
          [](const std::string& path, const py::bytes& text, const std::map<std::string, std::string>& csvs,
             const std::string& geometry, std::uint32_t slices) {
            return std::make_shared<ToolScene>(path, geometry, slices, std::string(text), io::FileTexts{csvs, false});
          },
          py::arg("path"), py::arg("text"), py::arg("csvs"), py::arg("geometry"), py::arg("slices"))
      .def_property_readonly("path", [](const ToolScene& s) { return s.path; })
      .def_property_readonly("object_count", [](const ToolScene& s) { return s.description.objects.size(); })
      .def_property_readonly("quad_count", [](const ToolScene& s) { return s.description.quads.size(); });

  py::class_<PySensor>(m, "Lidar",
                       R"(The laser range-finder of revolve-lidar: a sensor file's path, or its JSON as a dict.

scan(scene, poses) traces every beam from every pose with revolve-lidar's conventions (ROS
LaserScan: no return is inf, never clamped; seeded per-beam noise) and returns a dict of arrays
shaped (poses, rings, azimuths): ranges (float32, inf for no return), points (float32, (..., 3),
world frame, nan for no return), intensity (float32, reflectivity |cos| / range^2 in 1/m^2, nan
for no return), time (float32, seconds from the sweep's start to the beam's firing: 0 without a
rotation_rate), rings (uint16), return (uint8: the return's index, nearest first) and ids (int32:
the scene's object index, quads after the objects, -1 for no return), bit for bit revolve-lidar's.
A sensor reporting several returns a beam (returns "all", max_returns > 1) gives (poses,
max_returns, rings, azimuths): one layer per return, empty (inf range, nan point) where a beam has
fewer; a beam pattern one ring of all its beams. With a rotation_rate (or pattern
times) and poses that carry times, each beam is traced from where the moving sensor is when it
fires (docs/robot.md).)")
      .def(py::init([](py::handle sensor) { return sensorOf(sensor); }), py::arg("sensor"))
      .def(
          "_sources",
          [](const PySensor& s) {
            py::dict patterns;
            for (const auto& [path, text] : s.patterns.texts) patterns[py::str(path)] = py::bytes(text);
            return py::make_tuple(s.file, py::bytes(s.text), patterns);
          },
          "(name, JSON text, {pattern path: text}): what rebuilds the sensor (what a pickle keeps)")
      .def_static(
          "_from_sources",
          [](const std::string& file, const py::bytes& text, const std::map<std::string, std::string>& patterns) {
            return sensorFromTexts(file, std::string(text), io::FileTexts{patterns, false});
          },
          py::arg("file"), py::arg("text"), py::arg("patterns"))
      .def("scan", &scan, py::arg("scene"), py::arg("poses"), py::arg("threads") = py::int_(0),
           py::arg("first_pose") = py::int_(0), py::arg("sweeps") = py::none(),
           "scene: a Scene or a scene file's path; poses: (N, 3) [x, y, yaw], (N, 4) [x, y, z, yaw], (N, 5) "
           "[x, y, z, yaw, time], (N, 6) [x, y, z, roll, pitch, yaw] or (N, 7) [x, y, z, roll, pitch, yaw, time], or a "
           "POSES.csv path; first_pose: the number of poses[0] in a scan traced in parts "
           "(its noise is that pose's); sweeps: trace the sweeps of poses[:sweeps] only (default all), the poses after "
           "them the rest of the path a moving sensor follows (a part's poses reach past its last sweep's end: "
           "shard_poses).")
      .def_property_readonly(
          "azimuths",
          [](const PySensor& s) {
            const io::ScanLayout layout = io::scanLayout(s.sensor, 1);
            return py::array_t<double>(py::ssize_t(layout.azimuths.size()), layout.azimuths.data());
          },
          "one per column (a beam pattern's: one per beam)")
      .def_property_readonly(
          "elevations",
          [](const PySensor& s) {
            const io::ScanLayout layout = io::scanLayout(s.sensor, 1);
            return py::array_t<double>(py::ssize_t(layout.elevations.size()), layout.elevations.data());
          },
          "one per ring (a beam pattern's: one per beam)")
      .def_property_readonly("beams_per_pose",
                             [](const PySensor& s) { return io::scanLayout(s.sensor, 1).beamsPerPose(); })
      .def_property_readonly(
          "returns_per_beam", [](const PySensor& s) { return s.sensor.layers(); },
          "points a beam gives: max_returns with returns \"all\" (the scan's second axis), else 1")
      .def_property_readonly("rotation_rate", [](const PySensor& s) { return s.sensor.rotationRate; })
      .def_property_readonly(
          "sweep_duration", [](const PySensor& s) { return s.sensor.sweepDuration(); },
          "seconds from a sweep's first beam to its last (0 without a rotation_rate or pattern times)");

  py::class_<PyRangeSensors>(
      m, "RangeSensors",
      R"(Range sensors (sonars, infrared rangers): a sensor file with "type": "range" (its path, or
its JSON as a dict), one sensor or a ring of them, as revolve-lidar reads it (docs/robot.md).

read(scene, poses) gives each sensor's reading at each pose, bit for bit revolve-lidar's table: the
distance to the nearest surface inside the sensor's cone (ROS Range), exact, with the sensor's
seeded noise; inf where there is none or it falls outside [min_range, max_range]. A dict of
arrays: range (poses, sensors) float64, point (poses, sensors, 3) float64 (the reading's point in
the world frame, nan for none) and object (poses, sensors) int64 (the scene's object index, quads
after the objects, -1 for none).)")
      .def(py::init([](py::handle sensor) { return rangeSensorsOf(sensor); }), py::arg("sensor"))
      .def(
          "_sources", [](const PyRangeSensors& s) { return py::make_tuple(s.file, py::bytes(s.text)); },
          "(name, JSON text): what rebuilds the sensors (what a pickle keeps)")
      .def_static(
          "_from_sources",
          [](const std::string& file, const py::bytes& text) {
            PyRangeSensors made{{}, file, std::string(text)};
            made.sensors = io::parseRangeSensors(made.text, made.file);
            return made;
          },
          py::arg("file"), py::arg("text"))
      .def("read", &readRanges, py::arg("scene"), py::arg("poses"), py::arg("threads") = py::int_(0),
           py::arg("first_pose") = py::int_(0),
           "scene: a Scene or a scene file's path; poses: as Lidar.scan takes them, or a POSES.csv path; "
           "first_pose: the number of poses[0] in a path read in parts (its noise is that pose's)")
      .def_property_readonly("count", [](const PyRangeSensors& s) { return s.sensors.sensors.size(); })
      .def_property_readonly(
          "names",
          [](const PyRangeSensors& s) {
            py::list names;
            for (const io::RangeSensorDescription& d : s.sensors.sensors) names.append(d.name);
            return names;
          },
          "each sensor's name (its frame id), in the file's order")
      .def_property_readonly(
          "radiation_type",
          [](const PyRangeSensors& s) {
            py::list types;
            for (const io::RangeSensorDescription& d : s.sensors.sensors)
              types.append(io::radiationTypeName(d.radiation));
            return types;
          },
          "\"ultrasound\" or \"infrared\", a sensor")
      .def_property_readonly(
          "field_of_view",
          [](const PyRangeSensors& s) {
            py::array_t<double> a(py::ssize_t(s.sensors.sensors.size()));
            for (std::size_t i = 0; i < s.sensors.sensors.size(); ++i)
              a.mutable_at(py::ssize_t(i)) = s.sensors.sensors[i].fieldOfView;
            return a;
          },
          "full cone angles, radians")
      .def_property_readonly("min_range",
                             [](const PyRangeSensors& s) {
                               py::array_t<double> a(py::ssize_t(s.sensors.sensors.size()));
                               for (std::size_t i = 0; i < s.sensors.sensors.size(); ++i)
                                 a.mutable_at(py::ssize_t(i)) = s.sensors.sensors[i].minRange;
                               return a;
                             })
      .def_property_readonly("max_range",
                             [](const PyRangeSensors& s) {
                               py::array_t<double> a(py::ssize_t(s.sensors.sensors.size()));
                               for (std::size_t i = 0; i < s.sensors.sensors.size(); ++i)
                                 a.mutable_at(py::ssize_t(i)) = s.sensors.sensors[i].maxRange;
                               return a;
                             })
      .def_property_readonly(
          "noise_stddev",
          [](const PyRangeSensors& s) {
            py::array_t<double> a(py::ssize_t(s.sensors.sensors.size()));
            for (std::size_t i = 0; i < s.sensors.sensors.size(); ++i)
              a.mutable_at(py::ssize_t(i)) = s.sensors.sensors[i].noiseStddev;
            return a;
          },
          "each sensor's Gaussian range noise, metres (0: none); squared, a Range message's variance")
      .def_property_readonly(
          "mounting",
          [](const PyRangeSensors& s) {
            const py::ssize_t n = py::ssize_t(s.sensors.sensors.size());
            py::array_t<double> a(std::vector<py::ssize_t>{n, 6});
            for (py::ssize_t i = 0; i < n; ++i) {
              const io::SensorPose& pose = s.sensors.sensors[std::size_t(i)].pose;
              const double values[6] = {pose.position[0], pose.position[1], pose.position[2],
                                        pose.yaw,         pose.pitch,       pose.roll};
              for (py::ssize_t k = 0; k < 6; ++k) a.mutable_at(i, k) = values[k];
            }
            return a;
          },
          "(sensors, 6): x, y, z, yaw, pitch, roll of each sensor on the robot (R = Rz(yaw) Ry(pitch) Rx(roll))");

  py::class_<ScanFile>(m, "ScanFile",
                       R"(A scan file (.pcd or .csv, as revolve-lidar writes it), written shard by shard in pose order.

The file goes to a temporary beside it, renamed into place by commit() once every pose is written;
dropped (or a failed run) it leaves nothing. `inputs` name files it must not overwrite.)")
      .def(py::init([](py::handle path, py::handle lidar, py::handle poses, py::handle data, py::handle inputs) {
             const std::string file = pathArgument(path, "path");
             if (!py::isinstance<PySensor>(lidar)) {
               throw py::type_error("lidar: a " + std::string(py::str(py::type::handle_of(lidar).attr("__name__"))) +
                                    "; expected a revolve.Lidar");
             }
             const std::uint64_t count = unsignedArgument(poses, "poses", 0, std::numeric_limits<std::uint64_t>::max());
             const std::string format = textArgument(data, "data");
             if (!py::isinstance<py::list>(inputs) && !py::isinstance<py::tuple>(inputs)) {
               throw py::type_error("inputs: a " + std::string(py::str(py::type::handle_of(inputs).attr("__name__"))) +
                                    "; expected a list of paths");
             }
             std::vector<std::string> paths;
             for (const py::handle input : inputs) paths.push_back(pathArgument(input, "inputs[]"));
             try {
               return std::make_unique<ScanFile>(file, lidar.cast<const PySensor&>(), count, format, paths);
             } catch (const std::runtime_error& error) {  // the output named (its folder, its kind, an input)
               throw py::value_error(error.what());
             }
           }),
           py::arg("path"), py::arg("lidar"), py::arg("poses"), py::arg("data") = py::str("ascii"),
           py::arg("inputs") = py::list())
      .def("write", &ScanFile::write, py::arg("first_pose"), py::arg("scan"))
      .def("commit", &ScanFile::commit)
      .def_property_readonly("poses_written", [](const ScanFile& f) { return f.nextPose; });

  m.def("cylinder_clearance", &cylinderClearance, py::arg("scene"), py::arg("poses"), py::arg("radius"),
        py::arg("z_min"), py::arg("z_max"), py::arg("ground") = py::none(), py::arg("threads") = py::int_(0),
        R"(revolve-clearance's clearance of a vertical-cylinder robot at each pose.

The robot is a solid cylinder of `radius` from z + z_min to z + z_max at (x, y) of each pose. Returns
a dict: clearance (float64, signed: negative when an obstacle's surface enters the robot; inf with
no obstacle), collides (bool), object (int64, -1 for none), point (float64 (N, 3), a point of the
nearest obstacle's surface), exact (bool: false where the clearance is a lower bound).)");
  m.def(
      "read_poses", [](py::handle path) { return posesArray(io::readPosesCsv(pathArgument(path, "path"))); },
      py::arg("path"),
      "A POSES.csv file as revolve-lidar reads it: an (N, 4) float64 array of x, y, z, yaw, (N, 6) of x, y, z, roll, "
      "pitch, yaw where a pose is tilted, either with the time as a last column "
      "when the file has a time column.");
}

}  // namespace revolve::python
