#include "io/scene_file.h"

#include "io/curve_tolerance.h"
#include "io/json_reader.h"
#include "io/object_table.h"
#include "io/scene_profiles.h"
#include "io/text_files.h"

#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace revolve::io {
namespace {

using json::child;
using json::element;
using json::Json;
using json::quotedText;
using Reader = json::Reader<SceneError>;

using app::cross;
using json::numberText;
using json::unitVector;

// Reflectances lie in [0, 1]. Radiance and intensity lie in [0, 1e18]: the renderer computes in
// float (up to 3.4e38), which must hold them times a point light's 1/d^2 and a pixel's sum of
// samples.
constexpr double kReflectance = 1;
constexpr double kMaxLight = 1e18;

// A colour: three numbers each in [0, hi].
Rgb rgb(const Reader& in, const Json& value, const std::string& path, double hi) {
  if (!value.is_array() || value.size() != 3) in.fail(path, "expected a colour [r, g, b]");
  Rgb c;
  for (std::size_t i = 0; i < 3; ++i) {
    c[i] = in.number(value[i], element(path, i));
    if (c[i] >= 0 && c[i] <= hi) continue;
    if (hi == kReflectance)
      in.fail(element(path, i), numberText(value[i]) + " is out of range: a reflectance lies in [0, 1]");
    in.fail(element(path, i),
            numberText(value[i]) + " is out of range: light values lie in [0, 1e18] (the renderer computes in float)");
  }
  return c;
}

SceneCamera readCamera(const Reader& in, const Json& json) {
  const std::string path = "camera";
  in.object(json, path, {"from", "to", "up", "fov", "width", "height", "spp"});
  SceneCamera camera;
  camera.from = in.position(in.required(json, path, "from"), "camera.from");
  camera.to = in.position(in.required(json, path, "to"), "camera.to");
  camera.up = in.direction(in.required(json, path, "up"), "camera.up");
  const Json& fov = in.required(json, path, "fov");
  camera.fovDegrees = in.number(fov, "camera.fov");
  if (!(camera.fovDegrees > 0 && camera.fovDegrees < 180)) {
    in.fail("camera.fov", numberText(fov) + " is out of range: the vertical field of view lies in (0, 180) degrees");
  }
  // Both within the coordinate limit, so the difference is exact or finite.
  const Vec3d view{camera.to[0] - camera.from[0], camera.to[1] - camera.from[1], camera.to[2] - camera.from[2]};
  if (view[0] == 0 && view[1] == 0 && view[2] == 0)
    in.fail("camera.to", "equals camera.from; the camera needs a direction");
  const Vec3d side = cross(unitVector(view), camera.up);
  if (std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]) < 1e-6) {
    in.fail("camera.up", "is parallel to the view direction (to - from)");
  }
  if (const Json* v = in.optional(json, "width")) camera.width = in.integerIn(*v, "camera.width", 1, 16384);
  if (const Json* v = in.optional(json, "height")) camera.height = in.integerIn(*v, "camera.height", 1, 16384);
  if (const Json* v = in.optional(json, "spp")) camera.spp = in.integerIn(*v, "camera.spp", 1, 1 << 20);
  return camera;
}

ProfileSource readPoints(const Reader& in, const Json& json, const std::string& path, const std::string& directory,
                         FileTexts* csvs) {
  const Json* points = in.optional(json, "points");
  const Json* csv = in.optional(json, "csv");
  if ((points != nullptr) == (csv != nullptr)) in.fail(path, "needs exactly one of \"points\" or \"csv\"");
  if (points != nullptr) {
    const std::string pointsPath = child(path, "points");
    in.array(*points, pointsPath);
    ProfileSource source{{}, [pointsPath](std::size_t i) { return element(pointsPath, i); }, pointsPath, {}};
    for (std::size_t i = 0; i < points->size(); ++i) {
      const Json& point = (*points)[i];
      if (!point.is_array() || point.size() != 2) in.fail(element(pointsPath, i), "expected a point [r, z]");
      source.points.push_back(
          {in.number(point[0], element(pointsPath, i) + "[0]"), in.number(point[1], element(pointsPath, i) + "[1]")});
    }
    return source;
  }
  const std::string csvPath = child(path, "csv");
  const std::string relative = in.string(*csv, csvPath);
  if (relative.empty()) in.fail(csvPath, "the file name is empty");
  const std::string file = (std::filesystem::path(directory) / relative).string();
  ProfileFile csvPoints;
  try {
    csvPoints = csvs != nullptr ? parseProfileCsv(csvs->text(file, kMaxCsvFileBytes, "a CSV file"), file)
                                : readProfileCsv(file);
  } catch (const InputError& error) {  // "file:line: problem", the line's text already made printable
    in.fail(csvPath, error.what());
  }
  std::vector<std::size_t> lines = csvPoints.lines;
  return {std::move(csvPoints.points),
          [file, lines](std::size_t i) { return file + ":" + std::to_string(i < lines.size() ? lines[i] : 0); },
          csvPath, file};
}

