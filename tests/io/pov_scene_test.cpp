// The POV-Ray exporter (io/pov_scene.h) in process: what it writes is read back with POV-Ray's
// documented semantics (the lathe revolves <r, y> about y; `matrix <v00 ... v32>` maps p to
// p.x v0 + p.y v1 + p.z v2 + v3; a light with fade_power 2 falls off as 2 / (1 + (d / f)^2)) and
// held against closed forms in revolve's own axes. tests/render/pov_round_trip_test.cpp renders
// the SDL with POV-Ray itself.
#include "io/pov_scene.h"
#include "io/scene_file.h"
#include "scratch_directory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

namespace revolve::io {
namespace {

using ::testing::HasSubstr;
using V3 = std::array<double, 3>;

const std::string kPointScene = R"({
  "camera": {"from": [0.5, -4, 1.5], "to": [0.2, 0, 0.6], "up": [0.1, 0, 1], "fov": 35},
  "profiles": {"pot": {"points": [[0, 0], [0.5, 0.2], [0.7, 0.9], [0.2, 1.3], [0, 1.4]]}},
  "materials": {
    "white": {"type": "diffuse", "color": [0.8, 0.7, 0.6]},
    "chrome": {"type": "mirror", "color": [0.9, 0.9, 0.9]},
    "glass": {"type": "glass", "ior": 1.45, "tint": [0.5, 0.8, 0.6]}
  },
  "objects": [
    {"profile": "pot", "material": "white", "translate": [1.5, -2, 0.25], "rotate": [1, 2, -0.5, 37], "scale": [0.5, 2, 1.5]},
    {"profile": "pot", "material": "glass"}
  ],
  "quads": [{"corners": [[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], "material": "chrome"}],
  "lights": [{"type": "point", "position": [-2, -3, 4], "intensity": [5, 4, 3]},
             {"type": "sun", "direction": [0.3, 0.4, -1], "irradiance": [1, 2, 3]}],
  "environment": {"color": [0.2, 0.25, 0.3]}
})";

std::vector<double> numbersIn(const std::string& text) {
  std::vector<double> values;
  static const std::regex number(R"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
    values.push_back(std::stod(it->str()));
  }
  return values;
}

// The text between `start` and the next `end` after it.
std::string between(const std::string& text, const std::string& start, const std::string& end, std::size_t from = 0) {
  const std::size_t a = text.find(start, from);
  if (a == std::string::npos) {
    ADD_FAILURE() << "no \"" << start << "\" in the SDL";
    return "";
  }
  const std::size_t b = text.find(end, a + start.size());
  return text.substr(a + start.size(), b - a - start.size());
}

V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Rodrigues' formula: v turned by `degrees` about unit axis k.
V3 rotated(const V3& v, const V3& k, double degrees) {
  const double t = degrees * std::numbers::pi / 180, c = std::cos(t), s = std::sin(t);
  const V3 kv = cross(k, v);
  const double kd = dot(k, v) * (1 - c);
  return {v[0] * c + kv[0] * s + k[0] * kd, v[1] * c + kv[1] * s + k[1] * kd, v[2] * c + kv[2] * s + k[2] * kd};
}

TEST(PovSceneTest, LathePointsLandWhereRevolvesSurfaceIsAfterTheAxisSwap) {
  const SceneDescription scene = parseScene(kPointScene, "scene.json", ".");
  const PovScene pov = povScene(scene, {});
  // The lathe's points are the profile's (r, z), unchanged.
  const std::vector<double> lathe = numbersIn(between(pov.text, "lathe {", "}"));
  ASSERT_EQ(lathe.size(), 1 + 2 * 5u) << "linear_spline N, then N points";
  EXPECT_EQ(lathe[0], 5);
  const std::vector<double> matrix = numbersIn(between(pov.text, "matrix <", ">"));
  ASSERT_EQ(matrix.size(), 12u);

  const V3 k = {1 / std::sqrt(5.25), 2 / std::sqrt(5.25), -0.5 / std::sqrt(5.25)}, s = {0.5, 2, 1.5},
           t = {1.5, -2, 0.25};
  double worst = 0;
  for (int p = 0; p < 5; ++p) {
    const double r = lathe[1 + 2 * p], z = lathe[2 + 2 * p];
    for (int step = 0; step < 12; ++step) {
      const double theta = 2 * std::numbers::pi * step / 12;
      // POV-Ray: the lathe's point at angle theta about y, then the matrix.
      const V3 q = {r * std::cos(theta), z, r * std::sin(theta)};
      V3 pov3;
      for (int j = 0; j < 3; ++j)
        pov3[j] = q[0] * matrix[j] + q[1] * matrix[3 + j] + q[2] * matrix[6 + j] + matrix[9 + j];
      // revolve: the surface point at azimuth theta, scaled, rotated, translated.
      const V3 local = rotated({s[0] * r * std::cos(theta), s[1] * r * std::sin(theta), s[2] * z}, k, 37);
      const V3 world = {local[0] + t[0], local[1] + t[1], local[2] + t[2]};
      const V3 back = {pov3[0], pov3[2], pov3[1]};  // POV-Ray's axes to revolve's
      for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(back[j] - world[j]));
    }
  }
  // Values below 5 in magnitude through a handful of double operations on each side.
  EXPECT_LT(worst, 1e-14);
  // The second object has no transform: the identity, at the origin.
  const std::size_t second = pov.text.find("objects[1]");
  ASSERT_NE(second, std::string::npos);
  const std::size_t line = pov.text.rfind("matrix <", second);
  EXPECT_EQ(numbersIn(between(pov.text, "matrix <", ">", line)),
            (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}));
}

