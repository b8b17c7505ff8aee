// Random numbers for a pixel sample, from a counter-based hash of (seed, pixel, sample, dimension):
// the same numbers whatever thread renders the pixel and in whatever order, so an image depends on
// its seed only. The hash is common/counter_hash.h's.
//
// Two-dimensional decisions (the position in the pixel, a light's sample, a BSDF's sample) draw
// from a pixel's stratified point set instead: the samples of a pixel are the points of the Sobol
// (0, 2)-sequence, Owen-scrambled and shuffled per pixel and per decision (Burley 2020, "Practical
// Hash-based Owen Scrambling"). Each point is still uniform on the square, so every estimate stays
// unbiased; but the 2^k samples of a pixel cover the square evenly (one in each of its 2^k
// elementary intervals), which takes most of the noise out of small bright features: a highlight
// that covers a ninth of a pixel is found by close to a ninth of its samples, not by chance.
#pragma once

#include "random/counter_hash.h"

#include <array>
#include <cstdint>
#include <utility>

namespace revolve::render {

using app::mix64;

// Sobol's second dimension, a byte of the index at a time (RandomStream::sobolSecond).
constexpr std::array<std::array<std::uint32_t, 256>, 4> sobolByteTable() {
  std::array<std::uint32_t, 32> v{};
  v[0] = 1u << 31;
  for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
  std::array<std::array<std::uint32_t, 256>, 4> table{};
  for (int byte = 0; byte < 4; ++byte) {
    for (std::uint32_t bits = 0; bits < 256; ++bits) {
      for (int j = 0; j < 8; ++j) {
        if (bits >> j & 1) table[byte][bits] ^= v[8 * byte + j];
      }
    }
  }
  return table;
}

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
      : pixel_(mix64(mix64(seed) ^ pixel)), base_(mix64(pixel_ ^ sample)), sample_(std::uint32_t(sample)) {}
  // The next dimension's number, uniform in [0, 1): the top 24 bits, so it is exact in float.
  float next() { return float(mix64(base_ ^ mix64(dimension_++)) >> 40) * 0x1p-24f; }

  // The next two-dimensional decision's point, uniform on [0, 1)^2: this sample's point of the
  // pixel's scrambled Sobol set for the decision.
  std::pair<float, float> next2D() {
    // Seeds for the decision: the index shuffle's, then the two coordinates' scrambles.
    const std::uint64_t shuffle = mix64(pixel_ ^ (0x9e3779b97f4a7c15ull * ++pair_)), scramble = mix64(shuffle);
    const std::uint32_t index = nestedUniformScramble(sample_, std::uint32_t(shuffle));
    const std::uint32_t x = nestedUniformScramble(reverseBits(index), std::uint32_t(scramble));
    const std::uint32_t y = nestedUniformScramble(sobolSecond(index), std::uint32_t(scramble >> 32));
    return {float(x >> 8) * 0x1p-24f, float(y >> 8) * 0x1p-24f};
  }

 private:
  static std::uint32_t reverseBits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
  }
  // Sobol's second dimension: the xor of direction numbers v_k (v_0 = 2^31, v_k = v_(k-1) xor
  // (v_(k-1) >> 1)) over the index's set bits k, a byte at a time from a table: the scrambled
  // index's bits are random, and a loop branching on each of them cost more than the rest of a
  // sample's random numbers.
  static std::uint32_t sobolSecond(std::uint32_t index) {
    return kSobolBytes[0][index & 0xff] ^ kSobolBytes[1][(index >> 8) & 0xff] ^ kSobolBytes[2][(index >> 16) & 0xff] ^
           kSobolBytes[3][index >> 24];
  }
  static constexpr std::array<std::array<std::uint32_t, 256>, 4> kSobolBytes = sobolByteTable();
  // Laine & Karras's hash: each bit of the result depends on that bit and the lower ones only.
  static std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
  }
  // Owen scrambling of a 32-bit fixed-point number: each bit flipped by a hash of the higher ones.
  static std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits(laineKarras(reverseBits(x), seed));
  }

  std::uint64_t pixel_, base_;
  std::uint32_t sample_;
  std::uint64_t dimension_ = 0, pair_ = 0;
};

}  // namespace revolve::render
