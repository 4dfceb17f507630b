// Files the probes write besides probes.csv: profile_<name>.csv, across a restart.
#include <gtest/gtest.h>

#include "run_helpers.hpp"

namespace monosph::test {
namespace {

TEST(ProbeFiles, ProfileCsvOfARestartedRunEqualsTheUninterruptedOne) {
  // grain_bounce to 30 us at once, and to 20 us then restarted to 30 us (both land on 20 us, a
  // checkpoint time): the restart keeps the profile rows up to 20 us and appends the rest, as
  // probes.csv.
  const std::string scene =
      source("tests/scenes/grain_bounce.yaml") + " --set output.checkpoint_every=1e-5";
  const std::string full = out_dir("profile_full"), half = out_dir("profile_half");
  auto a = run_monosph("run " + scene + " --quiet --out " + full);
  ASSERT_EQ(a.code, 0) << a.output;
  auto b = run_monosph("run " + scene + " --set end_time=2e-5 --quiet --out " + half);
  ASSERT_EQ(b.code, 0) << b.output;
  auto c =
      run_monosph("run --restart " + half + "/final.h5 --quiet --set end_time=3e-5 --out " + half);
  ASSERT_EQ(c.code, 0) << c.output;
  auto tf = read_csv(full + "/profile_vy.csv"), tr = read_csv(half + "/profile_vy.csv");
  ASSERT_EQ(tf.head, (std::vector<std::string>{"time", "step", "position", "mean", "particles"}));
  ASSERT_EQ(tr.head, tf.head);
  ASSERT_EQ(tr["time"].size(), tf["time"].size());
  ASSERT_EQ(tf["time"].size() % 10, 0u);  // 10 bins per sample
  for (std::size_t q = 0; q < tf["time"].size(); ++q) {
    ASSERT_EQ(tr["time"][q], tf["time"][q]) << "row " << q;
    EXPECT_EQ(tr["step"][q], tf["step"][q]);
    EXPECT_EQ(tr["particles"][q], tf["particles"][q]);
    EXPECT_NEAR(tr["mean"][q], tf["mean"][q], 1e-12);
  }
  EXPECT_EQ(read_csv(half + "/probes.csv")["time"].size(), tf["time"].size() / 10);
}

}  // namespace
}  // namespace monosph::test
