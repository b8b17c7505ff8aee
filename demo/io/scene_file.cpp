#include "io/scene_file.h"

#include "io/text_files.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>

namespace revolve::io {
namespace {

// ordered_json keeps the file's order of profiles and materials, so indices and messages follow it.
using Json = nlohmann::ordered_json;

// Text from the file, made safe for a one-line message: control bytes become '?', and it is cut
// at 40 bytes so that a binary key cannot flood the terminal.
std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text.substr(0, 40)) {
    const auto byte = static_cast<unsigned char>(c);
    out += (byte >= 0x20 && byte != 0x7f) ? c : '?';
  }
  if (text.size() > 40) out += "...";
  return out;
}
std::string quotedText(std::string_view text) {
  std::string out = "\"";
  out += printable(text);
  out += "\"";
  return out;
}

std::string child(const std::string& path, std::string_view key) {
  return path.empty() ? printable(key) : path + "." + printable(key);
}
std::string element(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

std::string joined(std::initializer_list<std::string_view> names) {
  std::string out;
  for (const std::string_view name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

std::string degreesText(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// Typed access to the JSON tree with key paths for messages.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw SceneError(file_ + ": " + (path.empty() ? "" : path + ": ") + problem);
  }

  const Json& object(const Json& value, const std::string& path, std::initializer_list<std::string_view> allowed) const {
    if (!value.is_object()) fail(path, std::string("expected an object, found ") + value.type_name());
    for (const auto& [key, ignored] : value.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(child(path, key), "unknown key; expected one of: " + joined(allowed));
      }
    }
    return value;
  }

  const Json& required(const Json& object, const std::string& path, const char* key) const {
    const auto found = object.find(key);
    if (found == object.end()) fail(path, std::string("missing key \"") + key + "\"");
    return *found;
  }
  const Json* optional(const Json& object, const char* key) const {
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
  }

  const Json& array(const Json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, std::string("expected an array, found ") + value.type_name());
    return value;
  }

  double number(const Json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, std::string("expected a number, found ") + value.type_name());
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(path, "the number is beyond double's range");
    return x;
  }
  double numberIn(const Json& value, const std::string& path, double lo, double hi, const char* rule) const {
    const double x = number(value, path);
    if (!(x >= lo && x <= hi)) fail(path, degreesText(x) + " is out of range: " + rule);
    return x;
  }
  int integerIn(const Json& value, const std::string& path, int lo, int hi) const {
    const double x = number(value, path);
    if (x != std::floor(x)) fail(path, degreesText(x) + " is not a whole number");
    if (!(x >= lo && x <= hi)) {
      fail(path, degreesText(x) + " is out of range: must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return int(x);
  }
  std::string string(const Json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, std::string("expected a string, found ") + value.type_name());
    return value.get<std::string>();
  }
  Vec3d vec3(const Json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != 3) fail(path, "expected an array of 3 numbers [x, y, z]");
    return {number(value[0], element(path, 0)), number(value[1], element(path, 1)), number(value[2], element(path, 2))};
  }
  Vec3d nonZero(const Json& value, const std::string& path) const {
    const Vec3d v = vec3(value, path);
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) fail(path, "the vector is zero; a direction is needed");
    return v;
  }
  // A colour: three numbers each in [0, hi] (hi = 1 for reflectances, unbounded for radiance).
  Rgb rgb(const Json& value, const std::string& path, double hi) const {
    if (!value.is_array() || value.size() != 3) fail(path, "expected a colour [r, g, b]");
    Rgb c;
    for (std::size_t i = 0; i < 3; ++i) {
      c[i] = number(value[i], element(path, i));
      if (!(c[i] >= 0 && c[i] <= hi)) {
        fail(element(path, i), degreesText(c[i]) + (hi == 1 ? " is out of range: a reflectance lies in [0, 1]"
                                                             : " is negative: light cannot be"));
      }
    }
    return c;
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

constexpr double kUnbounded = 1.0e300;

Vec3d normalised(Vec3d v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

Vec3d cross(Vec3d a, Vec3d b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

SceneCamera readCamera(const Reader& in, const Json& json) {
  const std::string path = "camera";
  in.object(json, path, {"from", "to", "up", "fov", "width", "height", "spp"});
  SceneCamera camera;
  camera.from = in.vec3(in.required(json, path, "from"), "camera.from");
  camera.to = in.vec3(in.required(json, path, "to"), "camera.to");
  camera.up = in.nonZero(in.required(json, path, "up"), "camera.up");
  camera.fovDegrees = in.number(in.required(json, path, "fov"), "camera.fov");
  if (!(camera.fovDegrees > 0 && camera.fovDegrees < 180)) {
    in.fail("camera.fov", degreesText(camera.fovDegrees) + " is out of range: the vertical field of view lies in (0, 180) degrees");
  }
  const Vec3d view{camera.to[0] - camera.from[0], camera.to[1] - camera.from[1], camera.to[2] - camera.from[2]};
  if (view[0] == 0 && view[1] == 0 && view[2] == 0) in.fail("camera.to", "equals camera.from; the camera needs a direction");
  const Vec3d side = cross(normalised(view), normalised(camera.up));
  if (std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]) < 1e-6) {
    in.fail("camera.up", "is parallel to the view direction (to - from)");
  }
  if (const Json* v = in.optional(json, "width")) camera.width = in.integerIn(*v, "camera.width", 1, 16384);
  if (const Json* v = in.optional(json, "height")) camera.height = in.integerIn(*v, "camera.height", 1, 16384);
  if (const Json* v = in.optional(json, "spp")) camera.spp = in.integerIn(*v, "camera.spp", 1, 1 << 20);
  return camera;
}

SceneProfile readProfile(const Reader& in, const std::string& name, const Json& json, const std::string& path,
                         const std::string& directory) {
  in.object(json, path, {"points", "csv", "crease"});
  const Json* points = in.optional(json, "points");
  const Json* csv = in.optional(json, "csv");
  if ((points != nullptr) == (csv != nullptr)) in.fail(path, "needs exactly one of \"points\" or \"csv\"");
  double creaseDegrees = ShadingNormals::kDefaultCreaseDegrees;
  if (const Json* crease = in.optional(json, "crease")) {
    creaseDegrees = in.numberIn(*crease, child(path, "crease"), 0, 180, "a crease angle lies in [0, 180] degrees");
  }
  std::optional<Profile> built;
  std::vector<std::string> warnings;
  if (points != nullptr) {
    const std::string pointsPath = child(path, "points");
    in.array(*points, pointsPath);
    std::vector<Point2> values;
    for (std::size_t i = 0; i < points->size(); ++i) {
      const Json& point = (*points)[i];
      if (!point.is_array() || point.size() != 2) in.fail(element(pointsPath, i), "expected a point [r, z]");
      values.push_back({in.number(point[0], element(pointsPath, i) + "[0]"), in.number(point[1], element(pointsPath, i) + "[1]")});
    }
    try {
      built.emplace(values);
    } catch (const ProfileError& error) {
      in.fail(error.index() < values.size() ? element(pointsPath, error.index()) : pointsPath, error.what());
    }
    for (const ProfileWarning& warning : built->warnings()) {
      warnings.push_back(in.file() + ": " + element(pointsPath, warning.index) + ": " + warning.message);
    }
    return {name, std::move(*built), creaseDegrees, std::move(warnings)};
  }
  const std::string csvPath = child(path, "csv");
  const std::string relative = in.string(*csv, csvPath);
  if (relative.empty()) in.fail(csvPath, "the file name is empty");
  const std::string file = (std::filesystem::path(directory) / relative).string();
  ProfileFile csvPoints;
  try {
    csvPoints = readProfileCsv(file);
  } catch (const InputError& error) {  // "file:line: problem", the line's text already made printable
    in.fail(csvPath, error.what());
  }
  try {
    built.emplace(csvPoints.points);
  } catch (const ProfileError& error) {
    const std::size_t line = error.index() < csvPoints.lines.size() ? csvPoints.lines[error.index()] : 0;
    in.fail(csvPath, file + ":" + std::to_string(line) + ": " + error.what());
  }
  for (const ProfileWarning& warning : built->warnings()) {
    warnings.push_back(file + ":" + std::to_string(csvPoints.lines[warning.index]) + ": " + warning.message);
  }
  return {name, std::move(*built), creaseDegrees, std::move(warnings)};
}

SceneMaterial readMaterial(const Reader& in, const std::string& name, const Json& json, const std::string& path) {
  if (!json.is_object()) in.fail(path, std::string("expected an object, found ") + json.type_name());
  const std::string type = in.string(in.required(json, path, "type"), child(path, "type"));
  SceneMaterial material;
  material.name = name;
  if (type == "diffuse" || type == "mirror") {
    in.object(json, path, {"type", "color"});
    material.type = type == "diffuse" ? MaterialType::diffuse : MaterialType::mirror;
    material.color = in.rgb(in.required(json, path, "color"), child(path, "color"), 1);
  } else if (type == "metal") {
    in.object(json, path, {"type", "color", "roughness"});
    material.type = MaterialType::metal;
    material.color = in.rgb(in.required(json, path, "color"), child(path, "color"), 1);
    material.roughness = in.numberIn(in.required(json, path, "roughness"), child(path, "roughness"), 0, 1,
                                     "roughness lies in [0, 1]");
  } else if (type == "glass") {
    in.object(json, path, {"type", "ior", "tint"});
    material.type = MaterialType::glass;
    material.ior = in.numberIn(in.required(json, path, "ior"), child(path, "ior"), 1, 4,
                               "an index of refraction lies in [1, 4]");
    if (const Json* tint = in.optional(json, "tint")) material.tint = in.rgb(*tint, child(path, "tint"), 1);
  } else {
    in.fail(child(path, "type"), quotedText(type) + " is not a material type; expected one of: diffuse, metal, mirror, glass");
  }
  return material;
}

// Index of the entry called `name`, or a message listing what exists.
template <class Named>
std::size_t lookUp(const Reader& in, const std::vector<Named>& list, const Json& value, const std::string& path,
                   const char* what) {
  const std::string name = in.string(value, path);
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i].name == name) return i;
  }
  in.fail(path, std::string("no ") + what + " named " + quotedText(name));
}

