// Threads on a shared machine: study and stability never start more threads than CPUs, and a run
// lowers its thread count while other processes keep the CPUs busy.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "../busy_children.hpp"
#include "parallel/thread_governor.hpp"
#include "parallel/threads.hpp"

using namespace monosph;
using monosph::test::BusyChildren;

TEST(Threads, JobsTimesThreadsNeverExceedTheCpus) {
  const int cpus = usable_cpus();
  for (int jobs : {1, 2, 3, 1000}) {
    for (int threads : {0, 1, 2, 1000}) {
      const auto r = jobs_and_threads("study", jobs, threads);
      EXPECT_GE(r.jobs, 1);
      EXPECT_GE(r.threads, 1);
      EXPECT_LE(r.jobs, std::min(jobs, cpus));
      EXPECT_LE(r.jobs * r.threads, cpus) << jobs << " jobs, " << threads << " threads";
      if (threads == 0) {  // the default
        EXPECT_EQ(r.threads, std::max(1, cpus / r.jobs));
      }
      if (threads > 0 && jobs * threads <= cpus) {  // a request that fits is kept
        EXPECT_EQ(r.jobs, jobs);
        EXPECT_EQ(r.threads, threads);
      }
    }
  }
}

// The governor follows the other processes' load: it lowers the thread count after three agreeing
// samples, raises it after ten, and restores the count asked for at the end.
TEST(ThreadGovernor, FollowsTheLoadOfOtherProcesses) {
  const int before = omp_get_max_threads();
  int others = 0;
  {
    ThreadGovernor g(
        4, 4, [&] { return others; }, std::chrono::milliseconds(0));
    auto run = [&](int n) {
      for (int i = 0; i < n; ++i) g.update();
    };
    run(5);
    EXPECT_EQ(g.threads(), 4);
    others = 2;  // two busy CPUs: two threads after three samples
    run(2);
    EXPECT_EQ(g.threads(), 4);
    others = 0;  // a blip: no change
    run(1);
    others = 2;
    run(2);
    EXPECT_EQ(g.threads(), 4);
    run(1);
    EXPECT_EQ(g.threads(), 2);
    EXPECT_EQ(omp_get_max_threads(), 2);
    others = 7;  // more busy threads than CPUs: one thread, never zero
    run(3);
    EXPECT_EQ(g.threads(), 1);
    others = 0;  // the others have gone: back to four after ten samples
    run(9);
    EXPECT_EQ(g.threads(), 1);
    run(1);
    EXPECT_EQ(g.threads(), 4);
    for (int i = 0; i < 40; ++i) {  // a process that runs now and then: lowered, not raised
      others = i % 4 == 0 ? 0 : 3;
      g.update();
    }
    EXPECT_EQ(g.threads(), 1);
    others = -1;  // /proc unreadable: kept
    run(20);
    EXPECT_EQ(g.threads(), 1);
    EXPECT_EQ(g.changes(), 4);
    EXPECT_GT(g.mean_threads(), 1.0);
    EXPECT_LT(g.mean_threads(), 4.0);
  }
  EXPECT_EQ(omp_get_max_threads(), 4);  // restored
  {  // started beside three busy processes: one thread from the start
    ThreadGovernor g(4, 4, [] { return 3; });
    EXPECT_EQ(g.threads(), 1);
    EXPECT_EQ(omp_get_max_threads(), 1);
  }
  EXPECT_EQ(omp_get_max_threads(), 4);
  omp_set_num_threads(before);
}

namespace {

// Samples of other_runnable_threads() over about 0.2 s, sorted.
std::vector<int> samples() {
  std::vector<int> s;
  for (int i = 0; i < 20; ++i) {
    s.push_back(other_runnable_threads());
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::sort(s.begin(), s.end());
  return s;
}

}  // namespace

TEST(ThreadGovernor, CountsOtherProcessesNotItsOwnThreads) {
  ASSERT_GE(other_runnable_threads(), 0) << "/proc/loadavg or /proc/self/task unreadable";
  {
    BusyChildren busy(2);
    ASSERT_EQ(busy.pids.size(), 2u);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const auto s = samples();
    EXPECT_GE(s[s.size() / 2], 2) << "median of the other runnable threads with 2 busy children";
  }
  // Three busy threads of this process are not other processes. Samples with them spinning and
  // with them asleep are taken in turn, so that the load of the tests ctest runs beside this one
  // changes both alike: counted as others, they would add 3 to every pair.
  std::atomic<bool> stop{false}, spin{false};
  std::vector<std::thread> own;
  for (int i = 0; i < 3; ++i)
    own.emplace_back([&] {
      while (!stop.load(std::memory_order_relaxed))
        if (!spin.load(std::memory_order_relaxed))
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
  std::vector<int> added;
  for (int k = 0; k < 20; ++k) {
    spin = true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const int with = other_runnable_threads(), own_running = own_runnable_threads();
    spin = false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    added.push_back(with - other_runnable_threads());
    EXPECT_GE(own_running, 3) << "the three spinning threads are this process's";
  }
  std::sort(added.begin(), added.end());
  EXPECT_LT(added[added.size() / 2], 2) << "own spinning threads counted as other processes";
  stop = true;
  for (auto& t : own) t.join();
}
