// The per-ray entry points, compiled once per instruction set (see util/isa.h), and the choice of
// the best one this CPU runs. Every copy gives the same answers bit for bit: the same IEEE
// operations in the same order, without contraction into fused multiply-adds.
#pragma once

#include <embree3/rtcore.h>
#include <revolve/revolve.h>

#include <optional>

namespace revolve::detail {

struct QueryKernels {
  const char* isa;
  std::optional<Hit> (*intersect)(const Shape::Impl& shape, const Ray& ray, Stats* stats) noexcept;
  bool (*occluded)(const Shape::Impl& shape, const Ray& ray, Stats* stats) noexcept;
  RTCIntersectFunctionN embreeIntersect[2];  // indexed by Geometry::Options::countStats
  RTCOccludedFunctionN embreeOccluded[2];
};

enum class Isa { sse2, avx2 };

// The kernels for the best instruction set this CPU supports, chosen once.
const QueryKernels& queryKernels() noexcept;
// The kernels for `isa`, or nullptr if this CPU cannot run them (for tests comparing the copies).
const QueryKernels* queryKernelsFor(Isa isa) noexcept;

}  // namespace revolve::detail
