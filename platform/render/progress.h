// Progress of a render on stderr, shown only once it has run for a second: on a terminal a bar
// redrawn in place with percent, elapsed time and time left; elsewhere (CI logs) a plain line at
// each quarter.
#pragma once

#include <chrono>

namespace revolve::render {

class ProgressReport {
 public:
  ProgressReport();
  void update(double fraction);  // from one thread at a time
  void finish();

 private:
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
  bool shown_ = false;
  int quartersPrinted_ = 0;
};

}  // namespace revolve::render
