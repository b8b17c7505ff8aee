// The few SIMD operations the wide MIBIT search needs, on doubles, at the native width of the
// instruction set a translation unit is compiled for (util/isa.h): 4 lanes with AVX2, 2 with
// SSE2. Lane operations are the scalar IEEE operations, so results do not depend on the width.
#pragma once

#include "util/isa.h"

#include <immintrin.h>

namespace revolve::detail {
inline namespace REVOLVE_ISA {

#if defined(__AVX2__)
inline constexpr int kLanes = 4;
using NativeDouble = __m256d;
#define REVOLVE_SIMD(op) _mm256_##op##_pd
#else
inline constexpr int kLanes = 2;
using NativeDouble = __m128d;
#define REVOLVE_SIMD(op) _mm_##op##_pd
#endif

struct Lanes {
  NativeDouble v;
};
#if defined(__AVX512VL__)
// A comparison's result: bit i set where it holds in lane i, in a mask register (AVX-512 compares
// write one, and turning it into a vector and back costs two instructions a comparison).
struct LaneMask {
  __mmask8 m;
};
#else
// A comparison's result: all bits set in the lanes where it holds.
struct LaneMask {
  NativeDouble v;
};
#endif

[[gnu::always_inline]] inline Lanes load(const double* p) noexcept { return {REVOLVE_SIMD(loadu)(p)}; }
#if defined(__AVX2__)
[[gnu::always_inline]] inline Lanes loadFloats(const float* p) noexcept { return {_mm256_cvtps_pd(_mm_loadu_ps(p))}; }
#else
// Two floats through __m64, which may alias them (a double pointer would break strict aliasing).
[[gnu::always_inline]] inline Lanes loadFloats(const float* p) noexcept {
  return {_mm_cvtps_pd(_mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p)))};
}
#endif
[[gnu::always_inline]] inline void store(double* p, Lanes a) noexcept { REVOLVE_SIMD(storeu)(p, a.v); }
[[gnu::always_inline]] inline Lanes splat(double x) noexcept { return {REVOLVE_SIMD(set1)(x)}; }
[[gnu::always_inline]] inline Lanes operator+(Lanes a, Lanes b) noexcept { return {REVOLVE_SIMD(add)(a.v, b.v)}; }
[[gnu::always_inline]] inline Lanes operator-(Lanes a, Lanes b) noexcept { return {REVOLVE_SIMD(sub)(a.v, b.v)}; }
[[gnu::always_inline]] inline Lanes operator*(Lanes a, Lanes b) noexcept { return {REVOLVE_SIMD(mul)(a.v, b.v)}; }
[[gnu::always_inline]] inline Lanes operator/(Lanes a, Lanes b) noexcept { return {REVOLVE_SIMD(div)(a.v, b.v)}; }
[[gnu::always_inline]] inline Lanes operator-(Lanes a) noexcept {
  return {REVOLVE_SIMD(xor)(a.v, REVOLVE_SIMD(set1)(-0.0))};
}
[[gnu::always_inline]] inline Lanes sqrt(Lanes a) noexcept { return {REVOLVE_SIMD(sqrt)(a.v)}; }
[[gnu::always_inline]] inline Lanes abs(Lanes a) noexcept {
  return {REVOLVE_SIMD(andnot)(REVOLVE_SIMD(set1)(-0.0), a.v)};
}
// min and max as minsd / maxsd compute them; no operand here is ever NaN.
[[gnu::always_inline]] inline Lanes min(Lanes a, Lanes b) noexcept { return {REVOLVE_SIMD(min)(a.v, b.v)}; }
[[gnu::always_inline]] inline Lanes max(Lanes a, Lanes b) noexcept { return {REVOLVE_SIMD(max)(a.v, b.v)}; }
#if defined(__AVX512VL__)
[[gnu::always_inline]] inline LaneMask operator&(LaneMask a, LaneMask b) noexcept { return {__mmask8(a.m & b.m)}; }
[[gnu::always_inline]] inline LaneMask operator|(LaneMask a, LaneMask b) noexcept { return {__mmask8(a.m | b.m)}; }
[[gnu::always_inline]] inline LaneMask operator<(Lanes a, Lanes b) noexcept {
  return {_mm256_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::always_inline]] inline LaneMask operator<=(Lanes a, Lanes b) noexcept {
  return {_mm256_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)};
}
[[gnu::always_inline]] inline LaneMask operator==(Lanes a, Lanes b) noexcept {
  return {_mm256_cmp_pd_mask(a.v, b.v, _CMP_EQ_OQ)};
}
[[gnu::always_inline]] inline Lanes select(LaneMask m, Lanes ifSet, Lanes otherwise) noexcept {
  return {_mm256_mask_blend_pd(m.m, otherwise.v, ifSet.v)};
}
// The lanes of `a` where the mask holds, +0 elsewhere.
[[gnu::always_inline]] inline Lanes onlyWhere(LaneMask m, Lanes a) noexcept { return {_mm256_maskz_mov_pd(m.m, a.v)}; }
// Bit i set when lane i holds.
[[gnu::always_inline]] inline unsigned bits(LaneMask m) noexcept { return m.m; }
#else
[[gnu::always_inline]] inline LaneMask operator&(LaneMask a, LaneMask b) noexcept {
  return {REVOLVE_SIMD(and)(a.v, b.v)};
}
[[gnu::always_inline]] inline LaneMask operator|(LaneMask a, LaneMask b) noexcept {
  return {REVOLVE_SIMD(or)(a.v, b.v)};
}
#endif

