// revolve-clearance's output: one row per robot pose, header `pose,clearance,collides,object,px,py,pz`
// (an interface other tools read: keep the names). `clearance` is the signed clearance (%.9g;
// `inf` with nothing in the scene), `collides` 1 or 0, `object` the scene's object index of the
// nearest obstacle (quads: objects + quad index), px, py, pz a point of its surface; the last four
// are empty when there is no obstacle. Written into an output's temporary (io/output_set.h).
#pragma once

#include "io/output_set.h"

#include <cstdint>
#include <string>
#include <vector>

namespace revolve::io {

struct ClearanceRow {
  double clearance = 0;
  bool collides = false;
  std::int64_t object = -1;  // -1: no obstacle
  double px = 0, py = 0, pz = 0;
};

void writeClearanceCsv(OutputStream& out, const std::vector<ClearanceRow>& rows);

}  // namespace revolve::io
