#include "io/object_table.h"

#include "geometry/placement.h"
#include "geometry/ray_limits.h"
#include "io/csv_fields.h"
#include "io/curve_tolerance.h"
#include "io/scene_profiles.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace revolve::io {
namespace {

using json::child;
using json::Json;
using json::numberText;
using json::quotedText;

// Profiles are built a batch at a time, in parallel: enough objects to keep the threads busy, few
// enough that the batch's points are a small part of the scene's memory.
constexpr std::size_t kBatchObjects = 4096;

// The keys every object of the table shares.
struct TableKeys {
  std::string path;  // object_tables[t]
  std::string profilesPath, objectsPath;
  std::string profilesFile, objectsFile;  // as opened
  std::size_t material = 0;
  double reflectivity = 1;
  double tolerance = 0;
  double creaseDegrees = ShadingNormals::kDefaultCreaseDegrees;
};

// An object read but not yet built.
struct PendingObject {
  std::vector<Point2> points;
  std::vector<std::size_t> lines;  // of each point in profiles_csv
  SplineKind kind = SplineKind::linear;
  app::Transform transform;
  std::size_t line = 0;  // in objects_csv
  std::size_t id = 0;    // within the table
};

// A bad line: its file and line under the key that names the file (as a profile CSV's).
[[noreturn]] void failAt(const SceneReader& in, const std::string& keyPath, const std::string& file, std::size_t line,
                         const std::string& problem) {
  in.fail(keyPath, InputError(file, line, problem).what());
}

class TableReader {
 public:
  TableReader(const SceneReader& in, const TableKeys& keys, SceneDescription& scene)
      : in_(in), keys_(keys), scene_(scene) {}

  template <class LineSource>
  void read(LineSource& profileLines, LineSource& objectLines);

 private:
  // A whole-number object id in [0, kMaxObjectTableObjects).
  std::size_t objectId(std::string_view field, const std::string& keyPath, const std::string& file,
                       std::size_t line) const {
    std::uint64_t id = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), id);
    if (field.empty() || error != std::errc() || end != field.data() + field.size()) {
      failAt(in_, keyPath, file, line, "object = " + csv::quote(field) + " is not a whole number >= 0");
    }
    if (id >= kMaxObjectTableObjects) {
      failAt(in_, keyPath, file, line,
             "object = " + csv::quote(field) + " is beyond the table's limit: a table holds at most " +
                 std::to_string(kMaxObjectTableObjects) + " objects");
    }
    return std::size_t(id);
  }
  double finiteAt(const std::vector<std::string_view>& fields, std::size_t i, const char* name,
                  const std::string& keyPath, const std::string& file, std::size_t line) const {
    const std::optional<double> value = csv::parseNumber<double>(fields[i]);
    if (!value)
      failAt(in_, keyPath, file, line, std::string(name) + " = " + csv::quote(fields[i]) + " is not a number");
    if (!std::isfinite(*value))
      failAt(in_, keyPath, file, line, std::string(name) + " = " + csv::quote(fields[i]) + " is not finite");
    return *value;
  }
  // The object line's spline kind and placement, held to the rules of an object's keys.
  void readObjectLine(const std::vector<std::string_view>& fields, std::size_t line, PendingObject& object) const;
  // Builds the pending objects' profiles in parallel, checks their reach, and appends them in order.
  void flush();

  const SceneReader& in_;
  const TableKeys& keys_;
  SceneDescription& scene_;
  std::vector<PendingObject> pending_;
  std::size_t pendingPoints_ = 0;
};

void TableReader::readObjectLine(const std::vector<std::string_view>& fields, std::size_t line,
                                 PendingObject& object) const {
  const std::string& keyPath = keys_.objectsPath;
  const std::string& file = keys_.objectsFile;
  const std::optional<SplineKind> kind = splineKindNamed(fields[1]);
  if (!kind) {
    failAt(in_, keyPath, file, line,
           "spline = " + csv::quote(fields[1]) +
               " is not a spline kind; expected one of: linear, quadratic, bezier, catmull-rom, natural");
  }
  object.kind = *kind;
  static constexpr const char* kPosition[3] = {"x", "y", "z"};
  for (std::size_t i = 0; i < 3; ++i) {
    const double x = finiteAt(fields, 2 + i, kPosition[i], keyPath, file, line);
    if (std::abs(x) > app::kMaxWorldCoordinate) {
      failAt(in_, keyPath, file, line,
             std::string(kPosition[i]) + " = " + csv::quote(fields[2 + i]) +
                 " is beyond the coordinate limit: " + app::kCoordinateLimitRule);
    }
    object.transform.translate[i] = x;
  }
  static constexpr const char* kAxis[3] = {"axis_x", "axis_y", "axis_z"};
  app::Vec3d axis{};
  for (std::size_t i = 0; i < 3; ++i) axis[i] = finiteAt(fields, 5 + i, kAxis[i], keyPath, file, line);
  if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) {
    failAt(in_, keyPath, file, line,
           "the rotation axis (axis_x, axis_y, axis_z) is zero; give any axis with degrees 0");
  }
  object.transform.rotateAxis = json::unitVector(axis);
  object.transform.rotateDegrees = finiteAt(fields, 8, "degrees", keyPath, file, line);
  const double scale = finiteAt(fields, 9, "scale", keyPath, file, line);
  if (const std::optional<std::string> fault = app::scaleFactorFault(scale, fields[9]))
    failAt(in_, keyPath, file, line, "scale: " + *fault);
  object.transform.scale = {scale, scale, scale};
}

