#include "shape/query_kernels.h"

#include <atomic>

namespace revolve::detail {

extern const QueryKernels queryKernelsSse2;
extern const QueryKernels queryKernelsAvx2;
extern const QueryKernels queryKernelsAvx512;

const char* isaName(Isa isa) noexcept {
  switch (isa) {
    case Isa::sse2:
      return "sse2";
    case Isa::avx2:
      return "avx2";
    case Isa::avx512:
      return "avx512";
  }
  return "unknown";
}

bool cpuRuns(Isa isa) noexcept {
  __builtin_cpu_init();
  // x86-64-v3 as the AVX2 copy is compiled for it: every CPU with AVX2, FMA and BMI2 has the rest.
  const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
  switch (isa) {
    case Isa::sse2:
      return true;
    case Isa::avx2:
      return v3;
    case Isa::avx512:  // x86-64-v4: v3 and AVX-512 F, CD, BW, DQ, VL
      return v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
             __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
             __builtin_cpu_supports("avx512vl");
  }
  return false;
}

namespace {

Isa bestCpuIsa() noexcept {
  static const Isa best = cpuRuns(Isa::avx512) ? Isa::avx512 : cpuRuns(Isa::avx2) ? Isa::avx2 : Isa::sse2;
  return best;
}

std::atomic<Isa> isaLimit{Isa::avx512};

const QueryKernels& kernelsOf(Isa isa) noexcept {
  switch (isa) {
    case Isa::sse2:
      break;
    case Isa::avx2:
      return queryKernelsAvx2;
    case Isa::avx512:
      return queryKernelsAvx512;
  }
  return queryKernelsSse2;
}

}  // namespace

Isa chosenIsa() noexcept {
  const Isa limit = isaLimit.load(std::memory_order_relaxed);
  return bestCpuIsa() < limit ? bestCpuIsa() : limit;
}

void limitIsa(Isa isa) noexcept { isaLimit.store(isa, std::memory_order_relaxed); }

const QueryKernels* queryKernelsFor(Isa isa) noexcept { return cpuRuns(isa) ? &kernelsOf(isa) : nullptr; }

const QueryKernels& queryKernels() noexcept { return kernelsOf(chosenIsa()); }

}  // namespace revolve::detail