// A named profile's recipe from its keys.
ProfileRecipe readRecipe(const Reader& in, const Json& json, const std::string& path) {
  in.object(json, path, {"points", "csv", "crease", "spline", "tolerance"});
  ProfileRecipe recipe;
  recipe.splinePath = child(path, "spline");
  recipe.tolerancePath = child(path, "tolerance");
  if (const Json* crease = in.optional(json, "crease")) {
    recipe.creaseDegrees =
        in.numberIn(*crease, child(path, "crease"), 0, 180, "a crease angle lies in [0, 180] degrees");
  }
  if (const Json* spline = in.optional(json, "spline")) {
    const std::string text = in.string(*spline, recipe.splinePath);
    const std::optional<SplineKind> named = splineKindNamed(text);
    if (!named) {
      in.fail(recipe.splinePath, "unknown spline kind " + quotedText(text) +
                                     "; expected one of: linear, quadratic, bezier, catmull-rom, natural");
    }
    recipe.kind = *named;
  }
  if (const Json* value = in.optional(json, "tolerance")) {
    recipe.tolerance = in.number(*value, recipe.tolerancePath);
    if (recipe.kind == SplineKind::linear) {
      in.fail(recipe.tolerancePath,
              "applies to a curved \"spline\" (quadratic, bezier, catmull-rom or natural) only; a polyline is traced "
              "as it is");
    }
    if (const std::optional<std::string> fault = toleranceFault(recipe.tolerance, numberText(*value)))
      in.fail(recipe.tolerancePath, *fault);
  }
  return recipe;
}

SceneProfile readProfile(const Reader& in, const std::string& name, const Json& json, const std::string& path,
                         const std::string& directory, FileTexts* csvs) {
  const ProfileRecipe recipe = readRecipe(in, json, path);
  return buildSceneProfile(in, name, recipe, readPoints(in, json, path, directory, csvs));
}

