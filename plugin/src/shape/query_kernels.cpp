#include "shape/query_kernels.h"

namespace revolve::detail {

extern const QueryKernels queryKernelsSse2;
extern const QueryKernels queryKernelsAvx2;

// x86-64-v3 as the AVX2 copy is compiled for it; every CPU with AVX2 and FMA has the rest.
bool cpuRunsAvx2() noexcept {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
}

const QueryKernels* queryKernelsFor(Isa isa) noexcept {
  switch (isa) {
    case Isa::sse2:
      return &queryKernelsSse2;
    case Isa::avx2:
      return cpuRunsAvx2() ? &queryKernelsAvx2 : nullptr;
  }
  return nullptr;
}

const QueryKernels& queryKernels() noexcept {
  static const QueryKernels& best = cpuRunsAvx2() ? queryKernelsAvx2 : queryKernelsSse2;
  return best;
}

}  // namespace revolve::detail
