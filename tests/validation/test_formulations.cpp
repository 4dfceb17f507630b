// The non-hourglass formulation (Zhang et al. 2024) and dual-criteria time stepping on the
// oscillating plate at 10 particles across (full runs: cases/oscillating_plate/README.md).
#include <gtest/gtest.h>

#include "run_helpers.hpp"

using namespace monosph::test;

namespace {
const std::string coarse =
    " --quiet --set dp=0.002 output.every=0.3 end_time=0.6";  // 10 across, two periods
}

TEST(NonHourglassPlate, OscillatesCoherentlyWithoutHourglassControl) {
  // Zhang et al. 2024 Table 1 (H/dp = 30, v_f = 0.05): T = 0.279 s, +9.8 % of thin-plate theory.
  // Measured here at H/dp = 10: +9.6 %. Without the Laplacian (Eq. 19) the same set-up with the
  // stress divergence and no hourglass control disorders (OscillatingPlate tests).
  const std::string out = out_dir("enog_plate");
  auto r = run_monosph("run " + source("cases/oscillating_plate/scene_enog.yaml") + " --out " +
                       out + coarse);
  ASSERT_EQ(r.code, 0) << r.output;
  auto js = summary(out);
  const double e = js["metrics"]["period"]["relative_error"].get<double>();
  EXPECT_GT(e, 0.05);
  EXPECT_LT(e, 0.14);
  auto t = read_csv(out + "/probes.csv");
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_GT(min_of(t["min_distance"]), 0.8);
}

TEST(DualCriteria, FewerConfigurationUpdatesSamePlate) {
  // Both with Newmark gamma = 0.6: with velocity Verlet the dual-criteria plate is not stable
  // here (particles meet at 0.24-0.27 s; cases/oscillating_plate/README.md). Single: CFL 0.4.
  const std::string one = out_dir("dual_off"), two = out_dir("dual_on");
  const std::string scene = "run " + source("cases/oscillating_plate/scene_enog.yaml");
  auto a = run_monosph(scene + " --out " + one + coarse +
                       " time_step.newmark_gamma=0.6 time_step.cfl=0.4");
  ASSERT_EQ(a.code, 0) << a.output;
  auto b = run_monosph(scene + " --out " + two + coarse + " time_step.newmark_gamma=0.6" +
                       " 'time_step.dual_criteria={advection_cfl: 0.2, acoustic_cfl: 0.4}'");
  ASSERT_EQ(b.code, 0) << b.output;
  auto sa = summary(one), sb = summary(two);
  EXPECT_EQ(sa["configuration_updates"].get<long>(), sa["steps"].get<long>() + 1);
  // About one update per 14 acoustic steps here (v_max = 2.9 m/s, c0 = 65 m/s): 2663 updates.
  EXPECT_LT(sb["configuration_updates"].get<long>(), sb["steps"].get<long>() / 8);
  const double ta = sa["metrics"]["period"]["value"].get<double>();
  const double tb = sb["metrics"]["period"]["value"].get<double>();
  EXPECT_NEAR(tb, ta, 0.05 * ta);  // measured: -2.3 % (0.2722 s against 0.2786 s)
  auto t = read_csv(two + "/probes.csv");
  EXPECT_LT(max_of(t["disorder"]), 0.05);
}

TEST(DualCriteria, EulerianHourglassPlateNeedsRefreshedKernelValues) {
  // MMB's hourglass-controlled plate (10 across, 0.1 s: past the first peak of the tip at
  // 0.065 s). Acoustic steps with refreshed kernel values (the default) follow the single-step
  // run (tip peak 0.1083 m); with `kernel: frozen` the plate bends on past 0.13 m and leaves the
  // domain at 0.067 s (measured). The deformation gradient of the hourglass control is
  // recomputed in every acoustic step either way.
  const std::string scene = "run " + source("cases/oscillating_plate/scene.yaml");
  const std::string set =
      " --quiet --set dp=0.002 end_time=0.1 output.every=1"
      " output.checkpoint_every=0 time_step.dual_criteria.acoustic_cfl=0.3";
  const std::string one = out_dir("dual_eul_off"), two = out_dir("dual_eul_on"),
                    three = out_dir("dual_eul_frozen");
  auto a = run_monosph(scene + " --out " + one + set);
  ASSERT_EQ(a.code, 0) << a.output;
  auto b =
      run_monosph(scene + " --out " + two + set + " time_step.dual_criteria.advection_cfl=0.2");
  ASSERT_EQ(b.code, 0) << b.output;
  const double pa = max_of(read_csv(one + "/probes.csv")["tip_y"]);
  const double pb = max_of(read_csv(two + "/probes.csv")["tip_y"]);
  EXPECT_NEAR(pb, pa, 0.01 * pa);
  EXPECT_LT(summary(two)["configuration_updates"].get<long>(), summary(two)["steps"].get<long>());
  auto c = run_monosph(scene + " --out " + three + set +
                       " time_step.dual_criteria.advection_cfl=0.2"
                       " time_step.dual_criteria.kernel=frozen");
  EXPECT_NE(c.code, 0);  // stopped: a particle left the domain
}

TEST(DualCriteria, BadValuesNameTheKey) {
  auto r = run_monosph("run " + source("cases/oscillating_plate/scene_enog.yaml") + " --out " +
                       out_dir("dual_bad") + " --set 'time_step.dual_criteria={advection_cfl: 2}'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("time_step.dual_criteria.advection_cfl"), std::string::npos) << r.output;
}
