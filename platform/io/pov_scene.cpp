#include "io/pov_scene.h"

#include "geometry/placement.h"
#include "io/output_set.h"
#include "io/text_files.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

namespace revolve::io {
namespace {

constexpr double kPi = std::numbers::pi;

// Shortest text that reads back as the same double: POV-Ray parses doubles, so nothing is rounded.
std::string number(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (error != std::errc()) throw std::runtime_error("cannot format a number");
  return std::string(buffer, end);
}

// revolve's (x, y, z) in POV-Ray's axes: y and z swapped (see the header).
Vec3d toPov(const Vec3d& v) { return {v[0], v[2], v[1]}; }

std::string vector(const Vec3d& v) {
  std::string text = "<";
  return text.append(number(v[0])).append(", ").append(number(v[1])).append(", ").append(number(v[2])).append(">");
}
std::string povVector(const Vec3d& v) { return vector(toPov(v)); }
std::string colour(const Rgb& c, double scale = 1) {
  return "rgb " + vector({c[0] * scale, c[1] * scale, c[2] * scale});
}

// POV-Ray's `matrix <v00, v01, v02, v10, ..., v32>` maps a point p to (p.x v0* + p.y v1* + p.z v2* +
// v3*): row i is the image of POV-Ray's basis vector i. With the axis swap P (its own inverse), the
// object's map in POV-Ray's axes is P M P.
std::string povMatrix(const app::Transform& transform) {
  const app::Matrix3d m = app::linearPart(transform);
  constexpr int swap[3] = {0, 2, 1};
  std::string text = "matrix <";
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) text += number(m[swap[column]][swap[row]]) + ", ";
  }
  const Vec3d t = toPov(transform.translate);
  return text + number(t[0]) + ", " + number(t[1]) + ", " + number(t[2]) + ">";
}

// The largest coordinate magnitude of the scene's placed things: sets the light fall-off's scale.
double sceneExtent(const SceneDescription& scene) {
  double extent = 0;
  const auto grow = [&](const Vec3d& v) {
    for (const double x : v) extent = std::max(extent, std::abs(x));
  };
  grow(scene.camera.from);
  grow(scene.camera.to);
  for (const SceneObject& object : scene.objects) grow(object.transform.translate);
  for (const SceneQuad& quad : scene.quads) {
    for (const Vec3d& corner : quad.corners) grow(corner);
  }
  for (const SceneLight& light : scene.lights) {
    if (light.type == LightType::point) grow(light.position);
  }
  return extent > 0 ? extent : 1;
}

std::string identifier(const char* kind, std::size_t index) {
  return std::string("Revolve_") + kind + "_" + std::to_string(index);
}

// A comment line holding a name from the scene file: no line breaks can end the comment early.
std::string commentText(const std::string& text) {
  std::string out = text;
  std::replace(out.begin(), out.end(), '\n', ' ');
  std::replace(out.begin(), out.end(), '\r', ' ');
  return out;
}

class Writer {
 public:
  Writer(const SceneDescription& scene, const PovDefaults& defaults) : scene_(scene), defaults_(defaults) {}

  PovScene write() {
    checkLatheLimits();
    std::ostringstream body;
    globals(body);
    camera(body);
    lights(body);
    materials(body);
    lathes(body);
    objects(body);
    quads(body);
    std::ostringstream head;
    head << "// " << commentText(scene_.file) << " as POV-Ray 3.7 SDL, written by revolve-render --export-pov.\n"
         << "// POV-Ray's y is revolve's z (up) and its z is revolve's y: the swap makes revolve's right-handed\n"
         << "// z-up world POV-Ray's left-handed y-up one without mirroring the picture. The image size comes\n"
         << "// from +W +H; for revolve's whitted integrator at one sample a pixel:\n"
         << "//   povray +I"
         << "scene.pov +Oimage.exr +FE +W640 +H480 -A File_Gamma=1.0\n"
         << "//   [Declare=Revolve_Depth=D (whitted's --depth)] [Declare=Revolve_Shadows=0 (--no-shadows)]\n";
    if (!warnings_.empty()) {
      head << "// Approximated (no POV-Ray equivalent):\n";
      for (const std::string& warning : warnings_) head << "//   " << commentText(warning) << "\n";
    }
    head << "#version 3.7;\n\n";
    return {head.str() + body.str(), warnings_};
  }

 private:
  void checkLatheLimits() const {
    for (const std::size_t p : usedProfiles()) {
      const SceneProfile& profile = scene_.profiles[p];
      const std::size_t points = lathePointCount(profile);
      if (points > kPovMaxLathePoints) {
        throw SceneError(scene_.file + ": profiles." + profile.name + ": " + std::to_string(points) +
                         (profile.spline ? " points (its bezier_spline, four a piece)" : " points") +
                         ": a POV-Ray lathe holds at most 32767 (its point count is a 16-bit integer)");
      }
    }
  }

