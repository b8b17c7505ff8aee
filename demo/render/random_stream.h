// Random numbers for a pixel sample, from a counter-based hash of (seed, pixel, sample, dimension):
// the same numbers whatever thread renders the pixel and in whatever order, so an image depends on
// its seed only. The hash is SplitMix64's finaliser (Steele, Lea & Flood 2014), a bijection of
// 64-bit words with full avalanche, applied to each counter in turn.
#pragma once

#include <cstdint>

namespace revolve::render {

constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

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
