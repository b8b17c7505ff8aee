#include "io/temporary_files.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <unistd.h>

namespace revolve::io {
namespace {

// The signal handler's table: fixed storage, lock-free atomics, so that the handler may read it
// (POSIX allows unlink, kill and _exit in a handler, and lock-free atomic loads).
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
struct Slot {
  std::atomic<bool> claimed{false};  // taken by a registration
  std::atomic<bool> live{false};     // path complete: the handler removes it
  char path[kPathBytes];
};
Slot gSlots[kSlots];
std::atomic<pid_t> gChild{0};
std::atomic<int> gHeld{0};                 // > 0: a commit (or a temporary's creation) is under way
std::atomic<int> gPending{0};              // a signal that arrived meanwhile
std::atomic<bool> gEndByTheSignal{false};  // removeTemporariesOnTermination: die of it, as by default
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free &&
              std::atomic<pid_t>::is_always_lock_free);

// Removes what is registered, then ends the process: by _exit(128 + signal), as the tools report
// it, or by the signal itself under its default action (re-raised, it is delivered as the handler
// returns), as the program hosting us would have ended without the handler.
void cleanUpAndEnd(int signal) {
  if (const pid_t child = gChild.load(); child > 0) kill(child, SIGTERM);
  for (Slot& slot : gSlots) {
    if (slot.live.load()) unlink(slot.path);
  }
  if (!gEndByTheSignal.load()) _exit(128 + signal);
  struct sigaction byDefault {};
  byDefault.sa_handler = SIG_DFL;
  sigemptyset(&byDefault.sa_mask);
  sigaction(signal, &byDefault, nullptr);
  raise(signal);
}

extern "C" void onSignal(int signal) {
  if (gHeld.load() > 0) {
    gPending.store(signal);
    return;
  }
  cleanUpAndEnd(signal);
}

}  // namespace

HeldSignals::HeldSignals() { ++gHeld; }

HeldSignals::~HeldSignals() {
  if (--gHeld == 0) {
    if (const int signal = gPending.exchange(0); signal != 0) cleanUpAndEnd(signal);
  }
}

void removeTemporariesOnSignals() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    sigaction(signal, nullptr, &previous);
    if (previous.sa_handler == SIG_IGN) continue;  // ignored by whoever started us (nohup): keep it so
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a deferred signal must not make writes fail with EINTR
    sigaction(signal, &action, nullptr);
  }
}

void removeTemporariesOnTermination() {
  for (const int signal : {SIGTERM, SIGHUP}) {
    struct sigaction current {};
    sigaction(signal, nullptr, &current);
    if (current.sa_handler == onSignal) continue;  // installed already (by us, or a tool's handler)
    if (current.sa_handler != SIG_DFL) continue;   // the program's own handler, or ignored: theirs
    gEndByTheSignal.store(true);
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(signal, &action, nullptr);
  }
}

TemporaryRegistration::TemporaryRegistration(const std::string& path) {
  if (path.size() >= kPathBytes)
    throw std::runtime_error(path.substr(0, 80) + "...: the path is too long for a temporary file");
  for (int i = 0; i < kSlots; ++i) {
    if (!gSlots[i].claimed.exchange(true)) {
      std::memcpy(gSlots[i].path, path.c_str(), path.size() + 1);
      gSlots[i].live.store(true);
      slot_ = i;
      return;
    }
  }
  throw std::runtime_error(path + ": too many temporary files at once (" + std::to_string(kSlots) + ")");
}

TemporaryRegistration::~TemporaryRegistration() {
  if (slot_ >= 0) {
    gSlots[slot_].live.store(false);
    gSlots[slot_].claimed.store(false);
  }
}

TemporaryRegistration::TemporaryRegistration(TemporaryRegistration&& other) noexcept : slot_(other.slot_) {
  other.slot_ = -1;
}

TemporaryRegistration& TemporaryRegistration::operator=(TemporaryRegistration&& other) noexcept {
  if (this != &other) {
    this->~TemporaryRegistration();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

ChildRegistration::ChildRegistration(pid_t child) { gChild.store(child); }
ChildRegistration::~ChildRegistration() { gChild.store(0); }

ScratchFile::ScratchFile(std::string_view suffix) {
  const HeldSignals held;  // no window in which the file exists unregistered
  std::error_code code;
  const std::filesystem::path folder = std::filesystem::temp_directory_path(code);
  path_ = ((code ? std::filesystem::path("/tmp") : folder) / ("revolve-XXXXXX" + std::string(suffix))).string();
  const int descriptor = mkstemps(path_.data(), int(suffix.size()));
  if (descriptor < 0) throw std::runtime_error(path_ + ": cannot create a temporary file: " + std::strerror(errno));
  close(descriptor);
  registration_ = TemporaryRegistration(path_);
}

ScratchFile::~ScratchFile() { unlink(path_.c_str()); }

}  // namespace revolve::io
