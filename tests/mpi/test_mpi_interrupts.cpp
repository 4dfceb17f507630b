// Interrupts on 3 ranks: a signal to one rank stops every rank at the same step; SIGUSR1 to
// mpirun (which forwards it at once); SIGINT / SIGTERM to mpirun (which passes SIGTERM on after
// 1 s); SIGKILL of the ranks. A restart on 3 ranks from checkpoint.h5 equals the uninterrupted
// 3-rank run (to round-off: the restart decomposes the particles anew).
#include <gtest/gtest.h>

#include <csignal>
#include <cstring>

#include "../validation/child_process.hpp"
#include "mpi_helpers.hpp"

namespace monosph::test {
namespace {

const std::string kScene = source("cases/acoustic_wave/scene.yaml");
const std::string kOpts =
    " --threads 1 --quiet --set dp=0.005 output.checkpoint_every=0.005 output.every=0.01";

std::string mpirun_line(const std::string& args) {
  return MONOSPH_MPIEXEC
         " --allow-run-as-root --oversubscribe --bind-to none -x OMP_NUM_THREADS=1"
         " -np 3 " MONOSPH_BIN " " +
         args;
}

// The ranks of the mpirun `c` (its children), or a test failure.
std::vector<pid_t> ranks_of(const Child& c) {
  std::vector<pid_t> r;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((r = children_of(c.pid)).size() < 3 && std::chrono::steady_clock::now() < end) pause_ms(5);
  EXPECT_EQ(r.size(), 3u) << "ranks of mpirun " << c.pid;
  return r;
}

// The summary, checkpoint.h5 and probes.csv of an interrupted run hold the same last step.
void expect_interrupted_files(const std::string& dir) {
  auto js = summary(dir);
  EXPECT_EQ(js["status"], "interrupted");
  EXPECT_EQ(js["ranks"], 3);
  const long steps = js["steps"];
  Particles<2> p;
  EXPECT_EQ(read_checkpoint<2>(dir + "/checkpoint.h5", p).step, steps);
  const std::string row = last_line(file_text(dir + "/probes.csv"));
  EXPECT_EQ(row.substr(row.find(',') + 1, row.find(',', row.find(',') + 1) - row.find(',') - 1),
            std::to_string(steps));
}

TEST(MpiInterrupts, RestartAfterASignalOnThreeRanksEqualsTheUninterruptedRun) {
  const std::string full = out_dir("mpi_interrupt_full");
  auto r = mpirun(3, "run " + kScene + " --out " + full + kOpts + " end_time=0.1");
  ASSERT_EQ(r.code, 0) << r.output;
  struct Way {
    std::string name;
    int sig;
    bool to_mpirun, every_rank;
  };
  for (const Way& w : {Way{"SIGINT to one rank", SIGINT, false, false},
                       Way{"SIGTERM to one rank", SIGTERM, false, false},
                       Way{"SIGUSR1 to mpirun", SIGUSR1, true, false},
                       Way{"SIGKILL to every rank", SIGKILL, false, true}}) {
    SCOPED_TRACE(w.name);
    const std::string dir = out_dir("mpi_interrupt_" + std::to_string(w.sig));
    std::vector<pid_t> ranks;
    const int code =
        interrupt_run(mpirun_line("run " + kScene + " --out " + dir + kOpts + " end_time=0.1"), dir,
                      [&](Child& c) {
                        ranks = ranks_of(c);
                        if (w.to_mpirun) kill(c.pid, w.sig);
                        for (std::size_t k = 0; k < ranks.size() && !w.to_mpirun; ++k)
                          if (k == 0 || w.every_rank) kill(ranks[k], w.sig);
                      });
    for (pid_t p : ranks) EXPECT_FALSE(alive(p)) << "rank " << p << " outlived mpirun";
    if (w.sig == SIGKILL) {
      EXPECT_NE(code, 0);
      EXPECT_FALSE(std::filesystem::exists(dir + "/summary.json"));
    } else {
      EXPECT_EQ(code, 128 + w.sig) << file_text(log_of(dir));  // mpirun: the ranks' code
      expect_interrupted_files(dir);
    }
    auto b =
        mpirun(3, "run --restart " + dir + "/checkpoint.h5 --out " + dir + " --threads 1 --quiet");
    ASSERT_EQ(b.code, 0) << b.output;
    EXPECT_EQ(summary(dir)["status"], "completed");
    expect_same_state<2>(full + "/final.h5", dir + "/final.h5");
    expect_same_probes(full + "/probes.csv", dir + "/probes.csv");
  }
}

TEST(MpiInterrupts, SigintAndSigtermToMpirunStopTheRanksWithTheirFiles) {
  // mpirun passes either on to the ranks as SIGTERM after 1 s and kills them 1 s later
  // (odls_base_sigkill_timeout): the small run writes its files well within that.
  for (int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(strsignal(sig));
    const std::string dir = out_dir("mpi_interrupt_mpirun_" + std::to_string(sig));
    const int code =
        interrupt_run(mpirun_line("run " + kScene + " --out " + dir + kOpts + " end_time=100"), dir,
                      [&](Child& c) { kill(c.pid, sig); });
    EXPECT_NE(code, 0) << file_text(log_of(dir));
    expect_interrupted_files(dir);
  }
}

}  // namespace
}  // namespace monosph::test
