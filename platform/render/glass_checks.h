// Glass needs a closed profile whose normals point out of the glass (listed from the axis at the
// bottom, up the outside): the renderer tells an entering ray from a leaving one by the normal's
// side. An open profile renders as a sheet of glass with no inside, one listed the wrong way as a
// bubble of air inside glass. Neither is an error (both are valid surfaces), so the renderer warns.
#pragma once

#include "io/scene_file.h"

#include <string>
#include <vector>

namespace revolve::render {

// One message per glass object whose profile is open or runs clockwise in (r, z), naming the
// object (objects[i] and its name), its profile and what to change.
std::vector<std::string> glassWarnings(const io::SceneDescription& scene);

}  // namespace revolve::render