// A spline traced exactly is exported as the same curve: POV-Ray's bezier_spline, four control
// points a piece (POV-Ray's pieces do not share their ends). A quadratic piece P0 P1 P2 is the
// cubic P0, P0 + 2/3 (P1 - P0), P2 + 2/3 (P1 - P2), P2 (degree elevation).
TEST(PovSceneTest, ASplineIsWrittenAsTheSameCurveInBezierPieces) {
  const std::string scene = std::regex_replace(
      kPointScene, std::regex(R"("pot": \{"points": [^}]*\})"),
      R"("pot": {"spline": "quadratic", "points": [[0, 0], [0.9, 0], [0.6, 0.6], [0.3, 1.2], [0, 1.2]]})");
  const PovScene pov = povScene(parseScene(scene, "scene.json", "."), {});
  EXPECT_THAT(pov.text, ::testing::Not(HasSubstr("linear_spline")));
  const std::vector<double> lathe = numbersIn(between(pov.text, "bezier_spline", "}"));
  ASSERT_EQ(lathe.size(), 1 + 2 * 8u) << "bezier_spline N, then N = 4 x 2 points";
  EXPECT_EQ(lathe[0], 8);
  const double q[2][3][2] = {{{0, 0}, {0.9, 0}, {0.6, 0.6}}, {{0.6, 0.6}, {0.3, 1.2}, {0, 1.2}}};
  for (int piece = 0; piece < 2; ++piece) {
    for (int c = 0; c < 2; ++c) {  // r, then z
      const double p0 = q[piece][0][c], p1 = q[piece][1][c], p2 = q[piece][2][c];
      const double expected[4] = {p0, p0 + 2.0 / 3 * (p1 - p0), p2 + 2.0 / 3 * (p1 - p2), p2};
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(lathe[1 + 2 * (4 * piece + k) + c], expected[k], 1e-15) << piece << " " << k << " " << c;
    }
  }
}

