// Bad scene files and options for revolve-render, shared by the in-process reader test (every
// scene case) and the process test (one case of each kind the tool must refuse, and the options).
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

namespace revolve::testing {

// A small valid scene: an inline profile and one from a CSV beside it.
inline const std::string kScene = R"({
  "camera": {"from": [0, -3, 1], "to": [0, 0, 0.5], "up": [0, 0, 1], "fov": 40, "width": 8, "height": 6, "spp": 2},
  "profiles": {
    "ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]},
    "bottle": {"csv": "bottle.csv"}
  },
  "materials": {"white": {"type": "diffuse", "color": [0.8, 0.8, 0.8]}},
  "objects": [
    {"profile": "ball", "material": "white"},
    {"profile": "bottle", "material": "white", "translate": [1, 0, 0], "rotate": [1, 0, 0, 10], "scale": 0.5}
  ],
  "quads": [{"corners": [[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], "material": "white"}],
  "lights": [{"type": "sun", "direction": [0, 0.3, -1], "irradiance": [1, 1, 1]}],
  "environment": {"color": [0.2, 0.2, 0.2]}
})";
inline const std::string kBottleCsv = "r,z\n0,0\n0.3,0\n0.3,0.6\n0.1,0.8\n0.1,1\n0,1\n";

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// A valid profile CSV of `points` points: a gently wavy wall, strictly rising.
inline std::string longProfileCsv(int points) {
  std::string csv = "r,z\n";
  for (int i = 0; i < points; ++i) csv += std::to_string(0.3 + 0.01 * (i % 7)) + "," + std::to_string(i * 1e-3) + "\n";
  return csv;
}

struct BadCase {
  const char* name;
  std::string scene;                   // the scene file's text
  std::vector<std::string> extraArgs;  // after the scene; "-o old.png" unless they name an output
  std::string expected;                // a substring of the one stderr line
  std::string csv = kBottleCsv;        // bottle.csv's text ("" = no file)
  bool process = false;                // also run as a process (one case of each kind, and the options)
};

// How GoogleTest prints a case (its name, rather than its bytes, in test listings).
inline void PrintTo(const BadCase& bad, std::ostream* out) { *out << bad.name; }

