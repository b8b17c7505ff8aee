// The per-ray code for the x86-64 baseline (SSE2): built with the library's default flags.
#define REVOLVE_ISA_NAME "sse2"
#include "shape/query_kernels_impl.h"

namespace revolve::detail {
extern const QueryKernels queryKernelsSse2;
const QueryKernels queryKernelsSse2 = sse2::kQueryKernels;
}  // namespace revolve::detail
