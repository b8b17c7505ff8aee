// Where a tile's time goes, for --stats: each moment of a tile charged to one phase (tracing the
// nearest hit, shadow rays, drawing samples, or everything else: shading), by a clock read at
// every switch between phases. One clock per tile, on the tile's thread: no locks, no sharing;
// the renderer sums the tiles' clocks at the end. Without --stats there is no clock and every
// switch is a test of a null pointer.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace revolve::render {

enum class Phase : std::uint8_t { shading, intersection, shadows, sampling };
inline constexpr std::size_t kPhaseCount = 4;

// The clock's ticks: the time-stamp counter where there is one (a few nanoseconds a read, at a
// constant rate on every x86-64 processor of the last fifteen years), else the steady clock.
// Only ratios of ticks are reported, so their unit does not matter.
inline std::uint64_t phaseTicks() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

class PhaseClock {
 public:
  PhaseClock() noexcept : last_(phaseTicks()) {}  // starts in shading
  // Charges the time since the last switch to the current phase, moves to `phase` and returns the
  // phase it left.
  Phase enter(Phase phase) noexcept {
    const std::uint64_t now = phaseTicks();
    ticks_[std::size_t(current_)] += now - last_;
    last_ = now;
    const Phase left = current_;
    current_ = phase;
    return left;
  }
  // The ticks charged to each phase, the time since the last switch included.
  std::array<std::uint64_t, kPhaseCount> ticks() noexcept {
    enter(current_);
    return ticks_;
  }

 private:
  std::array<std::uint64_t, kPhaseCount> ticks_{};
  std::uint64_t last_;
  Phase current_ = Phase::shading;
};

// The scope of one phase: entered on construction, the phase before it restored on destruction.
// With no clock (not measuring), does nothing.
class PhaseScope {
 public:
  PhaseScope(PhaseClock* clock, Phase phase) noexcept
      : clock_(clock), left_(clock != nullptr ? clock->enter(phase) : Phase::shading) {}
  ~PhaseScope() {
    if (clock_ != nullptr) clock_->enter(left_);
  }
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

 private:
  PhaseClock* clock_;
  Phase left_;
};

}  // namespace revolve::render
