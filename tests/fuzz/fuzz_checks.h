// What the fuzz targets check beyond "no crash, no sanitizer report": the promises of revolve.h
// and text_files.h that hold for every input. A broken promise aborts, so libFuzzer saves the input.
#pragma once

#include <revolve/revolve.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <span>
#include <string_view>

namespace revolve::fuzz {

[[noreturn]] inline void fail(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", file, line, condition);
  std::abort();
}

#define FUZZ_CHECK(condition)                                                \
  do {                                                                       \
    if (!(condition)) ::revolve::fuzz::fail(#condition, __FILE__, __LINE__); \
  } while (false)

// revolve-trace prints an error as its one line of stderr: no line break or other control
// character may come from the input, and a binary line must not flood the terminal.
inline void checkOneLineMessage(std::string_view message) {
  FUZZ_CHECK(!message.empty());
  FUZZ_CHECK(message.size() <= 1024);
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    FUZZ_CHECK(byte >= 0x20 && byte != 0x7f);
  }
}

// A deterministic generator per input (libFuzzer needs each run of an input to do the same).
inline std::mt19937_64 generatorFor(std::span<const std::uint8_t> data) {
  std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a
  for (const std::uint8_t byte : data) hash = (hash ^ byte) * 0x100000001b3ull;
  return std::mt19937_64(hash);
}

// Builds a Shape of `profile` with every method (MIBIT with options drawn from `random`) and runs
// every query on rays aimed at its vertices, along and across its axis, from its surface and with
// tnear / tfar windows, checking each answer's documented postconditions.
void exerciseShapes(const Profile& profile, std::mt19937_64& random);
// The same for a spline's shapes (MIBIT with random options, and the linear scan).
void exerciseSplineShapes(const Spline& spline, std::mt19937_64& random);

}  // namespace revolve::fuzz
