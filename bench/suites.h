// The benchmark's subcommands: speed against error over the test shapes, and scaling with the
// number of profile points.
#pragma once

#include "results.h"

#include <revolve/embree_api.h>

#include <vector>

namespace revolve::bench {

// Error levels (relative to the object's size) at which methods are matched.
inline const std::vector<double> kErrorLevels = {1e-3, 1e-4, 1e-5, 1e-6};

// Every method on every test shape (or on the shapes named in `only`, if any).
std::vector<ShapeResult> runSpeedError(RTCDevice device, const RunSettings& settings,
                                       const std::vector<std::string>& only);

// MIBIT, the linear scan, Kajiya's strip tree, meshes and Embree's curves on the vase, 16 to 32,768
// points (round curves: Bézier segments, up to 4,096).
std::vector<ShapeResult> runScaling(RTCDevice device, const RunSettings& settings);

}  // namespace revolve::bench
