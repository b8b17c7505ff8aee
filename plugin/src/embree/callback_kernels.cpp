#include "embree/callback_kernels.h"

#include "shape/query_kernels.h"

namespace revolve::detail {

extern const CallbackKernels callbackKernelsSse2;
extern const CallbackKernels callbackKernelsAvx2;
extern const CallbackKernels callbackKernelsAvx512;

const CallbackKernels& callbackKernels() noexcept {
  switch (chosenIsa()) {
    case Isa::sse2:
      break;
    case Isa::avx2:
      return callbackKernelsAvx2;
    case Isa::avx512:
      return callbackKernelsAvx512;
  }
  return callbackKernelsSse2;
}

}  // namespace revolve::detail
