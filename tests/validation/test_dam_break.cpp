// Shortened dam-break runs with numeric bounds (full runs and the study: cases/dam_break/README.md,
// docs/studies/dam_break_marrone).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "run_helpers.hpp"

using namespace monosph::test;

namespace {

// Columns of a CSV file whose comment lines start with '#' (the reference files' headers).
Table read_reference(const std::string& file) {
  std::ifstream in(file);
  std::string line, text;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') text += line + "\n";
  const std::string tmp = out_dir("dam_break_reference") + ".csv";
  std::ofstream(tmp) << text;
  return read_csv(tmp);
}

// y(x) by linear interpolation in the increasing samples (xs, ys).
double interp(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  std::size_t k = 1;
  while (k + 1 < xs.size() && xs[k] < x) ++k;
  const double f = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + f * (ys[k] - ys[k - 1]);
}

}  // namespace

TEST(DamBreak, MarroneFrontAndImpactAgainstConvergedReferences) {
  // cases/dam_break/scene_marrone.yaml at H/40 to t sqrt(g/H) = 2.6 (about 20 s on one thread).
  // Front (largest fluid particle centre x) against the H/400 WCSPH solution for t* <= 2.3:
  // measured -2.2 % at most (t* = 2.28), RMS 1.8 %; bound 3 % and 2.5 % (H/80: -0.9 %, README).
  // Sensor P1 (De Courcy et al. 2024, right wall, y = 1.8-10.2 mm): no pressure before the front
  // arrives, first p >= 0.5 rho g H at t* = 2.407 (reference 2.360: the front's lag), bound
  // within 0.08 of the reference; mean over t* in [2.4, 2.6] 2.57 rho g H (reference 2.30),
  // bound within 25 %.
  const std::string out = out_dir("dam_break_marrone");
  auto r = run_monosph("run " + source("cases/dam_break/scene_marrone.yaml") + " --out " + out +
                       " --quiet --threads 1 --set end_time=0.643 output.every=0");
  ASSERT_EQ(r.code, 0) << r.output;
  const double H = 0.6, g = 9.81, rho0 = 1000, ts = std::sqrt(g / H);
  auto t = read_csv(out + "/probes.csv");
  auto ref = read_reference(source("cases/dam_break/reference_front_wcsph_H400.csv"));
  std::vector<double> tstar;
  for (double x : t["time"]) tstar.push_back(x * ts);
  const auto& rt = ref["t_sqrt_g_over_H"];
  const auto& rx = ref["x_front_m"];
  double worst = 0, sum2 = 0;
  int n = 0;
  for (std::size_t k = 0; k < rt.size() && rt[k] <= 2.3 + 1e-9; ++k) {
    const double e = interp(tstar, t["front"], rt[k]) / rx[k] - 1;
    worst = std::max(worst, std::abs(e));
    sum2 += e * e, ++n;
  }
  ASSERT_GT(n, 200);
  EXPECT_LT(worst, 0.03);
  EXPECT_LT(std::sqrt(sum2 / n), 0.025);
  const auto& p1 = t["P1"];
  double impact = -1, mean = 0;
  int nm = 0;
  for (std::size_t k = 0; k < p1.size(); ++k) {
    const double ps = p1[k] / (rho0 * g * H);
    if (tstar[k] < 2.3) {
      EXPECT_LT(std::abs(ps), 0.05) << "t* = " << tstar[k];  // dry wall
    }
    if (impact < 0 && ps >= 0.5) {
      const double before = p1[k - 1] / (rho0 * g * H);
      impact = tstar[k - 1] + (tstar[k] - tstar[k - 1]) * (0.5 - before) / (ps - before);
    }
    if (tstar[k] >= 2.4 && tstar[k] <= 2.6) mean += ps, ++nm;
  }
  EXPECT_NEAR(impact, 2.360, 0.08);
  ASSERT_GT(nm, 50);
  EXPECT_NEAR(mean / nm, 2.30, 0.25 * 2.30);
  for (double m : t["mass"]) EXPECT_NEAR(m, t["mass"].front(), 1e-12 * m);
}

TEST(DamBreak, MartinMoyceColumnKeepsMassAndSpacing) {
  // cases/dam_break/scene.yaml (the Martin & Moyce column) at a/dp = 20 (about 2 s): mass exact,
  // no particle pairing, the run completes. This test used to bound the front against Martin &
  // Moyce's measurements (20 % up to T = 2.55, 10 % at 3.35). That bound is retired: simulations
  // of the experiment lead it by about 0.15-0.2 in T = t sqrt(2g/a) because of the gate release
  // (the literature shifts time by about +0.175 before comparing), so it measured the experiment,
  // not the code. The code's front is bounded against the converged reference above.
  const std::string out = out_dir("dam_break_coarse");
  auto r = run_monosph("run " + source("cases/dam_break/scene.yaml") + " --out " + out +
                       " --quiet --set dp=0.005 domain.min=[-0.015,-0.015] domain.max=[0.615,0.3]"
                       " output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  for (double m : t["mass"]) EXPECT_NEAR(m, t["mass"].front(), 1e-12 * m);
  EXPECT_GT(min_of(t["min_distance"]), 0.3);
}
