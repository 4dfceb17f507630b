// A run on a shared machine: with other processes holding every CPU, a run asked for two threads
// lowers itself to one and ends with the same state as a run on one thread (results do not depend
// on the thread count, also when it changes mid-run). Raising it again is tested with a simulated
// load (unit test ThreadGovernor.FollowsTheLoadOfOtherProcesses): here the tests ctest runs beside
// this one may keep a CPU busy.
#include <gtest/gtest.h>

#include "../busy_children.hpp"
#include "child_process.hpp"
#include "parallel/threads.hpp"
#include "run_helpers.hpp"

namespace monosph::test {
namespace {

TEST(SharedMachine, TwoThreadsDropToOneWhileOtherProcessesHoldTheCpus) {
  const int cpus = usable_cpus();
  if (cpus < 2) GTEST_SKIP() << "one usable CPU: a run has one thread anyway";
  // The dam break, 4658 particles, 4000 steps: about 9 s on one thread of the 2-core machine.
  const std::string args = "run " + source("cases/dam_break/scene.yaml") +
                           " --steps 4000 --set output.every=0 --quiet --threads ";
  const std::string shared = out_dir("shared_machine_two"), alone = out_dir("shared_machine_one");
  BusyChildren busy(cpus);
  ASSERT_EQ(static_cast<int>(busy.pids.size()), cpus);
  Child run =
      start_child(std::string(MONOSPH_BIN) + " " + args + "2 --out " + shared, shared + ".log");
  // Once it steps (its first probe row is written), give it two seconds under load, then free the
  // CPUs (it may raise its thread count again 0.2 s later if nothing else runs).
  ASSERT_TRUE(wait_for_file(run, shared + "/probes.csv")) << file_text(shared + ".log");
  pause_ms(2000);
  busy.stop();
  ASSERT_EQ(wait_exit(run), 0) << file_text(shared + ".log");
  const auto js = summary(shared);
  EXPECT_EQ(js["threads"], 2);
  EXPECT_LT(js["threads_mean"].get<double>(), 1.95)
      << "not lowered while " << cpus << " other processes were busy";
  EXPECT_NE(file_text(shared + ".log").find("other processes were busy"), std::string::npos);
  // Bit for bit the run on one thread.
  ASSERT_EQ(run_monosph(args + "1 --out " + alone).code, 0);
  EXPECT_EQ(summary(alone)["threads_mean"], 1.0);
  expect_same_checkpoint(alone + "/final.h5", shared + "/final.h5");
}

TEST(SharedMachine, FixedThreadsHoldTwoThreadsWhileOtherProcessesHoldTheCpus) {
  // --fixed-threads: a thread-count comparison on a busy machine still compares two threads with
  // one (the governor would run both on one thread and the comparison would check nothing).
  const int cpus = usable_cpus();
  if (cpus < 2) GTEST_SKIP() << "one usable CPU: a run has one thread anyway";
  // 60 steps of the dam break: 0.15 s alone, some seconds on two threads beside busy processes.
  const std::string args = "run " + source("cases/dam_break/scene.yaml") +
                           " --steps 60 --set output.every=0 --quiet --threads ";
  const std::string fixed = out_dir("shared_machine_fixed"), alone = out_dir("shared_machine_1");
  {
    BusyChildren busy(cpus);
    ASSERT_EQ(static_cast<int>(busy.pids.size()), cpus);
    auto r = run_monosph(args + "2 --fixed-threads --out " + fixed);
    ASSERT_EQ(r.code, 0) << r.output;
  }
  expect_two_threads(fixed);
  ASSERT_EQ(run_monosph(args + "1 --out " + alone).code, 0);
  expect_same_checkpoint(alone + "/final.h5", fixed + "/final.h5");
}

}  // namespace
}  // namespace monosph::test
