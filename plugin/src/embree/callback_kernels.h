// Embree's intersect and occluded callbacks for a revolve::Geometry, compiled once per instruction
// set like the pure queries (isa/query_kernels.h), and the choice of the copy this CPU runs.
#pragma once

#include <revolve/embree_api.h>

namespace revolve::detail {

struct CallbackKernels {
  const char* isa;
  // Indexed by Geometry::Options::countStats, then by the attributes the hits carry: bit 0 the
  // normal (Options::normal), bit 1 u and v (Options::uv).
  RTCIntersectFunctionN intersect[2][4];
  RTCOccludedFunctionN occluded[2];
};

// The callbacks for chosenIsa() (shape/query_kernels.h): the best instruction set this CPU runs.
const CallbackKernels& callbackKernels() noexcept;

}  // namespace revolve::detail
