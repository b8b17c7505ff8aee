// revolve-bench scale --write-scene: the seeded family (scale_family.h) as a scene file, its
// objects in one object table (io/object_table.h), so that the tools can read, render and trace a
// scene of 10^5 or 10^6 distinct objects, and `revolve-bench scale --scene` can time building it
// from the file against building it from the C++ API.
#pragma once

#include "scale/scale_family.h"

#include <cstddef>
#include <string>

namespace revolve::bench {

// Writes DIRECTORY/scale-N.json, scale-N-profiles.csv and scale-N-objects.csv (each a temporary
// renamed into place once all three are whole; the directory is created) and returns the JSON's
// path. Numbers are written as the shortest text that reads back to the same double, so the file
// describes exactly the objects familyDescription makes in code. The camera is the benchmark's,
// above one corner looking across the grid; a sun and a sky light it.
std::string writeFamilyScene(const ScaleFamily& family, std::size_t count, const std::string& directory);

}  // namespace revolve::bench