SceneTransform readTransform(const Reader& in, const Json& json, const std::string& path) {
  SceneTransform transform;
  if (const Json* translate = in.optional(json, "translate")) transform.translate = in.vec3(*translate, child(path, "translate"));
  if (const Json* rotate = in.optional(json, "rotate")) {
    const std::string rotatePath = child(path, "rotate");
    if (!rotate->is_array() || rotate->size() != 4) in.fail(rotatePath, "expected [axis x, axis y, axis z, degrees]");
    Vec3d axis;
    for (std::size_t i = 0; i < 3; ++i) axis[i] = in.number((*rotate)[i], element(rotatePath, i));
    if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) in.fail(rotatePath, "the rotation axis is zero");
    transform.rotateAxis = normalised(axis);
    transform.rotateDegrees = in.number((*rotate)[3], element(rotatePath, 3));
  }
  if (const Json* scale = in.optional(json, "scale")) {
    const std::string scalePath = child(path, "scale");
    if (scale->is_number()) {
      const double s = in.number(*scale, scalePath);
      transform.scale = {s, s, s};
    } else if (scale->is_array() && scale->size() == 3) {
      transform.scale = in.vec3(*scale, scalePath);
    } else {
      in.fail(scalePath, "expected a number or [sx, sy, sz]");
    }
    for (const double s : transform.scale) {
      if (!(s > 0)) in.fail(scalePath, degreesText(s) + " is not positive: scale factors must be > 0");
    }
  }
  return transform;
}