template <class LineSource>
void TableReader::read(LineSource& profileLines, LineSource& objectLines) {
  const auto rowOf = [&](auto& rows, const std::string& keyPath) -> const std::vector<std::string_view>* {
    try {
      return rows.next();
    } catch (const InputError& error) {  // "file:line: problem"
      in_.fail(keyPath, error.what());
    }
  };
  csv::Rows profileRows(profileLines, keys_.profilesFile, kObjectTableProfilesHeader, 3);
  csv::Rows objectRows(objectLines, keys_.objectsFile, kObjectTableObjectsHeader, 10);
  const std::vector<std::string_view>* point = rowOf(profileRows, keys_.profilesPath);
  if (point == nullptr) failAt(in_, keys_.profilesPath, keys_.profilesFile, 0, "no profile points");
  std::size_t pointId = objectId((*point)[0], keys_.profilesPath, keys_.profilesFile, profileRows.line());
  if (pointId != 0) {
    failAt(in_, keys_.profilesPath, keys_.profilesFile, profileRows.line(),
           "the first object is " + std::to_string(pointId) + "; objects are numbered 0, 1, 2, ... in order");
  }
  std::size_t next = 0;  // the id the next object line must have
  try {
    while (const std::vector<std::string_view>* row = rowOf(objectRows, keys_.objectsPath)) {
      const std::size_t line = objectRows.line();
      const std::size_t id = objectId((*row)[0], keys_.objectsPath, keys_.objectsFile, line);
      if (id != next) {
        failAt(in_, keys_.objectsPath, keys_.objectsFile, line,
               "object " + std::to_string(id) + " where object " + std::to_string(next) +
                   " comes next: objects are numbered 0, 1, 2, ... in order, one line each");
      }
      if (point == nullptr) {
        failAt(in_, keys_.objectsPath, keys_.objectsFile, line,
               "object " + std::to_string(id) + " has no profile: " + keys_.profilesFile + " ends with object " +
                   std::to_string(id - 1));
      }
      PendingObject object;
      object.id = id;
      object.line = line;
      readObjectLine(*row, line, object);
      // This object's points: the profile lines up to the next object's first.
      while (point != nullptr && pointId == id) {
        if (object.points.size() == kMaxObjectTablePoints) {
          failAt(in_, keys_.profilesPath, keys_.profilesFile, profileRows.line(),
                 "object " + std::to_string(id) + " has more than " + std::to_string(kMaxObjectTablePoints) +
                     " points; a table's profile holds at most that many");
        }
        object.points.push_back({finiteAt(*point, 1, "r", keys_.profilesPath, keys_.profilesFile, profileRows.line()),
                                 finiteAt(*point, 2, "z", keys_.profilesPath, keys_.profilesFile, profileRows.line())});
        object.lines.push_back(profileRows.line());
        point = rowOf(profileRows, keys_.profilesPath);
        if (point != nullptr) {
          pointId = objectId((*point)[0], keys_.profilesPath, keys_.profilesFile, profileRows.line());
          if (pointId != id && pointId != id + 1) {
            failAt(in_, keys_.profilesPath, keys_.profilesFile, profileRows.line(),
                   "object " + std::to_string(pointId) + " follows object " + std::to_string(id) +
                       ": objects are numbered 0, 1, 2, ... in order, each one's points together");
          }
        }
      }
      pendingPoints_ += object.points.size();
      pending_.push_back(std::move(object));
      ++next;
      // A batch is so many objects, or as many points as that many of the family's 64-point profiles.
      if (pending_.size() == kBatchObjects || pendingPoints_ >= kBatchObjects * 64) flush();
    }
    if (next == 0) failAt(in_, keys_.objectsPath, keys_.objectsFile, 0, "no objects");
    if (point != nullptr) {
      failAt(in_, keys_.profilesPath, keys_.profilesFile, profileRows.line(),
             "object " + std::to_string(pointId) + " has no line in " + keys_.objectsFile +
                 ", which ends with object " + std::to_string(next - 1));
    }
  } catch (const SceneError&) {
    flush();  // an earlier object's own error comes first, as in a reading in order
    throw;
  }
  flush();
}

