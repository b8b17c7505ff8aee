// The Embree callbacks for x86-64-v4 (AVX-512 F, CD, BW, DQ, VL on top of x86-64-v3): built with
// -march=x86-64-v4 (plugin/CMakeLists.txt).
#define REVOLVE_ISA_NAME "avx512"
#include "embree/callback_kernels_impl.h"

#if !defined(__AVX512F__) || !defined(__AVX512VL__)
#error "callback_kernels_avx512.cpp must be compiled with -march=x86-64-v4"
#endif

namespace revolve::detail {
extern const CallbackKernels callbackKernelsAvx512;
const CallbackKernels callbackKernelsAvx512 = avx512::kCallbackKernels;
}  // namespace revolve::detail
