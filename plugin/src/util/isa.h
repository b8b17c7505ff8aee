// The instruction set a translation unit is compiled for.
//
// The per-ray code (ray set-up, searches, segment kernel, attributes, Embree callbacks) is compiled
// once for the x86-64 baseline (SSE2), once for x86-64-v3 (AVX2) and once for x86-64-v4 (AVX-512),
// and the CPU picks at run time (shape/query_kernels.h). Each copy lives in an inline namespace
// named after its instruction set, so the copies of an inline function are different symbols and
// the linker can never hand one translation unit another's instructions. Types stored across
// translation units (ShapeFrame, the trees) stay outside these namespaces.
#pragma once

#if defined(__AVX512F__)
#define REVOLVE_ISA avx512
#elif defined(__AVX2__)
#define REVOLVE_ISA avx2
#else
#define REVOLVE_ISA sse2
#endif
