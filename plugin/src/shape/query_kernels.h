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

// The instruction sets the per-ray code is compiled for, each including the ones before it.
enum class Isa { sse2, avx2, avx512 };
inline constexpr Isa kIsas[] = {Isa::sse2, Isa::avx2, Isa::avx512};
const char* isaName(Isa isa) noexcept;

// Whether this CPU runs the copy for `isa` (x86-64-v3, x86-64-v4 as the copies are compiled for them).
bool cpuRuns(Isa isa) noexcept;
// The instruction set whose copies queries and new Embree geometries use: the best this CPU runs,
// or at most the one a benchmark set with limitIsa.
Isa chosenIsa() noexcept;
// For benchmarks comparing instruction sets in one process: later choices take at most `isa`.
// Geometries already made keep their callbacks.
void limitIsa(Isa isa) noexcept;

// The kernels for chosenIsa().
const QueryKernels& queryKernels() noexcept;
// The kernels for `isa`, or nullptr if this CPU cannot run them (for tests comparing the copies).
const QueryKernels* queryKernelsFor(Isa isa) noexcept;

}  // namespace revolve::detail