#if defined(__AVX512VL__)
// The comparisons and selections are above.
#elif defined(__AVX2__)
[[gnu::always_inline]] inline LaneMask operator<(Lanes a, Lanes b) noexcept {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::always_inline]] inline LaneMask operator<=(Lanes a, Lanes b) noexcept {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)};
}
[[gnu::always_inline]] inline LaneMask operator==(Lanes a, Lanes b) noexcept {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)};
}
// Lane by lane, `ifSet` where the mask holds, `otherwise` elsewhere.
[[gnu::always_inline]] inline Lanes select(LaneMask m, Lanes ifSet, Lanes otherwise) noexcept {
  return {_mm256_blendv_pd(otherwise.v, ifSet.v, m.v)};
}
#else
[[gnu::always_inline]] inline LaneMask operator<(Lanes a, Lanes b) noexcept { return {_mm_cmplt_pd(a.v, b.v)}; }
[[gnu::always_inline]] inline LaneMask operator<=(Lanes a, Lanes b) noexcept { return {_mm_cmple_pd(a.v, b.v)}; }
[[gnu::always_inline]] inline LaneMask operator==(Lanes a, Lanes b) noexcept { return {_mm_cmpeq_pd(a.v, b.v)}; }
[[gnu::always_inline]] inline Lanes select(LaneMask m, Lanes ifSet, Lanes otherwise) noexcept {
  return {_mm_or_pd(_mm_and_pd(m.v, ifSet.v), _mm_andnot_pd(m.v, otherwise.v))};
}
#endif
#if !defined(__AVX512VL__)
// The lanes of `a` where the mask holds, +0 elsewhere.
[[gnu::always_inline]] inline Lanes onlyWhere(LaneMask m, Lanes a) noexcept { return {REVOLVE_SIMD(and)(m.v, a.v)}; }
#endif
// The lanes rounded to float, as static_cast<float> rounds each.
#if defined(__AVX2__)
[[gnu::always_inline]] inline void storeFloats(float* p, Lanes a) noexcept { _mm_storeu_ps(p, _mm256_cvtpd_ps(a.v)); }
#else
[[gnu::always_inline]] inline void storeFloats(float* p, Lanes a) noexcept {
  _mm_storel_pi(reinterpret_cast<__m64*>(p), _mm_cvtpd_ps(a.v));
}
#endif
// std::max and std::min lane by lane, with their exact semantics (the first argument when neither
// is less, which decides the sign of a zero result): the vector instructions return the second.
[[gnu::always_inline]] inline Lanes maxOf(Lanes a, Lanes b) noexcept { return select(a < b, b, a); }
[[gnu::always_inline]] inline Lanes minOf(Lanes a, Lanes b) noexcept { return select(b < a, b, a); }
#if !defined(__AVX512VL__)
// Bit i set when lane i holds.
[[gnu::always_inline]] inline unsigned bits(LaneMask m) noexcept { return unsigned(REVOLVE_SIMD(movemask)(m.v)); }
#endif

