// Temporary files that do not outlive an interrupted run: a signal-safe registry of paths that a
// handler for SIGINT, SIGTERM and SIGHUP removes before the tool exits (status 130, 143 or 129),
// the child process it terminates first, the scratch files built on it, and the holding off of
// signals while a step that must not stop half-way runs (io/output_set.h's commit).
#pragma once

#include <string>
#include <string_view>

#include <sys/types.h>

namespace revolve::io {

// Installs the handler that removes registered temporaries and exits 128 + signal on SIGINT,
// SIGTERM and SIGHUP. Idempotent; the tools call it first thing in main().
void removeTemporariesOnSignals();
// For code running inside another program (the Python package): on SIGTERM and SIGHUP, where the
// program has left them at their default (ending the process), remove the registered temporaries
// and end the process by the signal as the default would; SIGINT and any signal the program
// handles itself are left alone (Python turns SIGINT into KeyboardInterrupt, whose unwinding
// removes them). Idempotent; a tool's removeTemporariesOnSignals takes precedence.
void removeTemporariesOnTermination();

// A file path the signal handler removes if the process is interrupted while this lives. The
// handler reads a fixed table (no allocation, no locks: it only calls unlink() and _exit()).
class TemporaryRegistration {
 public:
  TemporaryRegistration() = default;
  explicit TemporaryRegistration(const std::string& path);  // std::runtime_error if the table is full
  ~TemporaryRegistration();
  TemporaryRegistration(TemporaryRegistration&& other) noexcept;
  TemporaryRegistration& operator=(TemporaryRegistration&& other) noexcept;

 private:
  int slot_ = -1;
};

// A child process the signal handler terminates (SIGTERM) before exiting, while this lives.
class ChildRegistration {
 public:
  explicit ChildRegistration(pid_t child);
  ~ChildRegistration();
  ChildRegistration(const ChildRegistration&) = delete;
  ChildRegistration& operator=(const ChildRegistration&) = delete;
};

// A private file in the system's temporary folder (TMPDIR), removed when this goes out of scope
// or the process is interrupted.
class ScratchFile {
 public:
  explicit ScratchFile(std::string_view suffix);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  TemporaryRegistration registration_;
};

// Signals wait while this lives (a commit must not stop half-way, a temporary must not exist
// unregistered); one that came meanwhile is acted on when the last HeldSignals ends.
class HeldSignals {
 public:
  HeldSignals();
  ~HeldSignals();
  HeldSignals(const HeldSignals&) = delete;
  HeldSignals& operator=(const HeldSignals&) = delete;
};

}  // namespace revolve::io