SceneMaterial readMaterial(const Reader& in, const std::string& name, const Json& json, const std::string& path) {
  if (!json.is_object()) in.fail(path, std::string("expected an object, found ") + json.type_name());
  const std::string type = in.string(in.required(json, path, "type"), child(path, "type"));
  SceneMaterial material;
  material.name = name;
  if (type == "diffuse" || type == "mirror") {
    in.object(json, path, {"type", "color"});
    material.type = type == "diffuse" ? MaterialType::diffuse : MaterialType::mirror;
    material.color = rgb(in, in.required(json, path, "color"), child(path, "color"), kReflectance);
  } else if (type == "metal") {
    in.object(json, path, {"type", "color", "roughness"});
    material.type = MaterialType::metal;
    material.color = rgb(in, in.required(json, path, "color"), child(path, "color"), kReflectance);
    material.roughness =
        in.numberIn(in.required(json, path, "roughness"), child(path, "roughness"), 0, 1, "roughness lies in [0, 1]");
  } else if (type == "glass") {
    in.object(json, path, {"type", "ior", "tint"});
    material.type = MaterialType::glass;
    material.ior =
        in.numberIn(in.required(json, path, "ior"), child(path, "ior"), 1, 4, "an index of refraction lies in [1, 4]");
    if (const Json* tint = in.optional(json, "tint")) material.tint = rgb(in, *tint, child(path, "tint"), kReflectance);
  } else {
    in.fail(child(path, "type"),
            quotedText(type) + " is not a material type; expected one of: diffuse, metal, mirror, glass");
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

app::Transform readTransform(const Reader& in, const Json& json, const std::string& path) {
  app::Transform transform;
  if (const Json* translate = in.optional(json, "translate"))
    transform.translate = in.position(*translate, child(path, "translate"));
  if (const Json* rotate = in.optional(json, "rotate")) {
    const std::string rotatePath = child(path, "rotate");
    if (!rotate->is_array() || rotate->size() != 4) in.fail(rotatePath, "expected [axis x, axis y, axis z, degrees]");
    Vec3d axis;
    for (std::size_t i = 0; i < 3; ++i) axis[i] = in.number((*rotate)[i], element(rotatePath, i));
    if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) in.fail(rotatePath, "the rotation axis is zero");
    transform.rotateAxis = unitVector(axis);
    transform.rotateDegrees = in.number((*rotate)[3], element(rotatePath, 3));
  }
  if (const Json* scale = in.optional(json, "scale")) {
    // The placement rule (geometry/placement.h), factor by factor, each named by its key path.
    const std::string scalePath = child(path, "scale");
    const auto factor = [&](const Json& value, const std::string& where) {
      const double s = in.number(value, where);
      if (const std::optional<std::string> fault = app::scaleFactorFault(s, numberText(value))) in.fail(where, *fault);
      return s;
    };
    if (scale->is_number()) {
      const double s = factor(*scale, scalePath);
      transform.scale = {s, s, s};
    } else if (scale->is_array() && scale->size() == 3) {
      for (std::size_t i = 0; i < 3; ++i) transform.scale[i] = factor((*scale)[i], element(scalePath, i));
    } else {
      in.fail(scalePath, "expected a number or [sx, sy, sz]");
    }
    const auto [smallest, largest] = std::minmax({transform.scale[0], transform.scale[1], transform.scale[2]});
    if (const std::optional<std::string> fault = app::scaleRatioFault(smallest, largest)) in.fail(scalePath, *fault);
  }
  return transform;
}

// An object's or quad's "reflectivity" (default 1): the fraction of a lidar beam's light its surface
// returns, a Lambertian reflectance.
double readReflectivity(const Reader& in, const Json& json, const std::string& path) {
  const Json* value = in.optional(json, "reflectivity");
  if (value == nullptr) return 1;
  return in.numberIn(*value, child(path, "reflectivity"), 0, 1, "a reflectivity lies in [0, 1]");
}

SceneLight readLight(const Reader& in, const Json& json, const std::string& path) {
  if (!json.is_object()) in.fail(path, std::string("expected an object, found ") + json.type_name());
  const std::string type = in.string(in.required(json, path, "type"), child(path, "type"));
  SceneLight light;
  if (type == "point") {
    in.object(json, path, {"type", "position", "intensity"});
    light.type = LightType::point;
    light.position = in.position(in.required(json, path, "position"), child(path, "position"));
    light.intensity = rgb(in, in.required(json, path, "intensity"), child(path, "intensity"), kMaxLight);
  } else if (type == "sun") {
    in.object(json, path, {"type", "direction", "irradiance", "angle"});
    light.type = LightType::sun;
    light.direction = in.direction(in.required(json, path, "direction"), child(path, "direction"));
    light.irradiance = rgb(in, in.required(json, path, "irradiance"), child(path, "irradiance"), kMaxLight);
    if (const Json* angle = in.optional(json, "angle")) {
      light.angleDegrees =
          in.numberIn(*angle, child(path, "angle"), 0, 45, "the sun's apparent diameter lies in [0, 45] degrees");
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
    environment.color = rgb(in, *color, "environment.color", kMaxLight);
    return environment;
  }
  in.object(*sky, "environment.sky", {"zenith", "horizon"});
  environment.sky = true;
  environment.zenith = rgb(in, in.required(*sky, "environment.sky", "zenith"), "environment.sky.zenith", kMaxLight);
  environment.horizon = rgb(in, in.required(*sky, "environment.sky", "horizon"), "environment.sky.horizon", kMaxLight);
  return environment;
}

}  // namespace

// Names appear in the tools' one-line messages: a control character (a newline, say) would break
// the line, so it is refused where it is written.
void checkName(const Reader& in, std::string_view name, const std::string& path) {
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "%02X", byte);
      in.fail(path, "the name " + quotedText(name) + " holds a control character (byte 0x" + code +
                        "); names appear in one-line messages, so they may not");
    }
  }
}

