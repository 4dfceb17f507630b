// Thread defaults on a shared machine: study and stability never start more threads than CPUs.
#include <gtest/gtest.h>

#include "core/threads.hpp"

using namespace monosph;

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
