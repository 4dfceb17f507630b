// The squeezed film between a grain and a wall (docs/theory.md, "Grain, film and wall"): the drag
// on a cylinder driven towards a plane at low Reynolds number against the Stokes result down to
// gaps far below the resolution, and grains that reach a PMMA wall through water at 10-100 m/s.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "run_helpers.hpp"

using namespace monosph::test;

namespace {

// Force per length on a cylinder of radius a approaching a plane at speed U, gap h, in Stokes
// flow (Jeffrey & Onishi 1981, bipolar coordinates): 4 pi mu U / (alpha - tanh alpha) with
// cosh alpha = 1 + h/a; for h << a it is the Reynolds result 3 sqrt(2) pi mu U (a/h)^1.5.
double stokes_drag(double h, double a, double mu, double U) {
  const double al = std::acosh(1 + h / a);
  return 4 * std::numbers::pi * mu * U / (al - std::tanh(al));
}

}  // namespace

TEST(Lubrication, CylinderApproachingAWallFollowsTheStokesDrag) {
  // a = 10 dp at U = 1 mm/s, Re = 0.2; from h = 1.5 a (start-up) to h = 0.02 a = 0.2 dp.
  const std::string out = out_dir("lubrication_cylinder");
  auto r = run_monosph("run " + source("tests/scenes/lubrication_cylinder.yaml") + " --out " + out +
                       " --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const double a = 1e-3, dp = 1e-4, mu = 5e-3, U = 1e-3;
  // Measured (docs/theory.md): 1.03-1.11 resolved; 0.77-0.95 in the transition, where the SPH
  // fluid already falls below the drag and the film term has not started (h_c = 1.5 dp);
  // 0.96-1.04 below 1.3 dp, where the SPH fluid alone gives 0.14-0.79.
  double below = 0, sph_only = 0;
  int n_resolved = 0, n_below = 0;
  for (std::size_t k = 0; k < t["time"].size(); ++k) {
    const double h = t["c_y"][k] - a, exact = stokes_drag(h, a, mu, U);
    const double sph = t["fluid_force_y"][k], total = sph + t["lubrication_y"][k];
    if (h >= 0.25 * a && h <= 0.6 * a) {  // resolved (2.5-6 dp): the SPH fluid alone
      EXPECT_EQ(t["lubrication_y"][k], 0.0);
      EXPECT_NEAR(total / exact, 1.0, 0.15) << "h/a = " << h / a;
      ++n_resolved;
    } else if (h > 0.13 * a && h < 0.25 * a) {  // the transition
      EXPECT_NEAR(total / exact, 1.0, 0.3) << "h/a = " << h / a;
    } else if (h > 0 && h <= 0.13 * a) {  // 0.2-1.3 dp: SPH + the sub-grid film
      EXPECT_NEAR(total / exact, 1.0, 0.1) << "h/a = " << h / a;
      below += total / exact, ++n_below;
      if (h <= 1.0 * dp) sph_only = std::max(sph_only, sph / exact);
    }
  }
  ASSERT_GT(n_resolved, 30);
  ASSERT_GT(n_below, 10);
  EXPECT_NEAR(below / n_below, 1.0, 0.05);
  EXPECT_LT(sph_only, 0.75);  // measured 0.67: without the film term the test fails
  EXPECT_GT(min_of(t["min_distance"]), 0.3);
}

TEST(Lubrication, FastGrainReachesTheWallThroughTheFluid) {
  // The abrasive-flow scene's water, PMMA and grain; 10 m/s needs longer to arrive.
  for (const char* set : {"variables.speed=100", "variables.speed=10 end_time=6e-7"}) {
    const std::string out = out_dir("grain_through_fluid");
    auto r = run_monosph("run " + source("tests/scenes/grain_through_fluid.yaml") + " --out " +
                         out + " --quiet --set " + set);
    ASSERT_EQ(r.code, 0) << set << ": " << r.output;  // no guard stops it
    auto t = read_csv(out + "/probes.csv");
    const double dp = 5e-7;
    EXPECT_GE(t["impacts"].back(), 1) << set;                    // the grain touched the PMMA
    EXPECT_GT(max_of(t["lubrication_y"]), 0.0) << set;           // through the film
    EXPECT_LT(max_of(t["fluid_penetration"]), 0.5 * dp) << set;  // measured 0.24 dp
    EXPECT_GT(min_of(t["min_distance"]), 0.3) << set;            // measured 0.49 / 0.59
    const auto& m = t["fluid_mass"];
    EXPECT_NEAR(m.back(), m.front(), 1e-12 * m.front()) << set;  // no fluid particle lost
  }
}
