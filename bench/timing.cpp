#include "timing.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace revolve::bench {
namespace {

// Google Benchmark 1.7 (Debian 12) reports a failed run as error_occurred / error_message, 1.8 and
// later (Debian 13) as skipped / skip_message.
template <class Run>
bool failed(const Run& run) {
  if constexpr (requires { run.error_occurred; }) {
    return run.error_occurred;
  } else {
    return run.skipped != 0;
  }
}
template <class Run>
std::string message(const Run& run) {
  if constexpr (requires { run.error_message; }) {
    return run.error_message;
  } else {
    return run.skip_message;
  }
}

// Collects each repetition's throughput, by job index (the benchmark's name).
class Collector : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration) continue;
      if (failed(run)) throw std::runtime_error("benchmark " + run.benchmark_name() + ": " + message(run));
      const std::size_t job = std::stoul(run.run_name.function_name);
      samples[job].push_back(double(run.counters.at("items_per_second")) / 1e6);
    }
  }
  std::map<std::size_t, std::vector<double>> samples;
};

void initialiseOnce() {
  static const bool initialised = [] {
    // Repetitions of all benchmarks run in random order (the library's own interleaving).
    static char name[] = "revolve-bench", interleave[] = "--benchmark_enable_random_interleaving=true";
    char* argv[] = {name, interleave, nullptr};
    int argc = 2;
    benchmark::Initialize(&argc, argv);
    return true;
  }();
  (void)initialised;
}

}  // namespace

Timer::Timer(int repetitions, double minSecondsPerRepetition)
    : repetitions_(repetitions), minSeconds_(minSecondsPerRepetition) {}

void Timer::add(std::string name, std::function<std::size_t()> batch, bool allThreads) {
  jobs_.push_back({std::move(name), std::move(batch), allThreads});
}

std::vector<Throughput> Timer::run() {
  initialiseOnce();
  benchmark::ClearRegisteredBenchmarks();
  for (std::size_t i = 0; i < jobs_.size(); ++i) {
    const Job& job = jobs_[i];
    benchmark::internal::Benchmark* b =
        benchmark::RegisterBenchmark(std::to_string(i).c_str(), [&job](benchmark::State& state) {
          std::size_t rays = 0;
          for (auto _ : state) rays += job.batch();
          state.SetItemsProcessed(std::int64_t(rays));
        });
    b->Repetitions(repetitions_)->MinTime(minSeconds_);
    if (job.allThreads) b->UseRealTime();
  }
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::ClearRegisteredBenchmarks();

  std::vector<Throughput> results(jobs_.size());
  for (auto& [job, samples] : collector.samples) {
    std::sort(samples.begin(), samples.end());
    const std::size_t n = samples.size();
    results[job] = {n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]), samples.front(),
                    samples.back()};
  }
  for (std::size_t i = 0; i < jobs_.size(); ++i) {
    if (collector.samples.count(i) == 0)
      throw std::runtime_error("benchmark job " + jobs_[i].name + " produced no timing");
  }
  jobs_.clear();
  return results;
}

}  // namespace revolve::bench
