// peak_memory FILE PROGRAM [ARGS...]: runs PROGRAM and writes its peak resident memory, in KB, to
// FILE; exits with PROGRAM's status (128 + signal if one ended it). What /usr/bin/time -f %M
// measures, for the tests to measure without it.
//
// Why a process of its own: at exec the kernel starts a process's peak from the memory image it
// replaces, and a child spawned straight from a large test process would report the test's own
// peak. Forked from this small program, the child starts from this program's.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: peak_memory FILE PROGRAM [ARGS...]\n");
    return 2;
  }
  const pid_t child = fork();
  if (child < 0) {
    std::perror("peak_memory: fork");
    return 2;
  }
  if (child == 0) {
    execv(argv[2], argv + 2);
    std::perror("peak_memory: exec");
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(child, &status, 0, &usage) != child) {
    std::perror("peak_memory: wait4");
    return 2;
  }
  std::FILE* out = std::fopen(argv[1], "w");
  if (out == nullptr || std::fprintf(out, "%ld\n", usage.ru_maxrss) < 0 || std::fclose(out) != 0) {
    std::perror("peak_memory: cannot write the figure");
    return 2;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
