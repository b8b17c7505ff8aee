// The Embree callbacks for the x86-64 baseline (SSE2): built with the library's default flags.
#define REVOLVE_ISA_NAME "sse2"
#include "embree/callback_kernels_impl.h"

namespace revolve::detail {
extern const CallbackKernels callbackKernelsSse2;
const CallbackKernels callbackKernelsSse2 = sse2::kCallbackKernels;
}  // namespace revolve::detail
