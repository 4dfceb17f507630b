#pragma once
// Child processes that keep CPUs busy, for the tests of a run on a shared machine.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vector>

namespace monosph::test {

// `n` child processes that spin until stop() or the destructor kills them.
struct BusyChildren {
  std::vector<pid_t> pids;
  explicit BusyChildren(int n) {
    for (int i = 0; i < n; ++i) {
      const pid_t pid = fork();
      if (pid == 0) {
        volatile unsigned long x = 0;
        for (;;) x = x + 1;
      }
      if (pid > 0) pids.push_back(pid);
    }
  }
  void stop() {
    for (pid_t p : pids) kill(p, SIGKILL);
    for (pid_t p : pids) waitpid(p, nullptr, 0);
    pids.clear();
  }
  ~BusyChildren() { stop(); }
};

}  // namespace monosph::test
