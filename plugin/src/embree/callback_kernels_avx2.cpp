// The Embree callbacks for x86-64-v3 (AVX2, BMI, LZCNT): built with -march=x86-64-v3
// (plugin/CMakeLists.txt).
#define REVOLVE_ISA_NAME "avx2"
#include "embree/callback_kernels_impl.h"

#if !defined(__AVX2__)
#error "callback_kernels_avx2.cpp must be compiled with -march=x86-64-v3"
#endif

namespace revolve::detail {
extern const CallbackKernels callbackKernelsAvx2;
const CallbackKernels callbackKernelsAvx2 = avx2::kCallbackKernels;
}  // namespace revolve::detail