#undef REVOLVE_SIMD

// Single precision, twice the lanes: the wide MIBIT search's conservative shell filter.
#if defined(__AVX2__)
inline constexpr int kFloatLanes = 8;
using NativeFloat = __m256;
#define REVOLVE_SIMD(op) _mm256_##op##_ps
#else
inline constexpr int kFloatLanes = 4;
using NativeFloat = __m128;
#define REVOLVE_SIMD(op) _mm_##op##_ps
#endif

struct FloatLanes {
  NativeFloat v;
};
#if defined(__AVX512VL__)
struct FloatMask {
  __mmask8 m;
};
#else
struct FloatMask {
  NativeFloat v;
};
#endif

[[gnu::always_inline]] inline FloatLanes load(const float* p) noexcept { return {REVOLVE_SIMD(loadu)(p)}; }
[[gnu::always_inline]] inline void store(float* p, FloatLanes a) noexcept { REVOLVE_SIMD(storeu)(p, a.v); }
[[gnu::always_inline]] inline FloatLanes splatFloat(float x) noexcept { return {REVOLVE_SIMD(set1)(x)}; }
[[gnu::always_inline]] inline FloatLanes operator+(FloatLanes a, FloatLanes b) noexcept {
  return {REVOLVE_SIMD(add)(a.v, b.v)};
}
[[gnu::always_inline]] inline FloatLanes operator-(FloatLanes a, FloatLanes b) noexcept {
  return {REVOLVE_SIMD(sub)(a.v, b.v)};
}
[[gnu::always_inline]] inline FloatLanes operator*(FloatLanes a, FloatLanes b) noexcept {
  return {REVOLVE_SIMD(mul)(a.v, b.v)};
}
[[gnu::always_inline]] inline FloatLanes min(FloatLanes a, FloatLanes b) noexcept {
  return {REVOLVE_SIMD(min)(a.v, b.v)};
}
[[gnu::always_inline]] inline FloatLanes max(FloatLanes a, FloatLanes b) noexcept {
  return {REVOLVE_SIMD(max)(a.v, b.v)};
}
#if defined(__AVX512VL__)
[[gnu::always_inline]] inline FloatMask operator&(FloatMask a, FloatMask b) noexcept { return {__mmask8(a.m & b.m)}; }
[[gnu::always_inline]] inline FloatMask operator|(FloatMask a, FloatMask b) noexcept { return {__mmask8(a.m | b.m)}; }
[[gnu::always_inline]] inline FloatMask operator<(FloatLanes a, FloatLanes b) noexcept {
  return {_mm256_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::always_inline]] inline FloatMask operator<=(FloatLanes a, FloatLanes b) noexcept {
  return {_mm256_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)};
}
[[gnu::always_inline]] inline unsigned bits(FloatMask m) noexcept { return m.m; }
#else
[[gnu::always_inline]] inline FloatMask operator&(FloatMask a, FloatMask b) noexcept {
  return {REVOLVE_SIMD(and)(a.v, b.v)};
}
[[gnu::always_inline]] inline FloatMask operator|(FloatMask a, FloatMask b) noexcept {
  return {REVOLVE_SIMD(or)(a.v, b.v)};
}
#if defined(__AVX2__)
[[gnu::always_inline]] inline FloatMask operator<(FloatLanes a, FloatLanes b) noexcept {
  return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::always_inline]] inline FloatMask operator<=(FloatLanes a, FloatLanes b) noexcept {
  return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)};
}
#else
[[gnu::always_inline]] inline FloatMask operator<(FloatLanes a, FloatLanes b) noexcept {
  return {_mm_cmplt_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline FloatMask operator<=(FloatLanes a, FloatLanes b) noexcept {
  return {_mm_cmple_ps(a.v, b.v)};
}
#endif
[[gnu::always_inline]] inline unsigned bits(FloatMask m) noexcept { return unsigned(REVOLVE_SIMD(movemask)(m.v)); }
#endif
#undef REVOLVE_SIMD

}  // namespace REVOLVE_ISA
}  // namespace revolve::detail