TEST(PovSceneTest, CameraAndLightsAreInPovRaysAxesAndLightUnits) {
  const SceneDescription scene = parseScene(kPointScene, "scene.json", ".");
  const PovScene pov = povScene(scene, {});
  EXPECT_TRUE(pov.warnings.empty()) << pov.warnings.front();
  EXPECT_EQ(numbersIn(between(pov.text, "location <", ">")), (std::vector<double>{0.5, 1.5, -4}));
  EXPECT_EQ(numbersIn(between(pov.text, "look_at <", ">")), (std::vector<double>{0.2, 0.6, 0}));
  // `up` (0.1, 0, 1) in POV-Ray's axes, (0.1, 1, 0), as the reader leaves it: of unit length.
  const std::vector<double> sky = numbersIn(between(pov.text, "sky <", ">"));
  ASSERT_EQ(sky.size(), 3u);
  const double upLength = std::hypot(0.1, 1.0);
  EXPECT_NEAR(sky[0], 0.1 / upLength, 1e-6);
  EXPECT_NEAR(sky[1], 1.0 / upLength, 1e-6);
  EXPECT_EQ(sky[2], 0.0);
  EXPECT_THAT(pov.text, HasSubstr("#declare Revolve_Vertical_Fov = 35;"));

  // The point light: POV-Ray's diffuse term, C * 2 / (1 + (d / f)^2) * cos * albedo with `diffuse
  // 1`, against revolve's Lambert, albedo / pi * I / d^2 * cos.
  const std::string light = between(pov.text, "// lights[0]", "}");
  const std::vector<double> position = numbersIn(between(light, "<", ">"));
  EXPECT_EQ(position, (std::vector<double>{-2, 4, -3}));
  const std::vector<double> colour = numbersIn(between(light, "rgb <", ">"));
  const std::vector<double> fade = numbersIn(between(light, "fade_distance", "\n"));
  ASSERT_EQ(colour.size(), 3u);
  ASSERT_EQ(fade.size(), 1u);
  EXPECT_THAT(light, HasSubstr("fade_power 2"));
  const double intensity[3] = {5, 4, 3};
  for (const double d : {0.5, 1.0, 3.0, 10.0}) {
    for (int c = 0; c < 3; ++c) {
      const double povray = colour[c] * 2 / (1 + (d / fade[0]) * (d / fade[0]));
      const double revolve = intensity[c] / (std::numbers::pi * d * d);
      EXPECT_NEAR(povray / revolve, 1, 1e-6) << "d = " << d;  // (f / d)^2 with f = 1e-4 of the extent 5
    }
  }
  // The sun: parallel, from far along -direction, its irradiance over pi.
  const std::string sun = between(pov.text, "// lights[1]", "}");
  EXPECT_THAT(sun, HasSubstr("parallel"));
  const std::vector<double> from = numbersIn(between(sun, "<", ">"));
  const std::vector<double> sunColour = numbersIn(between(sun, "rgb <", ">"));
  ASSERT_EQ(from.size(), 3u);
  const V3 towardsSun = {-0.3, 1, -0.4};  // -direction, in POV-Ray's axes
  const double n = std::sqrt(dot(towardsSun, towardsSun)),
               length = std::sqrt(from[0] * from[0] + from[1] * from[1] + from[2] * from[2]);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(from[j] / length, towardsSun[j] / n, 1e-12);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sunColour[c], (c + 1) / std::numbers::pi, 1e-15);
  // The uniform environment is both the background and the ambient light.
  EXPECT_EQ(numbersIn(between(pov.text, "background { rgb <", ">")), (std::vector<double>{0.2, 0.25, 0.3}));
  EXPECT_EQ(numbersIn(between(pov.text, "ambient_light rgb <", ">")), (std::vector<double>{0.2, 0.25, 0.3}));
  // Materials: glass's ior and tint as a filter, the mirror's colour as its reflection.
  EXPECT_THAT(pov.text, HasSubstr("rgbf <0.5, 0.8, 0.6, 1>"));
  EXPECT_THAT(pov.text, HasSubstr("ior 1.45"));
  EXPECT_THAT(pov.text, HasSubstr("reflection { rgb <0.9, 0.9, 0.9> }"));
  // The quad as two triangles (0, 1, 2) and (0, 2, 3), axes swapped.
  EXPECT_THAT(pov.text, HasSubstr("triangle { <-5, 0, -5>, <5, 0, -5>, <5, 0, 5> }"));
  EXPECT_THAT(pov.text, HasSubstr("triangle { <-5, 0, -5>, <5, 0, 5>, <-5, 0, 5> }"));
}

