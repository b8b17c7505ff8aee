// The per-ray C++ the geometry's Embree callbacks run: bounds, and the extern "C" entries the ISPC
// side calls (Revolutions.ispc). They read the revolutions through the shared struct's `host`,
// a std::vector<Revolution>. Per ray: no allocation, no exception, no lock.
#pragma once

#include "common/Embree.h"

#include <cstdint>

namespace ospray::revolve_module {

void revolutionBounds(const RTCBoundsFunctionArguments* args);

}  // namespace ospray::revolve_module

extern "C" {
void revolveOsprayIntersect(const RTCIntersectFunctionNArguments* args, std::int32_t occlusion);
// The ray's nearest crossing with revolution primID in [tnear, tfar]: (t, Ng, u, v), or false.
bool revolveOsprayCrossing(const void* geometryUserPtr, std::uint32_t primID, const float origin[3],
                           const float direction[3], float tnear, float tfar, float crossing[6]);
void revolveOsprayShadingNormal(const void* host, std::uint32_t primID, float u, float v, float normal[3]);
}