namespace {

SceneDescription parseSceneText(std::string_view text, const std::string& file, const std::string& directory,
                                FileTexts* csvs) {
  const Reader in(file);
  const Json root = json::parse(text, in);
  in.object(
      root, "",
      {"description", "camera", "profiles", "materials", "objects", "object_tables", "quads", "lights", "environment"});
  SceneDescription scene;
  scene.file = file;
  if (const Json* description = in.optional(root, "description")) in.string(*description, "description");
  scene.camera = readCamera(in, in.required(root, "", "camera"));

  const Json& profiles = in.required(root, "", "profiles");
  if (!profiles.is_object())
    in.fail("profiles", std::string("expected an object of named profiles, found ") + profiles.type_name());
  // Each profile's checks and curve are its own: built in parallel, the first error in order reported.
  std::vector<std::pair<std::string, const Json*>> named;
  for (const auto& [name, value] : profiles.items()) {
    checkName(in, name, child("profiles", name));
    named.emplace_back(name, &value);
  }
  // A CSV is read (and kept in `csvs`) in order first: FileTexts is not for concurrent use.
  if (csvs != nullptr) {
    for (const auto& [name, value] : named) {
      if (const Json* csv = value->is_object() ? in.optional(*value, "csv") : nullptr; csv && csv->is_string()) {
        try {
          csvs->text((std::filesystem::path(directory) / csv->get<std::string>()).string(), kMaxCsvFileBytes,
                     "a CSV file");
        } catch (const InputError&) {  // reported below, in its profile's turn
        }
      }
    }
  }
  std::vector<std::optional<SceneProfile>> built(named.size());
  forEachInParallel(named.size(), [&](std::size_t i) {
    const auto& [name, value] = named[i];
    built[i].emplace(readProfile(in, name, *value, child("profiles", name), directory, csvs));
  });
  scene.profiles.reserve(built.size());
  for (std::optional<SceneProfile>& profile : built) scene.profiles.push_back(std::move(*profile));

  const Json& materials = in.required(root, "", "materials");
  if (!materials.is_object())
    in.fail("materials", std::string("expected an object of named materials, found ") + materials.type_name());
  for (const auto& [name, value] : materials.items()) {
    checkName(in, name, child("materials", name));
    scene.materials.push_back(readMaterial(in, name, value, child("materials", name)));
  }

  const Json& objects = in.array(in.required(root, "", "objects"), "objects");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string path = element("objects", i);
    const Json& json =
        in.object(objects[i], path, {"profile", "material", "translate", "rotate", "scale", "name", "reflectivity"});
    SceneObject object;
    object.profile = lookUp(in, scene.profiles, in.required(json, path, "profile"), child(path, "profile"), "profile");
    object.material =
        lookUp(in, scene.materials, in.required(json, path, "material"), child(path, "material"), "material");
    if (const Json* name = in.optional(json, "name")) {
      object.name = in.string(*name, child(path, "name"));
      checkName(in, object.name, child(path, "name"));
    }
    object.transform = readTransform(in, json, path);
    object.reflectivity = readReflectivity(in, json, path);
    // Hits on it must lie within the limit too: secondary rays start there. An exact spline is held
    // to its control points' reach, which bounds its curve's (boundingPoints): conservative, and no
    // polyline is drawn for it.
    const double reach =
        app::worldReach(boundingPoints(scene.profiles[object.profile]), app::Placement(object.transform));
    if (const std::optional<std::string> fault = app::reachFault(reach)) in.fail(path, *fault);
    scene.objects.push_back(std::move(object));
  }

  // Tables' objects follow the listed ones, table by table (io/object_table.h).
  if (const Json* tables = in.optional(root, "object_tables")) {
    in.array(*tables, "object_tables");
    for (std::size_t t = 0; t < tables->size(); ++t)
      readObjectTable(in, (*tables)[t], element("object_tables", t), directory, csvs, scene);
  }

  if (const Json* quads = in.optional(root, "quads")) {
    in.array(*quads, "quads");
    for (std::size_t i = 0; i < quads->size(); ++i) {
      const std::string path = element("quads", i);
      const Json& json = in.object((*quads)[i], path, {"corners", "material", "reflectivity"});
      SceneQuad quad;
      const Json& corners = in.required(json, path, "corners");
      if (!corners.is_array() || corners.size() != 4)
        in.fail(child(path, "corners"), "expected 4 corners [[x, y, z], ...]");
      for (std::size_t c = 0; c < 4; ++c) quad.corners[c] = in.position(corners[c], element(child(path, "corners"), c));
      // Both triangles must have an area, or Embree would drop them silently.
      for (const auto& [a, b] : {std::pair{1, 2}, std::pair{2, 3}}) {
        const Vec3d e1{quad.corners[a][0] - quad.corners[0][0], quad.corners[a][1] - quad.corners[0][1],
                       quad.corners[a][2] - quad.corners[0][2]};
        const Vec3d e2{quad.corners[b][0] - quad.corners[0][0], quad.corners[b][1] - quad.corners[0][1],
                       quad.corners[b][2] - quad.corners[0][2]};
        const Vec3d n = cross(e1, e2);
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
          in.fail(child(path, "corners"), "corners 0, " + std::to_string(a) + " and " + std::to_string(b) +
                                              " are collinear; a quad needs an area");
        }
      }
      quad.material =
          lookUp(in, scene.materials, in.required(json, path, "material"), child(path, "material"), "material");
      quad.reflectivity = readReflectivity(in, json, path);
      scene.quads.push_back(quad);
    }
  }

  if (const Json* lights = in.optional(root, "lights")) {
    in.array(*lights, "lights");
    for (std::size_t i = 0; i < lights->size(); ++i)
      scene.lights.push_back(readLight(in, (*lights)[i], element("lights", i)));
  }
  if (const Json* environment = in.optional(root, "environment")) scene.environment = readEnvironment(in, *environment);
  return scene;
}

}  // namespace

