// Runs a program as a separate process, as its users run it: stdin from /dev/null, stdout and
// stderr captured in files of a scratch directory of their own (so that the directory the program
// writes to holds only what it made), judged by exit status and output. A process can also be
// started and signalled while it runs, given environment variables, and given a limit on the size
// of the files it writes (RLIMIT_FSIZE, with SIGXFSZ ignored, so a write beyond it fails as on a
// full disk). (Its peak memory is not reported here: spawned from this process, it would start
// from this process's peak; tests/hostile/peak_memory.cpp measures it.)
#pragma once

#include "io/scratch_directory.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

extern char** environ;

namespace revolve::testing {

struct ProcessResult {
  int status = -1;  // exit status, or 128 + signal
  std::string out, err;
};

struct ProcessOptions {
  std::string directory{};                 // working directory ("": this process's)
  std::vector<std::string> environment{};  // "NAME=value" entries added to this process's environment
  long fileSizeLimit = -1;                 // bytes any file written may reach (-1: no limit)
};

// A process started and not yet waited for.
class RunningProcess {
 public:
  RunningProcess(const std::string& program, const std::vector<std::string>& args, const ProcessOptions& options = {})
      : capture_(std::make_unique<ScratchDirectory>()) {
    const std::string outPath = *capture_ / "stdout", errPath = *capture_ / "stderr";
    std::vector<std::string> argv{program};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> pointers;
    for (std::string& arg : argv) pointers.push_back(arg.data());
    pointers.push_back(nullptr);
    // This process's environment, with the given entries replacing any of the same name.
    std::vector<std::string> environment;
    for (char** entry = environ; *entry != nullptr; ++entry) {
      const std::string text = *entry;
      const std::string name = text.substr(0, text.find('=') + 1);
      bool replaced = false;
      for (const std::string& given : options.environment) replaced = replaced || given.rfind(name, 0) == 0;
      if (!replaced) environment.push_back(text);
    }
    environment.insert(environment.end(), options.environment.begin(), options.environment.end());
    std::vector<char*> environmentPointers;
    for (std::string& entry : environment) environmentPointers.push_back(entry.data());
    environmentPointers.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (!options.directory.empty()) posix_spawn_file_actions_addchdir_np(&actions, options.directory.c_str());
    // The child inherits resource limits and ignored signals: set them here around the spawn.
    rlimit previousLimit{};
    struct sigaction previousAction {};
    if (options.fileSizeLimit >= 0) {
      getrlimit(RLIMIT_FSIZE, &previousLimit);
      const rlimit limit{rlim_t(options.fileSizeLimit), previousLimit.rlim_max};
      setrlimit(RLIMIT_FSIZE, &limit);
      struct sigaction ignore {};
      ignore.sa_handler = SIG_IGN;
      sigaction(SIGXFSZ, &ignore, &previousAction);
    }
    const int spawned = posix_spawn(&pid_, pointers[0], &actions, nullptr, pointers.data(), environmentPointers.data());
    if (options.fileSizeLimit >= 0) {
      setrlimit(RLIMIT_FSIZE, &previousLimit);
      sigaction(SIGXFSZ, &previousAction, nullptr);
    }
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
      ADD_FAILURE() << "cannot run " << program << ": " << std::strerror(spawned);
      pid_ = -1;
    }
    outPath_ = outPath;
    errPath_ = errPath;
  }
  ~RunningProcess() {
    if (pid_ > 0 && !waited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  RunningProcess(const RunningProcess&) = delete;
  RunningProcess& operator=(const RunningProcess&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int number) const {
    if (pid_ > 0) kill(pid_, number);
  }
  std::string errSoFar() const { return readWholeFile(errPath_); }

  // Whether it has ended (without waiting for it: the result is kept for finish()).
  bool ended() {
    if (pid_ <= 0 || waited_) return true;
    waited_ = waitpid(pid_, &status_, WNOHANG) == pid_;
    return waited_;
  }

  // Waits for it to end; after `timeoutSeconds` (> 0) it is killed, and that is a test failure.
  ProcessResult finish(double timeoutSeconds = 0) {
    ProcessResult result;
    if (pid_ <= 0) return result;
    if (timeoutSeconds > 0) {
      for (int i = 0; !ended(); ++i) {
        if (i * 0.01 >= timeoutSeconds) {
          ADD_FAILURE() << "still running after " << timeoutSeconds << " s: killed";
          kill(pid_, SIGKILL);
          break;
        }
        usleep(10000);
      }
    }
    int status = status_;
    pid_t waited = pid_;
    if (!waited_) {
      while ((waited = waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {}
    }
    pid_ = -1;
    if (waited < 0) {
      ADD_FAILURE() << "waitpid failed";
      return result;
    }
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = readWholeFile(outPath_);
    result.err = readWholeFile(errPath_);
    return result;
  }

 private:
  std::unique_ptr<ScratchDirectory> capture_;
  std::string outPath_, errPath_;
  pid_t pid_ = -1;
  bool waited_ = false;
  int status_ = 0;
};

// Runs `program` with `args` to its end (killed, and a test failure, after `timeoutSeconds` > 0).
inline ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                                const ProcessOptions& options, double timeoutSeconds = 0) {
  RunningProcess process(program, args, options);
  return process.finish(timeoutSeconds);
}

// Runs `program` with `args`, in `directory` when one is given.
inline ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                                const std::string& directory = "") {
  return runProcess(program, args, ProcessOptions{.directory = directory});
}

}  // namespace revolve::testing