inline std::vector<BadCase> badCases() {
  return {
      {"MissingKey",
       replaced(kScene, R"("fov": 40, )", ""),
       {},
       R"(scene.json: camera: missing key "fov")",
       kBottleCsv,
       true},
      {"WrongType",
       replaced(kScene, R"("fov": 40)", R"("fov": "wide")"),
       {},
       "scene.json: camera.fov: expected a number, found string",
       kBottleCsv,
       true},
      {"UnknownProfileName",
       replaced(kScene, R"("profile": "bottle")", R"("profile": "botle")"),
       {},
       R"(scene.json: objects[1].profile: no profile named "botle")",
       kBottleCsv,
       true},
      {"UnknownMaterialName",
       replaced(kScene, R"("profile": "ball", "material": "white")", R"("profile": "ball", "material": "paper")"),
       {},
       R"(objects[0].material: no material named "paper")"},
      {"UnknownKey",
       replaced(kScene, R"("color": [0.8, 0.8, 0.8])", R"("colour": [0.8, 0.8, 0.8])"),
       {},
       "materials.white.colour: unknown key; expected one of: type, color",
       kBottleCsv,
       true},
      {"UnknownTopLevelKey", replaced(kScene, R"("lights")", R"("lightz")"), {}, "scene.json: lightz: unknown key"},
      {"SelfIntersectingProfile",
       replaced(kScene, "[0.5, 0.8], [0, 1]", "[0.5, 0.8], [0.7, 0.1], [0, 1]"),
       {},
       "profiles.ball.points[1]: the segment from profile point 1",
       kBottleCsv,
       true},
      {"NegativeRadius",
       replaced(kScene, "[0.5, 0.2]", "[-0.5, 0.2]"),
       {},
       "profiles.ball.points[1]: profile point 1 (r = -0.5"},
      {"BadCsvLine",
       kScene,
       {},
       "profiles.bottle.csv: bottle.csv:3: r = \"abc\" is not a number",
       "r,z\n0,0\nabc,0\n0,1\n"},
      {"MissingCsv", kScene, {}, "profiles.bottle.csv: bottle.csv: cannot open", "", true},
      {"BadCsvProfile",
       kScene,
       {},
       "profiles.bottle.csv: bottle.csv:3: profile point 1 (r = -1",
       "r,z\n0,0\n-1,0\n0,1\n"},
      {"InvalidJson", kScene.substr(0, 200), {}, "scene.json: not valid JSON: parse error at line", kBottleCsv, true},
      {"RepeatedKey",
       replaced(kScene, R"("fov": 40)", R"("fov": 40, "fov": 50)"),
       {},
       "scene.json: camera.fov: the key appears twice in its object"},
      {"UnknownMaterialType",
       replaced(kScene, R"("type": "diffuse")", R"("type": "plastic")"),
       {},
       R"(materials.white.type: "plastic" is not a material type)"},
      {"ReflectanceAboveOne",
       replaced(kScene, "[0.8, 0.8, 0.8]", "[1.5, 0.8, 0.8]"),
       {},
       "materials.white.color[0]: 1.5 is out of range: a reflectance lies in [0, 1]"},
      {"ZeroRotationAxis",
       replaced(kScene, "[1, 0, 0, 10]", "[0, 0, 0, 10]"),
       {},
       "objects[1].rotate: the rotation axis is zero"},
      {"NegativeScale",
       replaced(kScene, R"("scale": 0.5)", R"("scale": -0.5)"),
       {},
       "objects[1].scale: -0.5 is not positive"},
      {"DegenerateQuad",
       replaced(kScene, "[5, 5, 0], [-5, 5, 0]", "[5, -5, 0], [-5, 5, 0]"),
       {},
       "quads[0].corners: corners 0, 1 and 2 are collinear"},
      {"UpAlongTheView",
       replaced(kScene, R"("up": [0, 0, 1])", R"("up": [0, 3, -0.5])"),
       {},
       "camera.up: is parallel to the view direction"},
      {"UnknownLightType",
       replaced(kScene, R"("type": "sun")", R"("type": "spot")"),
       {},
       R"(lights[0].type: "spot" is not a light type)"},
      {"SunAngleTooWide",
       replaced(kScene, R"("irradiance": [1, 1, 1])", R"("irradiance": [1, 1, 1], "angle": 90)"),
       {},
       "lights[0].angle: 90 is out of range"},
      {"ObjectsNotAList", replaced(kScene, R"("objects": [)", R"("objects": {"a": )"), {}, "not valid JSON"},
      // Embree's ray contract (common/ray_limits.h): far positions and scales that would carry rays
      // beyond it are refused by key path and limit; the messages name the rule actually broken.
      // (tests/hostile runs revolve-render on these and on the options' refusals, in one test.)
      {"FarCamera",
       replaced(kScene, R"("from": [0, -3, 1])", R"("from": [1e20, -3, 1])"),
       {},
       "scene.json: camera.from[0]: 1e+20 is beyond the coordinate limit: positions lie within +-2^40 (1.1e12)"},
      {"CameraAt1e300IsFarNotParallel",
       replaced(kScene, R"("from": [0, -3, 1])", R"("from": [0, -3, 1e300])"),
       {},
       "camera.from[2]: 1e+300 is beyond the coordinate limit"},
      {"FarQuadCorner",
       replaced(kScene, "[-5, -5, 0]", "[-5e12, -5, 0]"),
       {},
       "quads[0].corners[0][0]: -5e+12 is beyond the coordinate limit"},
      {"FarTranslation",
       replaced(kScene, R"("translate": [1, 0, 0])", R"("translate": [1, 2e12, 0])"),
       {},
       "objects[1].translate[1]: 2e+12 is beyond the coordinate limit"},
      {"TinyScale",
       replaced(kScene, R"("scale": 0.5)", R"("scale": [1e-20, 1, 1])"),
       {},
       "scene.json: objects[1].scale[0]: 1e-20 is out of range: scale factors lie in [2^-16, 2^40]"},
      {"ScalesTooUnequal",
       replaced(kScene, R"("scale": 0.5)", R"("scale": [100, 100, 1e-3])"),
       {},
       "objects[1].scale: the scale factors differ by a factor 1e+05: they lie within a factor 2^16 (65536) of each "
       "other"},
      // Every digit of a ratio just beyond the limit, which three digits would round to within it.
      {"ScalesJustTooUnequal",
       replaced(kScene, R"("scale": 0.5)", R"("scale": [65537, 1, 1])"),
       {},
       "objects[1].scale: the scale factors differ by a factor 65537: they lie within a factor 2^16 (65536) of each "
       "other"},
      // A name reaches one-line messages (warnings, refusals, --pick): a newline in it would break the line.
      {"ObjectNameWithANewline",
       replaced(kScene, R"({"profile": "ball", "material": "white"})",
                R"({"profile": "ball", "material": "white", "name": "glass\n1"})"),
       {},
       "scene.json: objects[0].name: the name \"glass?1\" holds a control character (byte 0x0A)",
       kBottleCsv,
       true},
      {"MaterialNameWithATab",
       replaced(replaced(kScene, R"("white": {"type")", R"("wh\tite": {"type")"), R"("material": "white"})",
                R"("material": "wh\tite"})"),
       {},
       "scene.json: materials.wh?ite: the name \"wh?ite\" holds a control character (byte 0x09)"},
      {"HugeScale",
       replaced(kScene, R"("scale": 0.5)", R"("scale": 1e13)"),
       {},
       "objects[1].scale: 1e+13 is out of range: scale factors lie in"},
      // Within the scale range, but the bottle (1 tall, turned 10 degrees) then reaches 1.13e12.
      {"ObjectReachesBeyondTheLimit",
       replaced(kScene, R"("scale": 0.5)", R"("scale": 1.09e12)"),
       {},
       "scene.json: objects[1]: the placed object reaches 1.13e+12, beyond the coordinate limit",
       kBottleCsv},
      {"HugeIrradianceIsNotNegative",
       replaced(kScene, R"("irradiance": [1, 1, 1])", R"("irradiance": [1, 1e307, 1])"),
       {},
       "lights[0].irradiance[1]: 1e+307 is out of range: light values lie in [0, 1e18]"},
      {"WidthAsWritten",
       replaced(kScene, R"("width": 8)", R"("width": 64.0000001)"),
       {},
       "camera.width: 64.0000001 is not a whole number"},
      {"RepeatedKeyInAnArrayElement",
       replaced(kScene, R"("scale": 0.5)", R"("scale": 0.5, "scale": 2)"),
       {},
       "scene.json: objects[1].scale: the key appears twice in its object"},
      {"RepeatedKeyInANestedObject",
       replaced(kScene, R"("type": "diffuse")", R"("type": "diffuse", "type": "metal")"),
       {},
       "scene.json: materials.white.type: the key appears twice in its object"},
      {"UnwritableOutput",
       kScene,
       {"-o", "no/such/folder/out.png"},
       "no/such/folder/out.png: cannot create a file there: No such file or directory",
       kBottleCsv,
       true},
      {"UnknownSplineKind",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "cubic", )"),
       {},
       R"(scene.json: profiles.ball.spline: unknown spline kind "cubic"; expected one of: linear, quadratic, bezier, catmull-rom, natural)",
       kBottleCsv,
       true},
      {"ReflectivityAboveOne",
       replaced(kScene, R"({"profile": "ball", "material": "white"})",
                R"({"profile": "ball", "material": "white", "reflectivity": 1.5})"),
       {},
       "objects[0].reflectivity: 1.5 is out of range: a reflectivity lies in [0, 1]"},
      {"QuadReflectivityNegative",
       replaced(kScene, R"("material": "white"}],)", R"("material": "white", "reflectivity": -0.1}],)"),
       {},
       "quads[0].reflectivity: -0.1 is out of range: a reflectivity lies in [0, 1]"},
      {"ToleranceForAPolyline",
       replaced(kScene, R"("ball": {)", R"("ball": {"tolerance": 0.001, )"),
       {},
       "profiles.ball.tolerance: applies to a curved \"spline\""},
      {"ToleranceNotPositive",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "natural", "tolerance": 0, )"),
       {},
       "profiles.ball.tolerance: 0 is out of range: a polyline tolerance is a finite number > 0 (the polyline's "
       "largest distance from the curve, in the profile's units)"},
      // The ball as one Bezier piece from the axis to the axis: within 10 its polyline is the chord on
      // the axis, a surface of no area; the same rule as --tolerance's below.
      {"ToleranceCollapsesTheCurve",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "bezier", "tolerance": 10, )"),
       {},
       "scene.json: profiles.ball.tolerance: polyline tolerance 10 collapses the bezier spline onto the axis: every "
       "point of its "
       "polyline has r = 0, a surface of no area that nothing hits, where the curve reaches r = 0.375; a tolerance "
       "below that keeps "
       "the polyline off the axis"},
      {"ToleranceBelowResolution",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "natural", "tolerance": 1e-30, )"),
       {},
       "profiles.ball.tolerance: polyline tolerance 1e-30 is below 2^-40"},
      {"BezierPointCount",
       replaced(replaced(kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )"), "[0, 1]]", "[0.2, 1], [0, 1]]"),
       {},
       "profiles.ball.points[4]: bezier spline has 5 points; cubic Bezier pieces sharing their ends need 3n + 1"},
      {"CurveCrossingTheAxis",
       replaced(kScene, R"("ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]})",
                R"("ball": {"spline": "bezier", "points": [[0.5, 0], [-1, 0.3], [-1, 0.7], [0.5, 1]]})"),
       {},
       "profiles.ball.points[0]: the piece from spline point 0",
       kBottleCsv,
       true},
      {"CsvSpline",
       replaced(kScene, R"("bottle": {"csv")", R"("bottle": {"spline": "catmull-rom", "csv")"),
       {},
       "profiles.bottle.csv: bottle.csv:4: spline point 2",
       "r,z\n0,0\n0.3,0\n0.3,0\n0,1\n"},
      {"ToleranceNotANumber",
       kScene,
       {"--tolerance", "fine"},
       R"(--tolerance: "fine" is neither "pixel" nor a number: a polyline tolerance is a finite number > 0 (the polyline's largest distance from the curve, in the profile's units) (see --help))",
       kBottleCsv,
       true},
      {"ToleranceNaN",
       kScene,
       {"--tolerance", "nan"},
       R"(--tolerance: "nan" is out of range: a polyline tolerance is a finite number > 0)",
       kBottleCsv,
       true},
      {"ToleranceZero",
       kScene,
       {"--tolerance", "0"},
       R"(--tolerance: "0" is out of range: a polyline tolerance is a finite number > 0)",
       kBottleCsv,
       true},
      {"ToleranceEmpty",
       kScene,
       {"--tolerance", ""},
       R"(--tolerance: "" is neither "pixel" nor a number: a polyline tolerance is a finite number > 0)",
       kBottleCsv,
       true},
      // Kajiya's strip tree bounds polylines: a curve traced exactly is refused naming its profile
      // and what works instead.
      {"KajiyaOnACurve",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )"),
       {"--geometry", "kajiya"},
       "scene.json: profiles.ball: a bezier spline, traced exactly: --geometry kajiya cannot trace it (Kajiya's strip "
       "tree bounds "
       "polylines only); use --geometry mibit or linear, or --tolerance to trace it as a polyline",
       kBottleCsv,
       true},
      // The spline's quadratic middle piece has r = (1 - 2u)^2: it touches the axis between its points.
      {"QuadraticTouchingTheAxis",
       replaced(
           kScene, R"("ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]})",
           R"("ball": {"spline": "quadratic", "points": [[0, 0], [0.5, 0], [1, 0], [-1, 0.5], [1, 1], [0.5, 1], [0, 1]]})"),
       {},
       "scene.json: profiles.ball.points[2]: the piece from spline point 2 (r = 1, z = 0) to spline point 4 (r = 1, z "
       "= 1) touches the axis"},
      {"ToleranceCollapsesTheCurveFromTheCommandLine",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )"),
       {"--tolerance", "10"},
       "--tolerance: profiles.ball: polyline tolerance 10 collapses the bezier spline onto the axis: every point of "
       "its polyline "
       "has r = 0",
       kBottleCsv,
       true},
      {"ToleranceBelowTheCurvesResolution",
       replaced(kScene, R"("ball": {)", R"("ball": {"spline": "bezier", )"),
       {"--tolerance", "1e-30"},
       R"(--tolerance: profiles.ball: polyline tolerance 1e-30 is below 2^-40)",
       kBottleCsv,
       true},
      {"UnknownImageExtension",
       kScene,
       {"-o", "out.jpg"},
       R"(out.jpg: unsupported image extension ".jpg")",
       kBottleCsv,
       true},
      {"UnwritableStats",
       kScene,
       {"--stats", "no/such/stats.json"},
       "no/such/stats.json: cannot create a file",
       kBottleCsv,
       true},
      // Embree's linear cone curve: a flat step between two cones, and a scaled instance.
      {"EmbreeConeCannotExpressAStep",
       replaced(kScene, "[0.5, 0.8], [0, 1]", "[0.5, 0.8], [0.3, 0.8], [0.3, 1], [0, 1]"),
       {"--geometry", "embree-cone"},
       "scene.json: objects[0] (profiles.ball) cannot be traced as Embree's linear cone curve: the segment from "
       "profile point 2 "
       "(r = 0.5, z = 0.8) to profile point 3 (r = 0.3, z = 0.8) is horizontal",
       kBottleCsv,
       true},
      // A curve with a flat ring traced as its polyline: the points named are the polyline's.
      {"EmbreeConeCannotExpressACurvesRing",
       replaced(
           kScene, R"("ball": {"points": [[0, 0], [0.5, 0.2], [0.5, 0.8], [0, 1]]})",
           R"("ball": {"spline": "bezier", "points": [[0, 0], [0.4, 0], [0.5, 0.2], [0.5, 0.4], [0.45, 0.4], [0.35, 0.4], )"
           R"([0.3, 0.4], [0.3, 0.7], [0.2, 1], [0, 1]]})"),
       {"--geometry", "embree-cone", "--tolerance", "0.01"},
       "scene.json: objects[0] (profiles.ball, a curve traced as its polyline within 0.01) cannot be traced as "
       "Embree's linear "
       "cone curve: the segment from polyline point "},
      // The POV-Ray export's warnings come only with the file: a run that fails after exporting (here
      // on a profile the cone curve cannot express) prints its one line, not the warnings first.
      {"FailureAfterAnExportWithWarnings",
       replaced(replaced(kScene, "[0.5, 0.8], [0, 1]", "[0.5, 0.8], [0.3, 0.8], [0.3, 1], [0, 1]"),
                R"({"type": "diffuse", "color": [0.8, 0.8, 0.8]})",
                R"({"type": "metal", "color": [0.8, 0.8, 0.8], "roughness": 0.3})"),
       {"--export-pov", "scene.pov", "--geometry", "embree-cone"},
       "cannot be traced as Embree's linear cone curve",
       kBottleCsv,
       true},
      {"EmbreeConeScaledObject",
       kScene,
       {"--geometry", "embree-cone"},
       "scene.json: objects[1] (profiles.bottle) is scaled by (0.5, 0.5, 0.5): Embree's linear cone curve kernel "
       "assumes unit ray "
       "directions",
       kBottleCsv,
       true},
      {"PovExportName",
       kScene,
       {"--export-pov", "scene.txt"},
       "scene.txt: --export-pov writes POV-Ray scene files, named .pov",
       kBottleCsv,
       true},
      {"UnwritablePovExport",
       kScene,
       {"--export-pov", "no/such/scene.pov"},
       "no/such/scene.pov: cannot create a file",
       kBottleCsv,
       true},
      {"PovLatheBeyondLimit",
       kScene,
       {"--export-pov", "scene.pov"},
       "scene.json: profiles.bottle: 32768 points: a POV-Ray lathe holds at most 32767",
       longProfileCsv(32768),
       true},
  };
}

}  // namespace revolve::testing
