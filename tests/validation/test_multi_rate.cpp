// Multi-rate stepping (docs/theory.md, "Multi-rate stepping") on a water column over an elastic
// floor (tests/scenes/tank_elastic_floor.yaml): the same deflection and forces as single-rate
// stepping with a tenth of the fluid steps, bit-identical on one and two threads and on restart.
#include <gtest/gtest.h>

#include <cmath>

#include "parallel/threads.hpp"
#include "run_helpers.hpp"

using namespace monosph::test;

namespace {

const std::string kScene = source("tests/scenes/tank_elastic_floor.yaml");

double mean_after(const Table& t, const std::string& col, double t0) {
  double s = 0;
  int n = 0;
  for (std::size_t k = 0; k < t["time"].size(); ++k)
    if (t["time"][k] >= t0) s += t[col][k], ++n;
  return s / n;
}

}  // namespace

TEST(MultiRate, ElasticFloorUnderWaterFollowsTheSingleRateRun) {
  const std::string a = out_dir("multi_rate_single"), b = out_dir("multi_rate_multi");
  const std::string args = "run " + kScene + " --quiet --threads 1 --out ";
  ASSERT_EQ(run_monosph(args + a).code, 0);
  ASSERT_EQ(run_monosph(args + b + " --set time_step.multi_rate=true").code, 0);
  auto sa = summary(a), sb = summary(b);
  // c_L / c0 = 10: about ten sub-steps of the floor per step of the water.
  const double steps_a = sa["steps"], steps_b = sb["steps"], sub = sb["solid_substeps"];
  EXPECT_LT(steps_b, 0.12 * steps_a) << steps_a << " " << steps_b;  // measured 771 / 7693
  EXPECT_GT(sub / steps_b, 9.5);                                    // measured 10.0
  auto ta = read_csv(a + "/probes.csv"), tb = read_csv(b + "/probes.csv");
  ASSERT_EQ(ta["time"].size(), tb["time"].size());
  // The floor's mean deflection (rest at y = -0.004) and the water's force on it along the run
  // (the column and floor ring with a period of about 12 ms): measured largest differences
  // 1.2e-6 m of a 2.9e-5 m peak (4 %) and 3.1 N/m of 58 N/m (5 %).
  double dy_peak = 0, dy_diff = 0, f_peak = 0, f_diff = 0;
  for (std::size_t k = 0; k < ta["time"].size(); ++k) {
    dy_peak = std::max(dy_peak, std::abs(ta["floor_y"][k] + 0.004));
    dy_diff = std::max(dy_diff, std::abs(ta["floor_y"][k] - tb["floor_y"][k]));
    f_peak = std::max(f_peak, std::abs(ta["on_floor_y"][k]));
    f_diff = std::max(f_diff, std::abs(ta["on_floor_y"][k] - tb["on_floor_y"][k]));
  }
  EXPECT_GT(dy_peak, 2e-5);  // the floor did bend
  EXPECT_LT(dy_diff, 0.08 * dy_peak);
  EXPECT_LT(f_diff, 0.08 * f_peak);
  // Over the last 20 ms the clamps carry the water (39.2 N/m) and the floor (14.4 N/m).
  const double ra = mean_after(ta, "clamps_y", 0.01), rb = mean_after(tb, "clamps_y", 0.01);
  EXPECT_NEAR(ra, 53.7, 0.05 * 53.7);
  EXPECT_NEAR(rb, ra, 0.02 * ra);
}

TEST(MultiRate, BitIdenticalOnOneAndTwoThreadsAndAfterARestart) {
  const std::string opts =
      " --quiet --set time_step.multi_rate=true end_time=0.004 "
      "output.checkpoint_every=0.003";
  const std::string a = out_dir("multi_rate_t1"), b = out_dir("multi_rate_t2");
  if (monosph::usable_cpus() < 2) GTEST_SKIP() << "one usable CPU: no second thread";
  ASSERT_EQ(run_monosph("run " + kScene + opts + " --threads 1 --out " + a).code, 0);
  ASSERT_EQ(run_monosph("run " + kScene + opts + " --threads 2 --fixed-threads --out " + b).code,
            0);
  expect_two_threads(b);
  expect_same_checkpoint(a + "/final.h5", b + "/final.h5");
  // From the checkpoint at 3 ms to the end again.
  auto r = run_monosph("run --restart " + a + "/checkpoint.h5 --out " + b + " --threads 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  expect_same_checkpoint(a + "/final.h5", b + "/final.h5");
}

TEST(MultiRate, GrainSettlingOntoAnElasticFloorFollowsTheSingleRateRun) {
  // tests/scenes/grain_on_elastic_floor.yaml: the grain falls 4 mm through water, hits the floor
  // at 54 ms and comes to rest on it. Measured single-rate / multi-rate: 21762 / 8158 steps
  // (23196 floor sub-steps; grain contact, a slow force, holds the step once they touch), first
  // contact in the probe row at 54.0 ms in both, top fall speed 0.3378 / 0.3373 m/s, mean height
  // after 80 ms 5.904 / 5.922 mm (dp = 2 mm), largest overlap 19 / 21 um.
  const std::string scene = source("tests/scenes/grain_on_elastic_floor.yaml");
  const std::string a = out_dir("multi_rate_grain_single"), b = out_dir("multi_rate_grain_multi");
  const std::string args = "run " + scene + " --quiet --threads 1 --out ";
  ASSERT_EQ(run_monosph(args + a).code, 0);
  ASSERT_EQ(run_monosph(args + b + " --set time_step.multi_rate=true").code, 0);
  const double steps_a = summary(a)["steps"], steps_b = summary(b)["steps"];
  EXPECT_LT(steps_b, 0.5 * steps_a);
  auto ta = read_csv(a + "/probes.csv"), tb = read_csv(b + "/probes.csv");
  auto first_contact = [](const Table& t) {
    for (std::size_t k = 0; k < t["time"].size(); ++k)
      if (t["pen"][k] > 0) return t["time"][k];
    return -1.0;
  };
  EXPECT_GT(first_contact(ta), 0.04);
  EXPECT_NEAR(first_contact(tb), first_contact(ta), 0.0025);  // one probe row (2 ms)
  EXPECT_NEAR(min_of(tb["v"]), min_of(ta["v"]), 0.01 * std::abs(min_of(ta["v"])));
  EXPECT_NEAR(mean_after(tb, "y", 0.08), mean_after(ta, "y", 0.08), 0.025 * 0.002);
  EXPECT_LT(max_of(tb["pen"]), 0.05 * 0.002);  // the grain stays on the floor
}
