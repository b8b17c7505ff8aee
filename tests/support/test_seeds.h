// Seeds for the tests that draw random inputs. By default each test runs a fixed set of seeds, so
// that the suite is deterministic: a test that failed on one seed in twenty would make CI fail at
// random. REVOLVE_TEST_SEED=n runs seed n alone instead (decimal, or hexadecimal with 0x), to
// explore other inputs or to replay a failure: every such test names its seed when it fails.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace revolve::testing {

// The seeds to run: REVOLVE_TEST_SEED's if set, otherwise `defaults`. Throws std::invalid_argument
// (a test failure naming the text) when REVOLVE_TEST_SEED is not a whole number.
inline std::vector<std::uint64_t> testSeeds(std::initializer_list<std::uint64_t> defaults) {
  const char* text = std::getenv("REVOLVE_TEST_SEED");
  if (text == nullptr) return defaults;
  char* end = nullptr;
  errno = 0;
  const std::uint64_t seed = std::strtoull(text, &end, 0);
  if (*text == '\0' || *text == '-' || *end != '\0' || errno == ERANGE) {
    throw std::invalid_argument("REVOLVE_TEST_SEED: '" + std::string(text) +
                                "' is not a whole number from 0 to 2^64 - 1 (decimal, or hexadecimal with 0x)");
  }
  return {seed};
}

// For SCOPED_TRACE: the seed, and how to run it again.
inline std::string seedTrace(std::uint64_t seed) {
  return "seed " + std::to_string(seed) + " (replay: REVOLVE_TEST_SEED=" + std::to_string(seed) + ")";
}

}  // namespace revolve::testing
