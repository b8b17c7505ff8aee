// Random numbers for a pixel sample, from a counter-based hash of (seed, pixel, sample, dimension):
// the same numbers whatever thread renders the pixel and in whatever order, so an image depends on
// its seed only. The hash is common/counter_hash.h's.
#pragma once

#include "common/counter_hash.h"

#include <cstdint>

namespace revolve::render {

using app::mix64;

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
      : base_(mix64(mix64(mix64(seed) ^ pixel) ^ sample)) {}
  // The next dimension's number, uniform in [0, 1): the top 24 bits, so it is exact in float.
  float next() { return float(mix64(base_ ^ mix64(dimension_++)) >> 40) * 0x1p-24f; }

 private:
  std::uint64_t base_;
  std::uint64_t dimension_ = 0;
};

}  // namespace revolve::render
