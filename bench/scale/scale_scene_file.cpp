#include "scale/scale_scene_file.h"

#include "io/object_table.h"
#include "io/output_set.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace revolve::bench {
namespace {

// Appends `value` as the shortest text that reads back to it exactly.
void appendNumber(std::string& out, double value) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

// Lines are gathered into blocks this large before they are written.
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;

}  // namespace

std::string writeFamilyScene(const ScaleFamily& family, std::size_t count, const std::string& directory) {
  std::filesystem::create_directories(directory);
  const std::string stem = "scale-" + std::to_string(count);
  const std::string json = (std::filesystem::path(directory) / (stem + ".json")).string();
  const std::string profilesName = stem + "-profiles.csv", objectsName = stem + "-objects.csv";
  const std::string profiles = (std::filesystem::path(directory) / profilesName).string();
  const std::string objects = (std::filesystem::path(directory) / objectsName).string();
  io::OutputSet outputs;
  outputs.add("--write-scene", json);
  outputs.add("--write-scene", profiles);
  outputs.add("--write-scene", objects);

  std::string pointLines = std::string(io::kObjectTableProfilesHeader) + "\n";
  std::string objectLines = std::string(io::kObjectTableObjectsHeader) + "\n";
  for (std::size_t i = 0; i < count; ++i) {
    const std::string id = std::to_string(i);
    for (const Point2& p : family.points(i)) {
      pointLines += id;
      pointLines += ',';
      appendNumber(pointLines, p.r);
      pointLines += ',';
      appendNumber(pointLines, p.z);
      pointLines += '\n';
    }
    const app::Transform t = family.transform(i, count);  // a uniform scale, no rotation
    objectLines += id;
    objectLines += family.isSpline(i) ? ",catmull-rom," : ",linear,";
    for (const double x : t.translate) {
      appendNumber(objectLines, x);
      objectLines += ',';
    }
    objectLines += "0,0,1,0,";
    appendNumber(objectLines, t.scale[0]);
    objectLines += '\n';
    if (pointLines.size() >= kBlockBytes) {
      outputs.stream(profiles).write(pointLines);
      pointLines.clear();
    }
    if (objectLines.size() >= kBlockBytes) {
      outputs.stream(objects).write(objectLines);
      objectLines.clear();
    }
  }
  outputs.stream(profiles).write(pointLines);
  outputs.stream(objects).write(objectLines);

  // The benchmark's camera (scale_suite.cpp's cameraRays): above one corner, across the grid.
  const double side = ScaleFamily::kSpacing * double(ScaleFamily::gridSide(count));
  nlohmann::ordered_json scene;
  scene["description"] = "revolve-bench scale: " + std::to_string(count) +
                         " distinct 64-point surfaces of revolution (seed " + std::to_string(family.seed) +
                         "), even objects polylines, odd ones centripetal Catmull-Rom splines traced exactly";
  scene["camera"] = {{"from", {-0.05 * side - 2, -0.05 * side - 2, 0.25 * side + 2}},
                     {"to", {0.5 * side, 0.5 * side, 0}},
                     {"up", {0, 0, 1}},
                     {"fov", 50},
                     {"width", 512},
                     {"height", 256}};
  scene["profiles"] = nlohmann::ordered_json::object();
  scene["materials"] = {{"clay", {{"type", "diffuse"}, {"color", {0.75, 0.6, 0.5}}}}};
  scene["objects"] = nlohmann::ordered_json::array();
  scene["object_tables"] = {{{"profiles_csv", profilesName}, {"objects_csv", objectsName}, {"material", "clay"}}};
  scene["lights"] = {{{"type", "sun"}, {"direction", {-0.4, -0.3, -1}}, {"irradiance", {3, 3, 3}}, {"angle", 0.5}}};
  scene["environment"] = {{"sky", {{"zenith", {0.3, 0.45, 0.8}}, {"horizon", {0.8, 0.85, 0.9}}}}};
  outputs.stream(json).write(scene.dump(2) + "\n");
  outputs.commit();
  return json;
}

}  // namespace revolve::bench
