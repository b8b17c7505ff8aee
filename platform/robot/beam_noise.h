// Gaussian range noise for one beam, from a counter-based hash of (seed, pose, ring, column): the
// same number whatever thread traces the beam and in whatever order, so a scan depends on its seed
// only (common/counter_hash.h). Box-Muller on two uniforms of 53 bits each.
#pragma once

#include "random/counter_hash.h"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace revolve::robot {

// A standard normal deviate for the beam.
inline double standardNormal(std::uint64_t seed, std::uint64_t pose, std::uint64_t ring,
                             std::uint64_t column) noexcept {
  using app::mix64;
  const std::uint64_t beam = mix64(mix64(mix64(mix64(seed) ^ pose) ^ ring) ^ column);
  // u1 in (0, 1] keeps the logarithm finite; u2 in [0, 1).
  const double u1 = double((mix64(beam ^ mix64(0)) >> 11) + 1) * 0x1p-53;
  const double u2 = double(mix64(beam ^ mix64(1)) >> 11) * 0x1p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace revolve::robot
