// What a revolve::Geometry hands Embree as its user data: the shape, which filters may apply, and
// the work counters.
#pragma once

#include <revolve/embree.h>

#include "shape/shape_impl.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace revolve::detail {

// A placed Geometry's map between world and object space (revolve::Placement and its inverse).
struct PlacementMaps {
  double linear[3][3], inverse[3][3], translate[3];
};

struct GeometryPayload {
  const ShapeImpl* shape;  // the heap part of the Shape: it stays put when the Shape is moved
  // A placed Geometry: its maps, and the callbacks that search the shape once the rays are in
  // object space (the instruction set's, as an unplaced Geometry's would be).
  std::unique_ptr<PlacementMaps> placement;
  RTCIntersectFunctionN objectIntersect = nullptr;
  RTCOccludedFunctionN objectOccluded = nullptr;
  bool intersectFilter = false;  // the geometry has its own intersection filter
  bool occlusionFilter = false;  // ... its own occlusion filter
  bool argumentFilter = false;   // enableFilterFunctionFromArguments (Embree 4)
  std::atomic<std::uint64_t> rays{0}, nodesVisited{0}, shellTests{0}, quadratics{0};

  void add(const Stats& stats) noexcept {
    rays.fetch_add(stats.rays, std::memory_order_relaxed);
    nodesVisited.fetch_add(stats.nodesVisited, std::memory_order_relaxed);
    shellTests.fetch_add(stats.shellTests, std::memory_order_relaxed);
    quadratics.fetch_add(stats.quadratics, std::memory_order_relaxed);
  }
};

}  // namespace revolve::detail