SceneLight readLight(const Reader& in, const Json& json, const std::string& path) {
  if (!json.is_object()) in.fail(path, std::string("expected an object, found ") + json.type_name());
  const std::string type = in.string(in.required(json, path, "type"), child(path, "type"));
  SceneLight light;
  if (type == "point") {
    in.object(json, path, {"type", "position", "intensity"});
    light.type = LightType::point;
    light.position = in.vec3(in.required(json, path, "position"), child(path, "position"));
    light.intensity = in.rgb(in.required(json, path, "intensity"), child(path, "intensity"), kUnbounded);
  } else if (type == "sun") {
    in.object(json, path, {"type", "direction", "irradiance", "angle"});
    light.type = LightType::sun;
    light.direction = normalised(in.nonZero(in.required(json, path, "direction"), child(path, "direction")));
    light.irradiance = in.rgb(in.required(json, path, "irradiance"), child(path, "irradiance"), kUnbounded);
    if (const Json* angle = in.optional(json, "angle")) {
      light.angleDegrees = in.numberIn(*angle, child(path, "angle"), 0, 45, "the sun's apparent diameter lies in [0, 45] degrees");
    }
  } else {
    in.fail(child(path, "type"), quotedText(type) + " is not a light type; expected one of: point, sun");
  }
  return light;
}

SceneEnvironment readEnvironment(const Reader& in, const Json& json) {
  const std::string path = "environment";
  in.object(json, path, {"color", "sky"});
  const Json* color = in.optional(json, "color");
  const Json* sky = in.optional(json, "sky");
  if ((color != nullptr) == (sky != nullptr)) in.fail(path, "needs exactly one of \"color\" or \"sky\"");
  SceneEnvironment environment;
  if (color != nullptr) {
    environment.color = in.rgb(*color, "environment.color", kUnbounded);
    return environment;
  }
  in.object(*sky, "environment.sky", {"zenith", "horizon"});
  environment.sky = true;
  environment.zenith = in.rgb(in.required(*sky, "environment.sky", "zenith"), "environment.sky.zenith", kUnbounded);
  environment.horizon = in.rgb(in.required(*sky, "environment.sky", "horizon"), "environment.sky.horizon", kUnbounded);
  return environment;
}

