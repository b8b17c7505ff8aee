#include "embree/callback_kernels.h"

#include "shape/query_kernels.h"

namespace revolve::detail {

extern const CallbackKernels callbackKernelsSse2;
extern const CallbackKernels callbackKernelsAvx2;

const CallbackKernels& callbackKernels() noexcept {
  static const CallbackKernels& best = cpuRunsAvx2() ? callbackKernelsAvx2 : callbackKernelsSse2;
  return best;
}

}  // namespace revolve::detail
