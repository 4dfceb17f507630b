// Fewer OpenMP threads while other processes keep the CPUs busy.
#pragma once

#include <chrono>
#include <functional>

namespace monosph {

// Runnable threads of other processes: the kernel's runnable count (/proc/loadavg) less this
// process's runnable threads (/proc/self/task/*/stat); -1 when /proc cannot be read.
int other_runnable_threads();
// Runnable threads of this process: state R in /proc/self/task/<tid>/stat; -1 when unreadable.
int own_runnable_threads();

// Lowers the thread count of the parallel regions to the CPUs that other processes leave free and
// raises it back (up to `most`) when they go. OpenMP threads wait for each other at every barrier
// of a step: with more threads than free CPUs a descheduled thread stalls the others (measured:
// 2 threads with one other busy process 20-36x slower than 1 thread). Results do not depend on the
// thread count, so it may change between any two steps.
class ThreadGovernor {
 public:
  using Sampler = std::function<int()>;  // other runnable threads, -1: unknown
  // `cpus`: the CPUs this process may use; `most`: the thread count asked for. Takes three samples
  // at once, so that a run started beside busy processes starts lowered.
  ThreadGovernor(int cpus, int most, Sampler others = other_runnable_threads,
                 std::chrono::milliseconds every = std::chrono::milliseconds(20));
  ~ThreadGovernor();  // restores `most`
  ThreadGovernor(const ThreadGovernor&) = delete;
  ThreadGovernor& operator=(const ThreadGovernor&) = delete;
  // Call between parallel regions (once per step): samples at most every `every` and sets
  // omp_set_num_threads when the thread count changes.
  void update();
  int threads() const { return threads_; }
  // Thread count averaged over the calls to update() (over the steps).
  double mean_threads() const { return calls_ ? double(thread_calls_) / calls_ : threads_; }
  long changes() const { return changes_; }

 private:
  void sample();
  int cpus_, most_, threads_;
  Sampler others_;
  std::chrono::milliseconds every_;
  std::chrono::steady_clock::time_point next_;
  int want_ = 0, seen_ = 0;  // the thread count the last samples agree on, and how many agree
  long calls_ = 0, thread_calls_ = 0, changes_ = 0;
};

}  // namespace monosph
