// Shortened runs of the solid cases with numeric bounds (full runs: the case READMEs).
#include <gtest/gtest.h>

#include <algorithm>

#include "run_helpers.hpp"

using namespace monosph::test;

TEST(OscillatingPlate, CoarsePeriodAndCoherence) {
  // 10 particles across (dp = 2 mm), 0.6 s: more than two periods; MMB's xi = 0.5 with the
  // Newmark gamma = 0.6 of the scene.
  const std::string out = out_dir("plate_coarse");
  auto r = run_monosph(
      "run " + source("cases/oscillating_plate/scene.yaml") + " --out " + out +
      " --quiet --set dp=0.002 end_time=0.6 output.every=0.3 output.checkpoint_every=0");
  ASSERT_EQ(r.code, 0) << r.output;
  auto js = summary(out);
  EXPECT_LT(js["metrics"]["period"]["relative_error"].get<double>(), 0.05);  // issue 3 target
  auto t = read_csv(out + "/probes.csv");
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_GT(min_of(t["min_distance"]), 0.5);
}

TEST(ElasticTension, HourglassControlKeepsTheStripCoherent) {
  // 10 particles across (dp = 0.4 mm), pulled to 0.45 strain with xi = 10.
  const std::string out = out_dir("tension_hg");
  auto r = run_monosph("run " + source("cases/elastic_tension/scene.yaml") + " --out " + out +
                       " --quiet --set dp=0.0004 output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_GT(min_of(t["min_distance"]), 0.5);
  EXPECT_GT(t["pull_force_x"].back(), 0.0);  // still carries load: no fracture
}

TEST(ElasticTension, ArtificialViscosityAndStressAloneBecomeUnstable) {
  // MMB Fig. 2: without hourglass control the strip disorders at small strain.
  const std::string out = out_dir("tension_av");
  auto r = run_monosph("run " + source("cases/elastic_tension/scene.yaml") + " --out " + out +
                       " --quiet --set dp=0.0004 output.every=1 bodies.0.hourglass.xi=0"
                       " bodies.0.artificial_viscosity.alpha=2 bodies.0.artificial_viscosity.beta=1"
                       " bodies.0.artificial_stress.epsilon=0.3");
  auto t = read_csv(out + "/probes.csv");
  EXPECT_GT(max_of(t["disorder"]), 0.1) << r.output;
}

TEST(RubberRings, CollideAndReboundWithoutFracture) {
  const std::string out = out_dir("rings");
  auto r = run_monosph("run " + source("cases/rubber_rings/scene.yaml") + " --out " + out +
                       " --quiet --set output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  EXPECT_GT(min_of(t["min_distance"]), 0.5);
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_LT(t["left_vx"].back(), -0.5 * 7.071);  // rebounded
}

TEST(OscillatingPlate, BodyAtRestStaysAtRestWithTheCorrectedStressDivergence) {
  // The plate released without velocity, xi = 0.5 (MMB's value): with the corrected (adjoint)
  // stress divergence round-off stays round-off; with the normalised one (MMB Eq. 10) the
  // non-adjoint surface rows let it grow into particle contact (docs/theory.md).
  const std::string base = "run " + source("cases/oscillating_plate/scene.yaml") +
                           " --quiet --set dp=0.002 end_time=0.25 output.every=1"
                           " output.checkpoint_every=0 bodies.0.hourglass.xi=0.5"
                           " time_step.newmark_gamma=0.5"
                           " bodies.0.initial.velocity_profile.amplitude=0";
  const std::string out = out_dir("plate_rest_corrected");
  auto r = run_monosph(base + " bodies.0.stress_divergence=corrected --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  EXPECT_LT(max_of(t["disorder"]), 1e-8);
  EXPECT_LT(max_of(t["kinetic_energy"]), 1e-12);
  const std::string out2 = out_dir("plate_rest_normalised");
  auto r2 = run_monosph(base + " bodies.0.stress_divergence=normalised --out " + out2);
  auto t2 = read_csv(out2 + "/probes.csv");
  EXPECT_GT(max_of(t2["disorder"]), 1e-3) << r2.output;
}

TEST(PatchTest, HourglassControlHoldsOneHundredBreathingPeriods) {
  // The whole case: the irregular stretched patch breathes for 170 s (110 periods of 1.54 s)
  // with corrected divergence, xi = 15 and Newmark gamma = 0.7, disorder below 0.05 dp; without
  // hourglass control two particles meet within 0.5 s.
  const std::string out = out_dir("patch_hg");
  auto r = run_monosph("run " + source("cases/patch_test/scene.yaml") + " --out " + out +
                       " --quiet --set output.every=100 output.checkpoint_every=0");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  EXPECT_GT(t["time"].back(), 169.9);
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_GT(min_of(t["min_distance"]), 0.4);
  // Still breathing after 100 periods: the edge moves (amplitude decays through gamma).
  std::vector<double> late(t["edge_x"].end() - 1000, t["edge_x"].end());
  EXPECT_GT(
      *std::max_element(late.begin(), late.end()) - *std::min_element(late.begin(), late.end()),
      1e-3);
  const std::string out2 = out_dir("patch_no_hg");
  auto r2 = run_monosph("run " + source("cases/patch_test/scene.yaml") + " --out " + out2 +
                        " --quiet --set end_time=3 output.every=1 bodies.0.hourglass.xi=0");
  EXPECT_EQ(r2.code, 3) << r2.output;
  auto t2 = read_csv(out2 + "/probes.csv");
  EXPECT_GT(max_of(t2["disorder"]), 0.1);
  EXPECT_LT(t2["time"].back(), 0.5);
}