// nlohmann keeps the last of repeated keys silently; a repeated key is more likely a mistake.
Json parseJson(std::string_view text, const Reader& in) {
  std::vector<std::set<std::string>> keysOfOpenObjects;
  const Json::parser_callback_t rejectRepeatedKeys = [&](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) {
      keysOfOpenObjects.emplace_back();
    } else if (event == Json::parse_event_t::object_end) {
      if (!keysOfOpenObjects.empty()) keysOfOpenObjects.pop_back();
    } else if (event == Json::parse_event_t::key && !keysOfOpenObjects.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!keysOfOpenObjects.back().insert(key).second) {
        in.fail("", "key " + quotedText(key) + " appears twice in one object; each key may appear once");
      }
    }
    return true;
  };
  try {
    return Json::parse(text.begin(), text.end(), rejectRepeatedKeys);
  } catch (const Json::exception& error) {
    std::string message = error.what();
    const std::size_t bracket = message.find("] ");
    if (message.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos) message = message.substr(bracket + 2);
    std::string safe;
    for (const char c : message.substr(0, 300)) safe += (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) ? c : '?';
    in.fail("", "not valid JSON: " + safe);
  }
}

}  // namespace

SceneDescription parseScene(std::string_view text, const std::string& file, const std::string& directory) {
  const Reader in(file);
  const Json root = parseJson(text, in);
  in.object(root, "", {"description", "camera", "profiles", "materials", "objects", "quads", "lights", "environment"});
  SceneDescription scene;
  scene.file = file;
  if (const Json* description = in.optional(root, "description")) in.string(*description, "description");
  scene.camera = readCamera(in, in.required(root, "", "camera"));

  const Json& profiles = in.required(root, "", "profiles");
  if (!profiles.is_object()) in.fail("profiles", std::string("expected an object of named profiles, found ") + profiles.type_name());
  for (const auto& [name, value] : profiles.items()) {
    scene.profiles.push_back(readProfile(in, name, value, child("profiles", name), directory));
  }

  const Json& materials = in.required(root, "", "materials");
  if (!materials.is_object()) in.fail("materials", std::string("expected an object of named materials, found ") + materials.type_name());
  for (const auto& [name, value] : materials.items()) {
    scene.materials.push_back(readMaterial(in, name, value, child("materials", name)));
  }

  const Json& objects = in.array(in.required(root, "", "objects"), "objects");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string path = element("objects", i);
    const Json& json = in.object(objects[i], path, {"profile", "material", "translate", "rotate", "scale", "name"});
    SceneObject object;
    object.profile = lookUp(in, scene.profiles, in.required(json, path, "profile"), child(path, "profile"), "profile");
    object.material = lookUp(in, scene.materials, in.required(json, path, "material"), child(path, "material"), "material");
    if (const Json* name = in.optional(json, "name")) object.name = in.string(*name, child(path, "name"));
    object.transform = readTransform(in, json, path);
    scene.objects.push_back(std::move(object));
  }

  if (const Json* quads = in.optional(root, "quads")) {
    in.array(*quads, "quads");
    for (std::size_t i = 0; i < quads->size(); ++i) {
      const std::string path = element("quads", i);
      const Json& json = in.object((*quads)[i], path, {"corners", "material"});
      SceneQuad quad;
      const Json& corners = in.required(json, path, "corners");
      if (!corners.is_array() || corners.size() != 4) in.fail(child(path, "corners"), "expected 4 corners [[x, y, z], ...]");
      for (std::size_t c = 0; c < 4; ++c) quad.corners[c] = in.vec3(corners[c], element(child(path, "corners"), c));
      // Both triangles must have an area, or Embree would drop them silently.
      for (const auto& [a, b] : {std::pair{1, 2}, std::pair{2, 3}}) {
        const Vec3d e1{quad.corners[a][0] - quad.corners[0][0], quad.corners[a][1] - quad.corners[0][1], quad.corners[a][2] - quad.corners[0][2]};
        const Vec3d e2{quad.corners[b][0] - quad.corners[0][0], quad.corners[b][1] - quad.corners[0][1], quad.corners[b][2] - quad.corners[0][2]};
        const Vec3d n = cross(e1, e2);
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
          in.fail(child(path, "corners"), "corners 0, " + std::to_string(a) + " and " + std::to_string(b) + " are collinear; a quad needs an area");
        }
      }
      quad.material = lookUp(in, scene.materials, in.required(json, path, "material"), child(path, "material"), "material");
      scene.quads.push_back(quad);
    }
  }

  if (const Json* lights = in.optional(root, "lights")) {
    in.array(*lights, "lights");
    for (std::size_t i = 0; i < lights->size(); ++i) scene.lights.push_back(readLight(in, (*lights)[i], element("lights", i)));
  }
  if (const Json* environment = in.optional(root, "environment")) scene.environment = readEnvironment(in, *environment);
  return scene;
}

SceneDescription readScene(const std::string& path) {
  std::string text;
  try {
    text = readTextFile(path);
  } catch (const InputError& error) {
    throw SceneError(error.what());
  }
  return parseScene(text, path, std::filesystem::path(path).parent_path().string());
}

}  // namespace revolve::io
