// The per-ray entry points of the pure queries, compiled once per instruction set (see util/isa.h),
// and the choice of the best one this CPU runs (the Embree callbacks: embree/callback_kernels.h).
// Every copy gives the same answers bit for bit: the same IEEE operations in the same order, without
// contraction into fused multiply-adds.
#pragma once

#include <revolve/core.h>

#include <optional>

namespace revolve::detail {

struct QueryKernels {
  const char* isa;
  std::optional<Hit> (*intersect)(const detail::ShapeImpl& shape, const Ray& ray, Stats* stats) noexcept;
  bool (*occluded)(const detail::ShapeImpl& shape, const Ray& ray, Stats* stats) noexcept;
  std::optional<Hit> (*attributes)(const detail::ShapeImpl& shape, const Ray& ray, std::uint32_t segment,
                                   float t) noexcept;
};

enum class Isa { sse2, avx2 };

// Whether this CPU runs the AVX2 copies (x86-64-v3 as they are compiled for it).
bool cpuRunsAvx2() noexcept;

// The kernels for the best instruction set this CPU supports, chosen once.
const QueryKernels& queryKernels() noexcept;
// The kernels for `isa`, or nullptr if this CPU cannot run them (for tests comparing the copies).
const QueryKernels* queryKernelsFor(Isa isa) noexcept;

}  // namespace revolve::detail