  // A spline traced exactly is written as the same curve, POV-Ray's bezier_spline (four points a
  // piece, neighbours repeating their shared end); every other profile as its polyline.
  static std::size_t lathePointCount(const SceneProfile& profile) {
    return profile.spline ? 4 * profile.spline->pieceCount() : profile.polyline().points().size();
  }

  std::set<std::size_t> usedProfiles() const {
    std::set<std::size_t> used;
    for (const SceneObject& object : scene_.objects) used.insert(object.profile);
    return used;
  }

  void globals(std::ostream& out) {
    out << "#ifndef (Revolve_Depth) #declare Revolve_Depth = " << defaults_.depth << "; #end\n"
        << "#ifndef (Revolve_Shadows) #declare Revolve_Shadows = " << (defaults_.shadows ? 1 : 0) << "; #end\n\n";
    // Whitted's ambient term is the albedo times the environment seen along the normal: a uniform
    // environment is exactly POV-Ray's ambient light (finish ambient 1 on diffuse surfaces).
    const SceneEnvironment& environment = scene_.environment;
    Rgb ambient = environment.color;
    if (environment.sky) {
      // Over normals spread evenly on the sphere, max(0, n_up) averages 1/4.
      for (int i = 0; i < 3; ++i) ambient[i] = 0.75 * environment.horizon[i] + 0.25 * environment.zenith[i];
      warnings_.push_back(
          "environment.sky: the ambient term along each normal has no POV-Ray equivalent; "
          "ambient_light is the sky's mean over all normals (3/4 horizon + 1/4 zenith); "
          "rays that escape see the sky exactly (a sky_sphere)");
    }
    // adc_bailout 0: POV-Ray would otherwise drop rays whose weight falls below 1/255, which
    // revolve's whitted never does.
    out << "global_settings {\n  assumed_gamma 1.0\n  max_trace_level Revolve_Depth\n  adc_bailout 0\n"
        << "  ambient_light " << colour(ambient) << "\n}\n"
        << "#default { finish { ambient 0 diffuse 0 } }\n";
    if (environment.sky) {
      // The radiance blends linearly with the direction's height, the horizon's below it.
      out << "sky_sphere { pigment { function { min(1, max(0, y)) } color_map { [0 " << colour(environment.horizon)
          << "] [1 " << colour(environment.zenith) << "] } } }\n\n";
    } else {
      out << "background { " << colour(environment.color) << " }\n\n";
    }
  }

  void camera(std::ostream& out) const {
    const SceneCamera& c = scene_.camera;
    // POV-Ray's `angle` is horizontal: tan(h / 2) = tan(v / 2) * width / height.
    out << "#declare Revolve_Vertical_Fov = " << number(c.fovDegrees) << ";\n"
        << "camera {\n  perspective\n  location " << povVector(c.from) << "\n  sky " << povVector(c.up)
        << "\n  up y\n  right x * image_width / image_height\n"
        << "  angle 2 * degrees(atan(tan(radians(Revolve_Vertical_Fov / 2)) * image_width / image_height))\n"
        << "  look_at " << povVector(c.to) << "\n}\n\n";
  }

