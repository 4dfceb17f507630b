// Shortened runs of the fluid cases with numeric bounds (full runs: the case READMEs).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "output/checkpoint.hpp"
#include "run_helpers.hpp"

using namespace monosph::test;

TEST(HydrostaticTank, PressureFollowsRhoGDepthAndTheFluidRests) {
  // The full case (2 s, about 4 s): row means of p within 1 % of rho0 g H of rho0 g (H - y),
  // velocities below 1e-3 sqrt(g H), no fluid particle in a wall, the tank carries the weight.
  const std::string out = out_dir("hydrostatic_tank");
  auto r = run_monosph("run " + source("cases/hydrostatic_tank/scene.yaml") + " --out " + out +
                       " --quiet --set output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  monosph::Particles<2> p;
  monosph::read_checkpoint<2>(out + "/final.h5", p);
  const double H = 1.0, g = 9.81, rho0 = 1000, dp = 0.025;
  std::map<long, std::pair<double, int>> rows;
  double vmax = 0, mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.phase()[i] != monosph::kFluid) continue;
    const auto& x = p.x()[i];
    EXPECT_GT(x[1], 0.45 * dp);  // inside the tank: walls end at y = 0, x = 0 and x = 1
    EXPECT_GT(x[0], 0.45 * dp);
    EXPECT_LT(x[0], H - 0.45 * dp);
    auto& row = rows[std::lround(x[1] / dp - 0.5)];
    row.first += p.p()[i] - rho0 * g * (H - x[1]);
    row.second += 1;
    vmax = std::max(vmax, p.v()[i].norm());
    mass += p.m()[i];
  }
  EXPECT_EQ(rows.size(), 40u);
  for (const auto& [k, row] : rows)
    EXPECT_LT(std::abs(row.first / row.second), 0.01 * rho0 * g * H) << "row " << k;
  EXPECT_LT(vmax, 1e-3 * std::sqrt(g * H));
  auto t = read_csv(out + "/probes.csv");
  EXPECT_NEAR(t["wall_force_y"].back(), -mass * g, 0.01 * mass * g);
}

TEST(TaylorGreen, EnergyDecayAt50x50) {
  // 50 x 50 particles, t = 1 (about 2 s): E(t)/E0 within 1.5 % of exp(-16 pi^2 nu t) at every
  // probe (measured 0.79 %; 0.90 % at 100 x 100, 1.85 % at 200 x 200), and within 1.5 % at t = 1.
  const std::string out = out_dir("taylor_green_50");
  auto r = run_monosph("run " + source("cases/taylor_green/scene.yaml") + " --out " + out +
                       " --quiet --set dp=0.02 output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const auto& e = t["kinetic_energy"];
  ASSERT_GT(e.size(), 90u);
  double worst = 0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    const double exact = std::exp(-16 * M_PI * M_PI * 0.01 * t["time"][k]);
    worst = std::max(worst, std::abs(e[k] / e.front() / exact - 1));
  }
  EXPECT_LT(worst, 0.015);
  EXPECT_NEAR(e.back() / e.front(), std::exp(-16 * M_PI * M_PI * 0.01),
              0.01 * e.back() / e.front());
  for (double m : t["mass"]) EXPECT_NEAR(m, t["mass"].front(), 1e-12 * m);
  for (double q : t["momentum_x"]) EXPECT_LT(std::abs(q), 1e-12);
}

// The dam-break tests: test_dam_break.cpp.

TEST(CouetteCylinder, TurnsAtTheConfinedStokesRateWithoutPairingOver10ShearTimes) {
  // cases/couette_cylinder (H = 8a, period 16a, a = 4 dp, Re = 0.1, transport-velocity shifting
  // with the consistent terms, no background pressure), 10 shear times (about 35 s on one thread).
  // Boundary-integral Stokes value 0.9645 gamma/2 (issue 24). Over 20 shear times the scene gives
  // omega/(gamma/2) 0.960 (-0.5 %), sd of the 0.01 s samples 0.75 %, drift 1e-4 a, pairs >= 0.64
  // dp (README); with the EOS background pressure and no shifting it was 0.956 +- 3.7 %.
  const std::string out = out_dir("couette_cylinder");
  auto r = run_monosph("run " + source("cases/couette_cylinder/scene.yaml") + " --out " + out +
                       " --quiet --threads 1 --set end_time=2.0 output.every=0");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const double gamma = 5, a = 0.002;
  std::vector<double> w;
  for (std::size_t k = 0; k < t["time"].size(); ++k)
    if (t["time"][k] * gamma >= 2) w.push_back(-t["omega"][k] / (gamma / 2));
  ASSERT_GT(w.size(), 150u);
  double mean = 0, var = 0;
  for (double x : w) mean += x / w.size();
  for (double x : w) var += (x - mean) * (x - mean) / w.size();
  EXPECT_NEAR(mean / 0.9645, 1.0, 0.02);
  EXPECT_LT(std::sqrt(var), 0.02);
  double drift = 0;
  for (std::size_t k = 0; k < t["time"].size(); ++k)
    drift = std::max(
        drift,
        std::hypot(t["centre_x"][k] - t["centre_x"][0], t["centre_y"][k] - t["centre_y"][0]) / a);
  EXPECT_LT(drift, 0.01);
  EXPECT_GT(min_of(t["min_distance"]), 0.5);
}
