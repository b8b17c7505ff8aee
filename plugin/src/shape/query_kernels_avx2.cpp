// The per-ray code for x86-64-v3 (AVX2, BMI, LZCNT): built with -march=x86-64-v3 (plugin/CMakeLists.txt).
#define REVOLVE_ISA_NAME "avx2"
#include "shape/query_kernels_impl.h"

#if !defined(__AVX2__)
#error "query_kernels_avx2.cpp must be compiled with -march=x86-64-v3"
#endif

namespace revolve::detail {
extern const QueryKernels queryKernelsAvx2;
const QueryKernels queryKernelsAvx2 = avx2::kQueryKernels;
}  // namespace revolve::detail
