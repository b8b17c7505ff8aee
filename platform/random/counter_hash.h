// A counter-based hash for random numbers that depend on what they are for (a pixel sample, a
// lidar beam), not on which thread draws them or in what order: SplitMix64's finaliser (Steele, Lea
// & Flood 2014), a bijection of 64-bit words with full avalanche, applied to each counter in turn.
#pragma once

#include <cstdint>

namespace revolve::app {

constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace revolve::app
