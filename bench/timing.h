// Timing through Google Benchmark. Each job traces one batch of rays per call; all jobs of a run
// are timed side by side, their repetitions randomly interleaved (so that a noisy moment of a
// shared machine does not land on one method), and each job's median throughput is reported with
// the spread of its repetitions.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace revolve::bench {

struct Throughput {
  double median = 0, low = 0, high = 0;  // Mrays/s over the repetitions
};

class Timer {
 public:
  Timer(int repetitions, double minSecondsPerRepetition);
  // `batch` traces some rays and returns how many. Single-threaded jobs are timed by the main
  // thread's CPU time, multi-threaded ones (`allThreads`) by wall time.
  void add(std::string name, std::function<std::size_t()> batch, bool allThreads = false);
  // Runs every job added since the last run; results in the order they were added.
  std::vector<Throughput> run();

 private:
  struct Job {
    std::string name;
    std::function<std::size_t()> batch;
    bool allThreads;
  };
  int repetitions_;
  double minSeconds_;
  std::vector<Job> jobs_;
};

}  // namespace revolve::bench
