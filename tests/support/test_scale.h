// Ray counts of the large property tests. Under the sanitizers (REVOLVE_SANITIZE) they run a tenth
// of them: AddressSanitizer and UndefinedBehaviorSanitizer look for memory and undefined-behaviour
// errors, which every ray's code path exercises, at five times the cost a ray; the Release run
// carries the full counts (those README quotes).
#pragma once

#include <cstddef>

namespace revolve::testing {

#ifndef REVOLVE_TEST_RAY_DIVISOR
#define REVOLVE_TEST_RAY_DIVISOR 1
#endif

inline constexpr std::size_t kRayDivisor = REVOLVE_TEST_RAY_DIVISOR;

// `rays` for this build: all of them, or a tenth under the sanitizers (at least one).
constexpr std::size_t scaledRays(std::size_t rays) { return rays / kRayDivisor > 0 ? rays / kRayDivisor : 1; }

}  // namespace revolve::testing
