// Shortened runs of the plasticity cases with numeric bounds (full runs: the case READMEs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "run_helpers.hpp"

using namespace monosph::test;

TEST(Upsetting, ForceFollowsTheJohnsonCookFlowCurve) {
  // 10 particles across the diameter, 150 us: 1.4 mm of the 2.5 mm travel. The plate force must
  // follow the homogeneous estimate sigma_JC(ln h0/h) A0 h0/h (Al 6061-T6, rate and heat small)
  // from above: friction 0.1 and the rate term add a few to 20 per cent.
  const std::string out = out_dir("upsetting_coarse");
  auto r = run_monosph("run " + source("cases/upsetting/scene.yaml") + " --out " + out +
                       " --quiet --set dp=1e-3 domain.min=[-0.01,-0.01,-0.002] end_time=1.5e-4"
                       " output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const auto& travel = t["top_travel_z"];
  const auto& force = t["top_force_z"];
  int checked = 0;
  for (std::size_t k = 0; k < travel.size(); ++k) {
    const double d = -travel[k], h = 5e-3 - d;
    if (d < 0.5e-3) continue;
    const double eps = std::log(5e-3 / h);
    const double est = (164e6 + 211e6 * std::pow(eps, 0.465)) * M_PI * 25e-6 * 5e-3 / h;
    EXPECT_GT(force[k] / est, 1.0) << "travel " << d;
    EXPECT_LT(force[k] / est, 1.3) << "travel " << d;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  EXPECT_GT(-travel.back(), 1.3e-3);
  EXPECT_GT(max_of(t["max_plastic_strain"]), 0.3);
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_GT(min_of(t["min_distance"]), 0.5);
  // Equal and opposite plate forces once the billet is in equilibrium.
  EXPECT_NEAR(force.back(), -t["bottom_force_z"].back(), 0.02 * force.back());
}

// The 3D bar at rest near the experiment (House et al. 1995: 29.9 mm, 13.5 mm), round, plastically
// deformed and heated at the impact face, no two particles closer than 0.1 dp.
static void expect_bar_at_rest_near_experiment(const Table& t) {
  EXPECT_LT(t["kinetic_energy"].back(), 0.01 * t["kinetic_energy"].front());
  EXPECT_NEAR(t["length"].back(), 29.9e-3, 0.12 * 29.9e-3);
  EXPECT_NEAR(t["diameter"].back(), 13.5e-3, 0.15 * 13.5e-3);
  EXPECT_NEAR(t["diameter_y"].back(), t["diameter_x"].back(), 0.05 * t["diameter_x"].back());
  EXPECT_GT(max_of(t["max_plastic_strain"]), 0.6);
  EXPECT_GT(max_of(t["max_temperature"]), 292 + 50.0);  // adiabatic heating at the impact face
  EXPECT_GT(min_of(t["min_distance"]), 0.1);
}

// Probes of a 3D Taylor bar scene run at 6 particles across the diameter (810 particles, 100 us).
static Table run_bar_6_across(const std::string& scene, const std::string& name) {
  const std::string out = out_dir(name);
  auto r = run_monosph("run " + source(scene) + " --out " + out +
                       " --quiet --set dp=1.2658333333333333e-3 output.every=1");
  EXPECT_EQ(r.code, 0) << r.output;
  return read_csv(out + "/probes.csv");
}

TEST(TaylorBar, CoarseBarStopsNearTheExperiment) {
  // 3D, 6 particles across the diameter (810 particles), 100 us, anvil friction 0.3: the bar
  // comes to rest. Against House et al. 1995 (29.9 mm, 13.5 mm) the length is 9.4 % short (MMB
  // report about 10 %) and the diameter (probe `diameter`, any direction) 11.8 % small; the
  // diameter is the same to 0.2 % at 10 and 15 across (cases/taylor_bar/README.md).
  const Table t = run_bar_6_across("cases/taylor_bar/scene.yaml", "taylor_3d_coarse");
  ASSERT_FALSE(HasFailure());
  // Plastic strain 0.82 at 6 across, 1.16 at 15 across.
  expect_bar_at_rest_near_experiment(t);
}

TEST(TaylorBar, TotalLagrangianBarStopsWhereTheSceneDoes) {
  // scene_tlsph.yaml (G15 total-Lagrangian SPH, h = dp) at 6 across, 100 us, 3 s: at rest, the
  // length within 1.5 % of scene.yaml's at 6 across (27.09 mm; measured 26.80 mm, -1.1 %) and
  // both within the experiment's bounds of the test above (measured -10.4 %, -5.3 %). At 29
  // across it is scene.yaml's within 0.02 mm and 1 % (cases/taylor_bar/README.md).
  const Table t = run_bar_6_across("cases/taylor_bar/scene_tlsph.yaml", "taylor_3d_tlsph");
  ASSERT_FALSE(HasFailure());
  EXPECT_NEAR(t["length"].back(), 27.09e-3, 0.015 * 27.09e-3);
  // Measured: plastic strain 1.14, 420 K, smallest distance 0.11 dp (0.27 at 10 across).
  expect_bar_at_rest_near_experiment(t);
}

TEST(TaylorBar, PlaneStrainImpactRunsToRest) {
  // 2D plane strain, 10 particles across, 80 us (about a second), anvil friction 0.3 with
  // self-contact and the plastic switch: the slab stops on the wall as one piece. Bounds around
  // the 20-across run (length 28.43 mm, width 18.70 mm; 30 across: 28.36 / 18.73 mm); measured
  // 28.58 mm (+0.5 %) and 16.16 mm (-13.6 %). On a frictionless anvil it spreads to 24.3 mm here.
  const std::string out = out_dir("taylor_2d");
  auto r = run_monosph("run " + source("cases/taylor_bar/scene_2d.yaml") + " --out " + out +
                       " --quiet --set dp=7.595e-4 output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  EXPECT_LT(t["kinetic_energy"].back(), 0.01 * t["kinetic_energy"].front());
  EXPECT_NEAR(t["length"].back(), 28.43e-3, 0.03 * 28.43e-3);
  EXPECT_NEAR(t["width"].back(), 18.70e-3, 0.15 * 18.70e-3);
  EXPECT_GT(min_of(t["min_distance"]), 0.3);  // measured 0.43
  EXPECT_LT(max_of(t["max_plastic_strain"]), 4.0);
}

TEST(MetalCutting, ChipSegmentBreaksOff) {
  // The scene (20 um, 10 particles over the 0.2 mm depth of cut), 70 us of the 150 us cut: a
  // shear band from the tool edge to the free surface fails and the first chip segment breaks
  // off (the `pieces` probe goes from 1 to 2; 54.6 us in the full run), the cutting force drops
  // to less than half its mean (62.8 us), failed particles are eroded, the mean force lies near
  // the full run's 90 kN/m (cases/metal_cutting/README.md), and self-contact keeps every pair
  // above 0.2 dp (0.46 dp in the full run; without it two particles meet at the rake face).
  const std::string out = out_dir("cutting_segment");
  auto r = run_monosph("run " + source("cases/metal_cutting/scene.yaml") + " --out " + out +
                       " --quiet --set end_time=7e-5 output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  double sum = 0, low = 1e30, broke = -1;
  int count = 0;
  for (std::size_t k = 0; k < t["time"].size(); ++k) {
    if (broke < 0 && t["pieces"][k] >= 2) broke = t["time"][k];
    if (t["time"][k] < 15e-6) continue;
    sum += t["cutting_force_x"][k], ++count;
    low = std::min(low, t["cutting_force_x"][k]);
  }
  ASSERT_GT(count, 100);
  EXPECT_EQ(t["pieces"].front(), 1.0);
  EXPECT_GT(broke, 30e-6) << "no chip segment broke off";
  EXPECT_EQ(t["pieces"].back(), 2.0);
  EXPECT_GT(sum / count, 60e3);
  EXPECT_LT(sum / count, 120e3);
  EXPECT_LT(low, 0.5 * sum / count);  // the force drop of the breaking segment
  EXPECT_GT(t["removed_mass"].back(), 0.0);
  EXPECT_GT(max_of(t["max_plastic_strain"]), 1.0);
  EXPECT_GT(min_of(t["min_distance"]), 0.2);
}