TEST(PovSceneTest, WhatDoesNotMapIsWrittenAsTheNearestAndNamed) {
  std::string text = kPointScene;
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace(R"("irradiance": [1, 2, 3])", R"("irradiance": [1, 2, 3], "angle": 2)");
  replace(R"({"type": "mirror", "color": [0.9, 0.9, 0.9]})",
          R"({"type": "metal", "color": [0.9, 0.9, 0.9], "roughness": 0.3})");
  replace(R"({"color": [0.2, 0.25, 0.3]})", R"({"sky": {"zenith": [0, 0, 1], "horizon": [1, 1, 1]}})");
  const PovScene pov = povScene(parseScene(text, "scene.json", "."), {});
  ASSERT_EQ(pov.warnings.size(), 3u);
  EXPECT_THAT(pov.warnings[0], HasSubstr("environment.sky"));
  EXPECT_THAT(pov.warnings[1], HasSubstr("lights[1]: a sun of apparent diameter 2 degrees"));
  EXPECT_THAT(pov.warnings[2], HasSubstr("materials.chrome: metal of roughness 0.3"));
  // Each is also a comment in the file, and the nearest POV-Ray form is written.
  EXPECT_THAT(pov.text, HasSubstr("//   materials.chrome: metal"));
  EXPECT_THAT(pov.text, HasSubstr("sky_sphere"));
  EXPECT_EQ(numbersIn(between(pov.text, "ambient_light rgb <", ">")), (std::vector<double>{0.75, 0.75, 1}));
}

std::string sceneWithPoints(std::size_t points) {
  std::string list;
  for (std::size_t i = 0; i < points; ++i) {
    // A wavy wall, strictly rising: a valid profile of any length.
    if (i > 0) list += ",";
    list.append("[")
        .append(std::to_string(1 + 0.1 * std::sin(0.01 * double(i))))
        .append(",")
        .append(std::to_string(i))
        .append("]");
  }
  return R"({"camera": {"from": [0, -9, 1], "to": [0, 0, 0], "up": [0, 0, 1], "fov": 40},
    "profiles": {"big": {"points": [)" +
         list + R"(]}},
    "materials": {"white": {"type": "diffuse", "color": [0.8, 0.8, 0.8]}},
    "objects": [{"profile": "big", "material": "white"}]})";
}

TEST(PovSceneTest, LathesBeyondPovRaysLimitAreRefusedAndNothingIsWritten) {
  const SceneDescription atLimit = parseScene(sceneWithPoints(kPovMaxLathePoints), "scene.json", ".");
  EXPECT_THAT(povScene(atLimit, {}).text, HasSubstr("linear_spline 32767,"));

  const SceneDescription beyond = parseScene(sceneWithPoints(kPovMaxLathePoints + 1), "scene.json", ".");
  const testing::ScratchDirectory dir;
  try {
    writePovScene(dir / "scene.pov", beyond, {});
    ADD_FAILURE() << "a 32,768-point lathe was written";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              "scene.json: profiles.big: 32768 points: a POV-Ray lathe holds at most 32767 (its point count is a "
              "16-bit integer)");
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PovSceneTest, DepthAndShadowsAreDefaultsThatPovRaysCommandLineCanOverride) {
  const SceneDescription scene = parseScene(kPointScene, "scene.json", ".");
  const PovScene pov = povScene(scene, {2, false});
  EXPECT_THAT(pov.text, HasSubstr("#ifndef (Revolve_Depth) #declare Revolve_Depth = 2; #end"));
  EXPECT_THAT(pov.text, HasSubstr("#ifndef (Revolve_Shadows) #declare Revolve_Shadows = 0; #end"));
  EXPECT_THAT(pov.text, HasSubstr("max_trace_level Revolve_Depth"));
  EXPECT_THAT(pov.text, HasSubstr("#if (!Revolve_Shadows) shadowless #end"));
}

}  // namespace
}  // namespace revolve::io
