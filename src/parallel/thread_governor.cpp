#include "parallel/thread_governor.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace monosph {
namespace {

// The first bytes of a /proc file ("" when it cannot be read).
std::string read_proc(const char* path) {
  char buf[512];
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  const ssize_t n = ::read(fd, buf, sizeof buf - 1);
  ::close(fd);
  return n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string();
}

}  // namespace

int own_runnable_threads() {
  DIR* dir = ::opendir("/proc/self/task");
  if (!dir) return -1;
  int running = 0;
  while (const dirent* e = ::readdir(dir)) {
    if (e->d_name[0] == '.') continue;
    const std::string stat =
        read_proc(("/proc/self/task/" + std::string(e->d_name) + "/stat").c_str());
    const size_t close = stat.rfind(')');
    if (close != std::string::npos && close + 2 < stat.size() && stat[close + 2] == 'R') ++running;
  }
  ::closedir(dir);
  return running;
}

int other_runnable_threads() {
  // /proc/loadavg: "0.52 0.58 0.59 3/467 12345": the fourth field is runnable/total. Own threads
  // are counted before and after it: one that went to sleep in between is still taken as own.
  const int before = own_runnable_threads();
  const std::string load = read_proc("/proc/loadavg");
  const int after = own_runnable_threads();
  int runnable = -1;
  if (before < 0 || std::sscanf(load.c_str(), "%*f %*f %*f %d/", &runnable) != 1) return -1;
  return std::max(0, runnable - std::max({before, after, 1}));  // the thread reading is running
}

ThreadGovernor::ThreadGovernor(int cpus, int most, Sampler others, std::chrono::milliseconds every)
    : cpus_(std::max(1, cpus)),
      most_(std::max(1, most)),
      threads_(most_),
      others_(std::move(others)),
      every_(every),
      next_(std::chrono::steady_clock::now() + every) {
  // Three samples at once: a run started beside busy processes starts with fewer threads.
  if (most_ > 1)
    for (int k = 0; k < 3; ++k) sample();
}

ThreadGovernor::~ThreadGovernor() {
  if (threads_ != most_) omp_set_num_threads(most_);
}

void ThreadGovernor::update() {
  ++calls_;
  thread_calls_ += threads_;
  if (most_ == 1) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + every_;
  sample();
}

void ThreadGovernor::sample() {
  const int others = others_();
  if (others < 0) return;  // no /proc: keep the thread count
  const int want = std::clamp(cpus_ - others, 1, most_);
  seen_ = want == want_ ? seen_ + 1 : 1;
  want_ = want;
  // Lower after three agreeing samples (60 ms: an idle machine shows a short-lived process in
  // about 1.6 % of the samples, never in two in a row), raise after ten (0.2 s), so that a process
  // that runs now and then does not make the count flap.
  const int needed = want < threads_ ? 3 : 10;
  if (want == threads_ || seen_ < needed) return;
  threads_ = want;
  ++changes_;
  omp_set_num_threads(threads_);
}

}  // namespace monosph
