// A scene description (io/scene_file.h) written as POV-Ray 3.7 scene description language, so that
// the same scene can be rendered by POV-Ray and compared with revolve (README, "Against POV-Ray").
//
// The mapping (README, "Against POV-Ray", lists what does not map):
// - Axes: POV-Ray's y is revolve's z (up) and its z is revolve's y. The swap turns revolve's
//   right-handed z-up world into POV-Ray's left-handed y-up one without mirroring the picture, and
//   it makes each profile a POV-Ray `lathe` (revolved about its y) with the points (r, z) unchanged.
// - Each profile used by an object becomes one `lathe`: a polyline (or a spline traced as one) a
//   `linear_spline`, a spline traced exactly the same curve as a `bezier_spline` (its cubic Bézier
//   pieces, four points each); each object places it with a `matrix` (the object's scale, rotation
//   and translation, axes swapped).
// - Quads become `mesh` triangles (0, 1, 2) and (0, 2, 3), one mesh per material, as revolve draws them.
// - The camera keeps its position, target, up vector and vertical field of view; the horizontal
//   angle and `right` come from POV-Ray's image_width / image_height, so one file serves every +W +H.
// - Point lights fall off as 1 / d^2 (POV-Ray's fade_power 2), Lambert's 1 / pi folded into the
//   light's colour; diffuse, mirror and glass (Fresnel reflection, refraction with ior, the tint as
//   a filter per crossing) map; a uniform environment is the background and the ambient light.
// - The reflection depth and shadows are #declared with defaults that POV-Ray's command line can
//   override (Declare=Revolve_Depth=1 Declare=Revolve_Shadows=0).
#pragma once

#include "io/scene_file.h"

#include <cstddef>
#include <string>
#include <vector>

namespace revolve::io {

// POV-Ray keeps a lathe's point count in a 16-bit integer: a larger lathe renders nothing.
inline constexpr std::size_t kPovMaxLathePoints = 32767;

struct PovDefaults {
  int depth = 4;        // Revolve_Depth: POV-Ray's max_trace_level, the same count as whitted's --depth
  bool shadows = true;  // Revolve_Shadows
};

struct PovScene {
  std::string text;                   // the SDL
  std::vector<std::string> warnings;  // "key path: what was approximated and how", one per item
};

// The scene as SDL. Throws SceneError (naming the profile's key path) for a profile beyond POV-Ray's
// lathe limit. What maps only approximately (metal, a sky, a sun of finite angle) is written as
// the closest POV-Ray allows and listed in `warnings` (and as comments in the file).
PovScene povScene(const SceneDescription& scene, const PovDefaults& defaults);

// povScene written to `path` through a temporary file renamed into place; returns the warnings.
std::vector<std::string> writePovScene(const std::string& path, const SceneDescription& scene,
                                       const PovDefaults& defaults);

}  // namespace revolve::io