  void lights(std::ostream& out) {
    // POV-Ray's fall-off is 2 / (1 + (d / f)^2) for fade_distance f and fade_power 2: f^2 * 2 / d^2
    // times 1 / (1 + (f / d)^2). With f = 1e-4 of the scene's extent, that last factor differs from 1
    // by less than 1e-4 wherever d exceeds 1% of the extent. Lambert's 1 / pi goes into the colour,
    // so that `diffuse 1` with the albedo as pigment gives revolve's albedo / pi * I / d^2 * cos.
    const double fade = 1e-4 * sceneExtent(scene_);
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const SceneLight& light = scene_.lights[i];
      out << "// lights[" << i << "]\n";
      if (light.type == LightType::point) {
        out << "light_source {\n  " << povVector(light.position) << "\n  "
            << colour(light.intensity, 1 / (2 * kPi * fade * fade)) << "\n  fade_distance " << number(fade)
            << "\n  fade_power 2\n";
      } else {
        // A parallel light from far outside the scene: every point sees the same direction.
        const double far = 1e3 * sceneExtent(scene_);
        const Vec3d from{-light.direction[0] * far, -light.direction[1] * far, -light.direction[2] * far};
        out << "light_source {\n  " << povVector(from) << "\n  " << colour(light.irradiance, 1 / kPi)
            << "\n  parallel\n  point_at <0, 0, 0>\n";
        if (light.angleDegrees > 0) {
          warnings_.push_back("lights[" + std::to_string(i) + "]: a sun of apparent diameter " +
                              number(light.angleDegrees) +
                              " degrees has soft shadows in revolve; POV-Ray's parallel light casts hard ones (an area "
                              "light would need many shadow rays a point)");
        }
      }
      out << "  #if (!Revolve_Shadows) shadowless #end\n}\n";
    }
    out << "\n";
  }

  void materials(std::ostream& out) {
    for (std::size_t i = 0; i < scene_.materials.size(); ++i) {
      const SceneMaterial& m = scene_.materials[i];
      out << "// materials." << commentText(m.name) << "\n#declare " << identifier("Material", i) << " = material {\n";
      switch (m.type) {
        case MaterialType::diffuse:
          out << "  texture { pigment { " << colour(m.color) << " } finish { ambient 1 diffuse 1 } }\n";
          break;
        case MaterialType::mirror:
          out << "  texture { pigment { rgb 0 } finish { reflection { " << colour(m.color) << " } } }\n";
          break;
        case MaterialType::glass:
          // Fresnel reflection, the rest transmitted (conserve_energy) and filtered by the tint at
          // each crossing of the surface, as revolve's glass.
          out << "  texture { pigment { rgbf <" << number(m.tint[0]) << ", " << number(m.tint[1]) << ", "
              << number(m.tint[2]) << ", 1> } finish { reflection { 0, 1 fresnel on } conserve_energy } }\n"
              << "  interior { ior " << number(m.ior) << " }\n";
          break;
        case MaterialType::metal:
          // The mirror part (Schlick's Fresnel at normal incidence is the colour) and, for the
          // microfacet lobe, POV-Ray's Blinn highlight tinted by the colour.
          out << "  texture { pigment { " << colour(m.color) << " } finish { reflection { " << colour(m.color)
              << " } specular 1 metallic roughness " << number(std::max(m.roughness * m.roughness, 0.0005)) << " } }\n";
          warnings_.push_back("materials." + m.name + ": metal of roughness " + number(m.roughness) +
                              " has no POV-Ray equivalent (no microfacet lobe); written as a mirror of its colour with "
                              "a Blinn highlight");
          break;
      }
      out << "}\n";
    }
    out << "\n";
  }

  void lathes(std::ostream& out) const {
    for (const std::size_t p : usedProfiles()) {
      const SceneProfile& profile = scene_.profiles[p];
      out << "// profiles." << commentText(profile.name) << "\n#declare " << identifier("Profile", p) << " = lathe {\n";
      const auto point = [&](Point2 q) { out << ",\n  <" << number(q.r) << ", " << number(q.z) << ">"; };
      if (profile.spline) {
        const auto bezier = profile.spline->bezier();
        out << "  bezier_spline " << lathePointCount(profile);
        for (std::size_t piece = 0; piece < profile.spline->pieceCount(); ++piece) {
          for (std::size_t k = 0; k < 4; ++k) point(bezier[3 * piece + k]);
        }
      } else {
        const auto points = profile.polyline().points();
        out << "  linear_spline " << points.size();
        for (const Point2& q : points) point(q);
      }
      out << "\n}\n";
    }
    out << "\n";
  }

  void objects(std::ostream& out) const {
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const SceneObject& object = scene_.objects[i];
      out << "object { " << identifier("Profile", object.profile) << " material { "
          << identifier("Material", object.material) << " } " << povMatrix(object.transform) << " }  // objects[" << i
          << "]" << (object.name.empty() ? "" : " ") << commentText(object.name) << "\n";
    }
    out << "\n";
  }

  void quads(std::ostream& out) const {
    for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
      bool any = false;
      for (std::size_t i = 0; i < scene_.quads.size(); ++i) {
        const SceneQuad& quad = scene_.quads[i];
        if (quad.material != m) continue;
        if (!any) out << "mesh {  // the quads of materials." << commentText(scene_.materials[m].name) << "\n";
        any = true;
        const auto& c = quad.corners;
        out << "  triangle { " << povVector(c[0]) << ", " << povVector(c[1]) << ", " << povVector(c[2])
            << " }  // quads[" << i << "]\n"
            << "  triangle { " << povVector(c[0]) << ", " << povVector(c[2]) << ", " << povVector(c[3]) << " }\n";
      }
      if (any) out << "  material { " << identifier("Material", m) << " }\n}\n";
    }
  }

  const SceneDescription& scene_;
  PovDefaults defaults_;
  std::vector<std::string> warnings_;
};

}  // namespace

PovScene povScene(const SceneDescription& scene, const PovDefaults& defaults) {
  return Writer(scene, defaults).write();
}

std::vector<std::string> writePovScene(const std::string& path, const SceneDescription& scene,
                                       const PovDefaults& defaults) {
  const PovScene pov = povScene(scene, defaults);
  writeFileAtomically(path, [&](std::FILE* out) {
    if (std::fwrite(pov.text.data(), 1, pov.text.size(), out) != pov.text.size())
      throw std::runtime_error("short write");
  });
  return pov.warnings;
}

}  // namespace revolve::io