SceneProfile buildSceneProfile(const SceneReader& in, std::string name, const ProfileRecipe& recipe,
                               const ProfileSource& source) {
  const auto failAt = [&](const ProfileError& error) {
    if (error.index() >= source.points.size()) in.fail(source.path, error.what());
    // Points are named by their key path; a CSV's by its file and line, under the csv key.
    const std::string where = source.where(error.index());
    if (where.rfind(source.path, 0) == 0) in.fail(where, error.what());
    in.fail(source.path, where + ": " + error.what());
  };
  std::vector<std::string> warnings;
  if (recipe.kind == SplineKind::linear) {
    std::optional<Profile> built;
    try {
      built.emplace(source.points);
    } catch (const ProfileError& error) {
      failAt(error);
    }
    for (const ProfileWarning& warning : built->warnings()) {
      const std::string where = source.where(warning.index);
      warnings.push_back((where.rfind(source.path, 0) == 0 ? in.file() + ": " : "") + where + ": " + warning.message);
    }
    return {
        std::move(name), std::move(*built), recipe.creaseDegrees, std::move(warnings), source.file, std::nullopt, 0};
  }
  std::optional<Spline> spline;
  try {
    spline.emplace(recipe.kind, source.points);
  } catch (const ProfileError& error) {
    failAt(error);
  }
  const double tolerance = recipe.tolerance;
  if (tolerance <= 0) {
    // Traced exactly: its polyline is drawn only if a tool asks (SceneProfile::polyline; fromCurve
    // cannot refuse kDrawingFraction of the spline's own size, far above 2^-40 of its extent).
    return {std::move(name), std::nullopt, recipe.creaseDegrees, {}, source.file, spline, 0, spline};
  }
  std::optional<Profile> polyline;
  try {
    // A tolerance the user gave is held to the rule every tool applies (io/curve_tolerance.h).
    polyline.emplace(curvePolyline(*spline, tolerance));
  } catch (const std::invalid_argument& error) {
    in.fail(recipe.tolerancePath, error.what());
  }
  return {std::move(name), std::move(*polyline), recipe.creaseDegrees, {}, source.file, std::nullopt,
          tolerance,       std::move(spline)};
}

const Profile& SceneProfile::polyline() const {
  if (profile) return *profile;
  if (!spline) throw std::logic_error("SceneProfile \"" + name + "\" has neither a polyline nor a spline");
  std::call_once(drawing->once, [this] {
    double size = 0;
    for (const Point2& p : spline->bezier()) size = std::max({size, std::abs(p.r), std::abs(p.z)});
    drawing->polyline.emplace(Profile::fromCurve(*spline, kDrawingFraction * size));
  });
  return *drawing->polyline;
}

void drawPolylines(const SceneDescription& description) {
  tbb::parallel_for(std::size_t{0}, description.profiles.size(),
                    [&](std::size_t i) { (void)description.profiles[i].polyline(); });
}

std::span<const Point2> boundingPoints(const SceneProfile& profile) {
  return profile.profile ? profile.profile->points() : profile.spline->bezier();
}

void forEachInParallel(std::size_t count, const std::function<void(std::size_t)>& task) {
  std::vector<std::exception_ptr> errors(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
    try {
      task(i);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

SceneDescription parseScene(std::string_view text, const std::string& file, const std::string& directory) {
  return parseSceneText(text, file, directory, nullptr);
}

SceneDescription parseScene(std::string_view text, const std::string& file, const std::string& directory,
                            FileTexts& csvs) {
  return parseSceneText(text, file, directory, &csvs);
}

SceneDescription readScene(const std::string& path) {
  std::string text;
  try {
    text = readTextFile(path, kMaxJsonFileBytes, "a JSON file");
  } catch (const InputError& error) {
    throw SceneError(error.what());
  }
  return parseScene(text, path, std::filesystem::path(path).parent_path().string());
}

SceneDescription readScene(const std::string& path, std::string& text, FileTexts& csvs) {
  try {
    text = readTextFile(path, kMaxJsonFileBytes, "a JSON file");
  } catch (const InputError& error) {
    throw SceneError(error.what());
  }
  return parseScene(text, path, std::filesystem::path(path).parent_path().string(), csvs);
}

}  // namespace revolve::io
