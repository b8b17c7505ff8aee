// The callbacks of one instruction set: include once, from that set's translation unit
// (callback_kernels_sse2.cpp, _avx2.cpp, _avx512.cpp), which defines its table from them.
#pragma once

#include "embree/callback_kernels.h"
#include "embree/ray_callbacks.h"
#include "util/isa.h"

namespace revolve::detail {
inline namespace REVOLVE_ISA {

// Four intersect callbacks per Stats choice (one per choice of attributes) grow this translation
// unit past GCC's inlining budget, which then called small per-ray helpers out of line (5% to 8%
// slower packets, measured against the build before): those helpers (shellRayOf, laneRay,
// outwardAt, azimuthFraction, PartView::at, coefficientsOf, rayParameterAt, cubicRestricted,
// cylinderShellPasses) are marked [[gnu::always_inline]] so that the choice costs nothing.
inline constexpr CallbackKernels kCallbackKernels{
    REVOLVE_ISA_NAME,
    {{intersectCallback<false, 0>, intersectCallback<false, 1>, intersectCallback<false, 2>,
      intersectCallback<false, 3>},
     {intersectCallback<true, 0>, intersectCallback<true, 1>, intersectCallback<true, 2>, intersectCallback<true, 3>}},
    {occludedCallback<false>, occludedCallback<true>},
};

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
