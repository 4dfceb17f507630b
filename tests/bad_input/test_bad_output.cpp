// Output that cannot be written: a full disk, a file size limit, /dev/full, a folder in the way.
// Exit code 6 (2 when the output folder is unusable from the start) and one line naming the
// file; no crash at exit, and no summary.json, final.h5 or .pvd left that claims success.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "fault_helpers.hpp"

using namespace monosph::test;
namespace fs = std::filesystem;

namespace {

constexpr int kOutputFailed = 6;
const std::string kWave = "cases/acoustic_wave/scene.yaml";   // 800 particles, frames of 15-31 kB
const std::string kGrain = "tests/scenes/grain_bounce.yaml";  // has a profile probe (vy)

std::string run_args(const std::string& scene, const std::string& out, const std::string& more) {
  return "run " + source(scene) + " --out " + out + " --steps 5 " + more;
}

struct Case {
  const char* name;
  const char* scene;
  const char* setup;    // shell commands run in the output folder before the run ("" none)
  const char* prefix;   // before the binary in its shell (a file size limit)
  const char* args;     // extra run arguments
  int code;             // expected exit code
  const char* message;  // in the one line
};

// ulimit -f counts 512-byte blocks (dash); SIGXFSZ is ignored so that writes fail with EFBIG.
const Case kCases[] = {
    {"first_frame_over_size_limit", "wave", "", "trap '' XFSZ; ulimit -f 20;", "", kOutputFailed,
     "acoustic_wave_000000.vtu"},
    {"later_frame_over_size_limit", "wave", "", "trap '' XFSZ; ulimit -f 60;", "", kOutputFailed,
     "acoustic_wave_000005.vtu"},
    {"final_h5_over_size_limit", "wave", "", "trap '' XFSZ; ulimit -f 200;", "", kOutputFailed,
     "final.h5"},
    {"checkpoint_over_size_limit", "wave", "", "trap '' XFSZ; ulimit -f 200;",
     "--set output.checkpoint_every=1e-4", kOutputFailed, "checkpoint.h5"},
    {"probes_csv_on_dev_full", "wave", "ln -s /dev/full probes.csv", "", "", kOutputFailed,
     "probes.csv"},
    {"profile_csv_on_dev_full", "grain", "ln -s /dev/full profile_vy.csv", "", "", kOutputFailed,
     "profile_vy.csv"},
    // An earlier run's summary.json, final.h5, checkpoint.h5 are removed at the start: one that
    // cannot be removed stops the run there (exit 2).
    {"summary_json_is_a_folder", "wave", "mkdir -p summary.json/x", "", "", 2, "cannot remove"},
    {"final_h5_is_a_folder", "wave", "mkdir -p final.h5/x", "", "", 2, "cannot remove"},
    {"summary_tmp_is_a_folder", "wave", "mkdir -p summary.json.tmp/x", "", "", kOutputFailed,
     "summary.json"},
    {"final_h5_tmp_is_a_folder", "wave", "mkdir -p final.h5.tmp/x", "", "", kOutputFailed,
     "final.h5"},
    {"summary_tmp_on_dev_full", "wave", "ln -s /dev/full summary.json.tmp", "", "", kOutputFailed,
     "summary.json"},
    {"final_h5_tmp_on_dev_full", "wave", "ln -s /dev/full final.h5.tmp", "", "", kOutputFailed,
     "final.h5"},
    {"pvd_tmp_on_dev_full", "wave", "ln -s /dev/full acoustic_wave.pvd.tmp", "", "", kOutputFailed,
     "acoustic_wave.pvd"},
    {"frame_tmp_on_dev_full", "wave", "ln -s /dev/full acoustic_wave_000005.vtu.tmp", "", "",
     kOutputFailed, "acoustic_wave_000005.vtu"},
    {"pvd_is_a_folder", "wave", "mkdir -p acoustic_wave.pvd/x", "", "", kOutputFailed,
     "acoustic_wave.pvd"},
    {"frame_is_a_folder", "wave", "mkdir -p acoustic_wave_000005.vtu/x", "", "", kOutputFailed,
     "acoustic_wave_000005.vtu"},
    {"checkpoint_is_a_folder", "wave", "mkdir -p checkpoint.h5/x", "",
     "--set output.checkpoint_every=1e-4", 2, "cannot remove"},
    {"checkpoint_tmp_is_a_folder", "wave", "mkdir -p checkpoint.h5.tmp/x", "",
     "--set output.checkpoint_every=1e-4", kOutputFailed, "checkpoint.h5"},
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

}  // namespace

class BadOutput : public ::testing::TestWithParam<Case> {};

TEST_P(BadOutput, FailsWithOneLineAndLeavesNothingThatClaimsSuccess) {
  const Case& c = GetParam();
  const std::string out = out_dir(std::string("bad_output_") + c.name);
  fs::create_directories(out);
  if (*c.setup) {
    ASSERT_EQ(std::system(("cd " + out + " && " + c.setup).c_str()), 0);
  }
  const std::string scene = std::string(c.scene) == "wave" ? kWave : kGrain;
  auto r = run_limited(run_args(scene, out, c.args), c.prefix);
  expect_clean_failure(r, c.code, {c.message, out});
  expect_nothing_claims_success(out);
}

INSTANTIATE_TEST_SUITE_P(Faults, BadOutput, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// An output folder that cannot be used at all: exit 2 before the run starts.
TEST(BadOutput, OutIsARegularFile) {
  const std::string dir = out_dir("bad_output_out_is_file");
  fs::create_directories(dir);
  std::ofstream(dir + "/file") << "x";
  auto r = run_limited(run_args(kWave, dir + "/file", ""));
  expect_clean_failure(r, 2, {dir + "/file"});
  r = run_limited(run_args(kWave, dir + "/file/below", ""));
  expect_clean_failure(r, 2, {dir + "/file/below"});
  r = run_limited(run_args(kWave, "/dev/null", ""));
  expect_clean_failure(r, 2, {"/dev/null"});
}

// A size limit large enough for everything: the same run completes (the cases above fail for
// their fault, not for the setup).
TEST(BadOutput, RunWithinTheSizeLimitCompletes) {
  const std::string out = out_dir("bad_output_within_limit");
  auto r = run_limited(run_args(kWave, out, ""), "trap '' XFSZ; ulimit -f 2000;");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(summary(out)["status"], "completed");
}

// A really full file system (a small tmpfs; needs root, skipped otherwise): the run writes about
// 265 kB, so at each size it fails (at a frame, final.h5 or summary.json at 220k) with exit 6 and
// one line, and does not crash at exit (HDF5 did, after a failed write).
class FullDisk : public ::testing::TestWithParam<const char*> {};

TEST_P(FullDisk, RunFailsCleanly) {
  const std::string mnt = out_dir(std::string("bad_output_tmpfs_") + GetParam());
  fs::create_directories(mnt);
  const std::string mount =
      "mount -t tmpfs -o size=" + std::string(GetParam()) + " tmpfs " + mnt + " 2>/dev/null";
  if (std::system(mount.c_str()) != 0) GTEST_SKIP() << "cannot mount a tmpfs (not root?)";
  struct Unmount {
    std::string dir;
    ~Unmount() { (void)std::system(("umount " + dir).c_str()); }
  } unmount{mnt};
  const std::string out = mnt + "/run";
  auto r = run_limited(run_args(kWave, out, ""));
  expect_clean_failure(r, kOutputFailed, {"cannot write", out});
  if (fs::exists(out)) {
    expect_nothing_claims_success(out);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, FullDisk,
                         ::testing::Values("40k", "60k", "100k", "150k", "200k", "220k"));

// Under mpirun a write that fails on one rank (a piece of rank 1, the .pvd of rank 0) stops every
// rank with exit 6, no hang. (mpirun adds its own lines after the first.)
class BadOutputMpi : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(BadOutputMpi, EveryRankStops) {
  const auto [link, message] = GetParam();
  const std::string out = out_dir(std::string("bad_output_mpi_") + link);
  fs::create_directories(out);
  fs::create_symlink("/dev/full", fs::path(out) / link);
  auto r = run_command("timeout " + std::to_string(kTimeLimitSeconds) +
                       " " MONOSPH_MPIEXEC
                       " --allow-run-as-root --oversubscribe --bind-to none -x OMP_NUM_THREADS=1"
                       " -np 2 " MONOSPH_BIN " " +
                       run_args(kWave, out, "--quiet") + " 2>&1");
  EXPECT_EQ(r.code, kOutputFailed) << r.output;
  EXPECT_NE(r.output.find("cannot write " + out + "/" + message), std::string::npos) << r.output;
  expect_nothing_claims_success(out);
}

INSTANTIATE_TEST_SUITE_P(Links, BadOutputMpi,
                         ::testing::Values(std::pair{"probes.csv", "probes.csv"},
                                           std::pair{"acoustic_wave_000005_p1.vtu.tmp",
                                                     "acoustic_wave_000005_p1.vtu"},
                                           std::pair{"acoustic_wave.pvd.tmp", "acoustic_wave.pvd"}),
                         [](const auto& info) {
                           std::string n = info.param.second;
                           std::replace(n.begin(), n.end(), '.', '_');
                           return n;
                         });
