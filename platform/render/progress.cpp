#include "render/progress.h"

#include <unistd.h>
#include <cstdio>
#include <string>

namespace revolve::render {

ProgressReport::ProgressReport() : start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) == 1) {}

void ProgressReport::update(double fraction) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (elapsed < 1.0) return;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
    if (fraction > 0) {
      std::fprintf(stderr, "\r[%s] %3.0f%%  elapsed %.1f s  left %.1f s ", bar.c_str(), 100 * fraction, elapsed,
                   elapsed * (1 - fraction) / fraction);
    } else {
      std::fprintf(stderr, "\r[%s] %3.0f%%  elapsed %.1f s ", bar.c_str(), 0.0, elapsed);
    }
    shown_ = true;
    return;
  }
  while (quartersPrinted_ < 3 && fraction >= 0.25 * (quartersPrinted_ + 1)) {
    ++quartersPrinted_;
    std::fprintf(stderr, "rendering: %d%% after %.1f s\n", 25 * quartersPrinted_, elapsed);
    shown_ = true;
  }
}

void ProgressReport::finish() {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_ && shown_) std::fprintf(stderr, "\r%70s\r", "");
  if (shown_ || elapsed >= 1.0) std::fprintf(stderr, "rendered in %.1f s\n", elapsed);
}

}  // namespace revolve::render
