// Where the platform's parallel work runs: one TBB arena for each thread count, made on first use
// and kept for the life of the process. A simulation loop traces every frame, and Debian's TBB
// (2021.8) keeps about 7 KB for every task_arena made and destroyed, so an arena per call grows a
// long-running process without end (Python's queries were seen at 721 MB after 100,000 scans).
#pragma once

#include <tbb/task_arena.h>
#include <optional>
#include <string>

namespace revolve::app {

// The most worker threads a job may ask for: the tools' --threads and Python's thread arguments.
// Far above the cores of any machine revolve runs on, and a bound on the arenas kept.
inline constexpr int kMaxThreads = 1024;

// Why `threads` (0: all of this machine's) cannot be a thread count, naming `name`; nothing when
// it can (0 to kMaxThreads).
std::optional<std::string> threadCountFault(long long threads, const std::string& name);

// The process's arena for `threads` worker threads (0: all of this machine's); throws
// std::invalid_argument with threadCountFault's message otherwise. Thread-safe; an arena may run
// the work of several callers at once.
tbb::task_arena& threadArena(int threads);

}  // namespace revolve::app
