// A placed Geometry (revolve::Placement): the shape put in the scene by the geometry itself rather
// than by an Embree instance. Its callbacks map each valid lane's ray into object space in place,
// run the shape's own callbacks on the packet, and put the world rays back exactly as they were.
#pragma once

#include <revolve/embree.h>

#include "embree/payload.h"

namespace revolve::detail {

// The maps of `placement`, its inverse computed in double. Throws std::invalid_argument when an
// entry is not finite or the linear part is singular (its inverse not finite).
PlacementMaps placementMaps(const Placement& placement);

Vec3 toObjectSpace(const PlacementMaps& maps, Vec3 world) noexcept;
Vec3 toWorldSpace(const PlacementMaps& maps, Vec3 object) noexcept;

void placedBoundsCallback(const RTCBoundsFunctionArguments* args);
void placedIntersectCallback(const RTCIntersectFunctionNArguments* args);
void placedOccludedCallback(const RTCOccludedFunctionNArguments* args);

}  // namespace revolve::detail