void TableReader::flush() {
  std::vector<PendingObject> batch = std::move(pending_);
  pending_.clear();
  pendingPoints_ = 0;
  std::vector<std::optional<SceneProfile>> profiles(batch.size());
  std::vector<SceneObject> objects(batch.size());
  forEachInParallel(batch.size(), [&](std::size_t i) {
    PendingObject& pending = batch[i];
    const std::string objectLine = InputError(keys_.objectsFile, pending.line, "").what();
    const std::string where = objectLine.substr(0, objectLine.size() - 2);  // "file:line"
    ProfileRecipe recipe{pending.kind, pending.kind == SplineKind::linear ? 0 : keys_.tolerance, keys_.creaseDegrees,
                         keys_.objectsPath + ": " + where, child(keys_.path, "tolerance")};
    const std::string& file = keys_.profilesFile;
    ProfileSource source{std::move(pending.points),
                         [&file, &pending](std::size_t k) {
                           return file + ":" + std::to_string(k < pending.lines.size() ? pending.lines[k] : 0);
                         },
                         keys_.profilesPath, file};
    profiles[i].emplace(
        buildSceneProfile(in_, keys_.profilesFile + " object " + std::to_string(pending.id), recipe, source));
    SceneObject& object = objects[i];
    object.profile = scene_.profiles.size() + i;
    object.material = keys_.material;
    object.transform = pending.transform;
    object.reflectivity = keys_.reflectivity;
    // Hits on it must lie within the limit too: secondary rays start there (as an object's). An
    // exact spline by its control points' reach, which bounds its curve's (boundingPoints).
    const double reach = app::worldReach(boundingPoints(*profiles[i]), app::Placement(object.transform));
    if (const std::optional<std::string> fault = app::reachFault(reach))
      failAt(in_, keys_.objectsPath, keys_.objectsFile, pending.line, *fault);
  });
  for (std::size_t i = 0; i < batch.size(); ++i) {
    scene_.profiles.push_back(std::move(*profiles[i]));
    scene_.objects.push_back(std::move(objects[i]));
  }
}

}  // namespace

void readObjectTable(const SceneReader& in, const Json& json, const std::string& path, const std::string& directory,
                     FileTexts* csvs, SceneDescription& scene) {
  in.object(json, path, {"profiles_csv", "objects_csv", "material", "reflectivity", "tolerance", "crease"});
  TableKeys keys;
  keys.path = path;
  keys.profilesPath = child(path, "profiles_csv");
  keys.objectsPath = child(path, "objects_csv");
  const auto fileOf = [&](const std::string& keyPath, const char* key) {
    const std::string relative = in.string(in.required(json, path, key), keyPath);
    if (relative.empty()) in.fail(keyPath, "the file name is empty");
    return (std::filesystem::path(directory) / relative).string();
  };
  keys.profilesFile = fileOf(keys.profilesPath, "profiles_csv");
  keys.objectsFile = fileOf(keys.objectsPath, "objects_csv");
  const std::string materialPath = child(path, "material");
  const std::string material = in.string(in.required(json, path, "material"), materialPath);
  keys.material = scene.materials.size();
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == material) keys.material = i;
  }
  if (keys.material == scene.materials.size()) in.fail(materialPath, "no material named " + quotedText(material));
  if (const Json* value = in.optional(json, "reflectivity"))
    keys.reflectivity = in.numberIn(*value, child(path, "reflectivity"), 0, 1, "a reflectivity lies in [0, 1]");
  if (const Json* value = in.optional(json, "crease")) {
    keys.creaseDegrees = in.numberIn(*value, child(path, "crease"), 0, 180, "a crease angle lies in [0, 180] degrees");
  }
  if (const Json* value = in.optional(json, "tolerance")) {
    keys.tolerance = in.number(*value, child(path, "tolerance"));
    if (const std::optional<std::string> fault = toleranceFault(keys.tolerance, numberText(*value)))
      in.fail(child(path, "tolerance"), *fault);
  }

  TableReader reader(in, keys, scene);
  // Opening a file (or finding its kept text) fails under its key: "file: problem".
  const auto opened = [&](const std::string& keyPath, auto open) {
    try {
      return open();
    } catch (const InputError& error) {
      in.fail(keyPath, error.what());
    }
  };
  const char* kind = "an object table's CSV";
  if (csvs != nullptr) {
    const std::string& profiles =
        *opened(keys.profilesPath, [&] { return &csvs->text(keys.profilesFile, kMaxObjectTableFileBytes, kind); });
    const std::string& objects =
        *opened(keys.objectsPath, [&] { return &csvs->text(keys.objectsFile, kMaxObjectTableFileBytes, kind); });
    csv::Lines profileLines(profiles, keys.profilesFile), objectLines(objects, keys.objectsFile);
    reader.read(profileLines, objectLines);
    return;
  }
  std::unique_ptr<FileLines> profileLines = opened(keys.profilesPath, [&] {
    return std::make_unique<FileLines>(keys.profilesFile, kMaxObjectTableFileBytes, kind);
  });
  std::unique_ptr<FileLines> objectLines = opened(
      keys.objectsPath, [&] { return std::make_unique<FileLines>(keys.objectsFile, kMaxObjectTableFileBytes, kind); });
  reader.read(*profileLines, *objectLines);
}

}  // namespace revolve::io
