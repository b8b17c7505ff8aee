// The per-ray code for x86-64-v4 (AVX-512 F, CD, BW, DQ, VL on top of x86-64-v3): built with
// -march=x86-64-v4 (plugin/CMakeLists.txt).
#define REVOLVE_ISA_NAME "avx512"
#include "shape/query_kernels_impl.h"

#if !defined(__AVX512F__) || !defined(__AVX512VL__)
#error "query_kernels_avx512.cpp must be compiled with -march=x86-64-v4"
#endif

namespace revolve::detail {
extern const QueryKernels queryKernelsAvx512;
const QueryKernels queryKernelsAvx512 = avx512::kQueryKernels;
}  // namespace revolve::detail
