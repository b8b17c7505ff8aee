// The scene file: JSON describing a camera, profiles, materials, objects of revolution, quads,
// lights and an environment (README.md, "Scene format"). An interface other tools write and read
// (revolve-render now; the lidar and clearance tools later), so the reader returns a plain
// description with everything validated and every name resolved to an index; building Embree
// objects from it is platform/scene's job.
//
// The reader is strict: a missing or unknown key, a wrong type, an unknown name, a bad profile or
// an unreadable profile CSV is a SceneError naming the file, the key path
// (`objects[12].profile: no profile named "botle"`), the value and the rule, on one line. Positions
// (and every placed object's reach) lie within the coordinate limit and scale factors within the
// range of geometry/ray_limits.h (the placement rule, geometry/placement.h), so that no ray the tools trace breaks
// Embree's contract.
#pragma once

#include "geometry/placement.h"
#include "geometry/vec3d.h"
#include "io/input_file.h"

#include <revolve/revolve.h>

#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace revolve::io {

class SceneError : public std::runtime_error {
 public:
  explicit SceneError(const std::string& message) : std::runtime_error(message) {}
};

using app::Vec3d;
using Rgb = std::array<double, 3>;  // linear RGB

struct SceneCamera {
  Vec3d from{}, to{}, up{};
  double fovDegrees = 0;                  // vertical field of view, in (0, 180)
  std::optional<int> width, height, spp;  // defaults for the renderer's options
};

struct SceneProfile {
  // The fraction of a spline's size (its largest coordinate) within which polyline() follows a
  // curve traced exactly: fine enough that the tools drawing or meshing it do not show it.
  static constexpr double kDrawingFraction = 1e-5;

  std::string name;
  // The polyline traced: the points of a linear profile; for a spline with a "tolerance", the curve
  // as Profile::fromCurve samples it within that tolerance. Empty for a spline traced exactly, which
  // needs none to be traced: polyline() draws one for the tools that do (meshes, plots).
  std::optional<Profile> profile{};
  double creaseDegrees = ShadingNormals::kDefaultCreaseDegrees;  // for smooth shading normals
  std::vector<std::string> warnings{};                           // "where: message" for each point the Profile dropped
  std::string csvFile{};           // the CSV it was read from, as opened; empty for inline points
  std::optional<Spline> spline{};  // a curved "spline" without a "tolerance": traced exactly
  double tolerance = 0;            // the "tolerance" given, or 0
  // The curve the polyline was made from (a curved "spline", with or without a "tolerance"): tools
  // shading its polyline take the curve's own normals (ShadingNormals(polyline(), *curve)).
  std::optional<Spline> curve{};

  // The polyline: `profile`, or for a spline traced exactly, Profile::fromCurve(*spline,
  // kDrawingFraction * size), drawn on the first call (from any thread) and kept. Reading a scene of
  // a million exact splines then costs no drawing the exact build never looks at.
  const Profile& polyline() const;

  // An exact spline's drawn polyline, shared by the copies of its SceneProfile (the spline they
  // hold is the same). A std::once_flag is neither copyable nor movable, hence the pointer.
  struct Drawing {
    std::once_flag once;
    std::optional<Profile> polyline;
  };
  std::shared_ptr<Drawing> drawing = std::make_shared<Drawing>();
};

// The points whose box holds every point of `profile`'s curve: the polyline's points, or for a
// spline traced exactly its Bezier control points (each piece lies in the hull of its control
// points), so that a reach check needs no drawing.
std::span<const Point2> boundingPoints(const SceneProfile& profile);

enum class MaterialType { diffuse, metal, mirror, glass };

struct SceneMaterial {
  std::string name;
  MaterialType type = MaterialType::diffuse;
  Rgb color{1, 1, 1};    // diffuse albedo, metal and mirror reflectance; each in [0, 1]
  double roughness = 0;  // metal: GGX alpha = roughness^2, in [0, 1]
  double ior = 1.5;      // glass: index of refraction, in [1, 4]
  Rgb tint{1, 1, 1};     // glass: transmittance a crossing of its surface keeps, in [0, 1]
};

struct SceneObject {
  std::string name;          // empty unless given
  std::size_t profile = 0;   // index into SceneDescription::profiles
  std::size_t material = 0;  // index into SceneDescription::materials
  app::Transform transform;  // object to world, its scale factors held to the placement rule
  double reflectivity = 1;   // what a lidar's return keeps, in [0, 1] (robot/lidar.h: intensity)
};

struct SceneQuad {
  std::array<Vec3d, 4> corners{};  // in order around the quad; drawn as triangles (0, 1, 2), (0, 2, 3)
  std::size_t material = 0;
  double reflectivity = 1;  // as SceneObject's
};

enum class LightType { point, sun };

struct SceneLight {
  LightType type = LightType::point;
  Vec3d position{};         // point
  Rgb intensity{};          // point: radiant intensity, W/sr per channel
  Vec3d direction{};        // sun: the direction the light travels (towards the ground), unit length
  Rgb irradiance{};         // sun: irradiance on a surface facing it
  double angleDegrees = 0;  // sun: apparent diameter, in [0, 45]; 0 = hard shadows
};

struct SceneEnvironment {
  bool sky = false;         // false: uniform `color`
  Rgb color{0, 0, 0};       // uniform radiance
  Rgb zenith{}, horizon{};  // sky: radiance straight up and at the horizon (and below it)
};

struct SceneDescription {
  std::string file;  // as given to readScene
  SceneCamera camera;
  std::vector<SceneProfile> profiles;
  std::vector<SceneMaterial> materials;
  std::vector<SceneObject> objects;
  std::vector<SceneQuad> quads;
  std::vector<SceneLight> lights;
  SceneEnvironment environment;
};

// Draws every exact spline's polyline (SceneProfile::polyline) on TBB's threads: for a tool about to
// ask for all of them one after another.
void drawPolylines(const SceneDescription& description);

// Parses scene JSON `text`; `file` names it in messages and profile CSVs resolve against
// `directory`. Throws SceneError.
SceneDescription parseScene(std::string_view text, const std::string& file, const std::string& directory);
// The same, each profile CSV's text taken from (or, as it is read, kept in) `csvs`, by its path as
// opened (`directory` / the name the scene gives): a scene rebuilt from texts alone, its messages
// still naming the files.
SceneDescription parseScene(std::string_view text, const std::string& file, const std::string& directory,
                            FileTexts& csvs);
// Reads and parses the file at `path` (CSVs relative to its folder). Throws SceneError.
SceneDescription readScene(const std::string& path);
// The same, keeping the scene file's text in `text` and every CSV's in `csvs`.
SceneDescription readScene(const std::string& path, std::string& text, FileTexts& csvs);

}  // namespace revolve::io
