#include "threads/thread_arenas.h"

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace revolve::app {

std::optional<std::string> threadCountFault(long long threads, const std::string& name) {
  if (threads >= 0 && threads <= kMaxThreads) return std::nullopt;
  return name + " = " + std::to_string(threads) + ": a thread count lies in [0, " + std::to_string(kMaxThreads) +
         "] (0: all of this machine's threads)";
}

tbb::task_arena& threadArena(int threads) {
  if (std::optional<std::string> fault = threadCountFault(threads, "threads")) throw std::invalid_argument(*fault);
  // Index 0 is the automatic arena. Arenas are made once under the lock and never destroyed (TBB
  // may still hold their workers at exit), so a reference handed out stays valid.
  static std::array<std::atomic<tbb::task_arena*>, kMaxThreads + 1> arenas{};
  static std::mutex making;
  std::atomic<tbb::task_arena*>& slot = arenas[std::size_t(threads)];
  if (tbb::task_arena* arena = slot.load(std::memory_order_acquire)) return *arena;
  std::lock_guard lock(making);
  if (tbb::task_arena* arena = slot.load(std::memory_order_relaxed)) return *arena;
  auto* arena = new tbb::task_arena(threads > 0 ? threads : tbb::task_arena::automatic);
  slot.store(arena, std::memory_order_release);
  return *arena;
}

}  // namespace revolve::app
