// Shortened runs of the plasticity cases with numeric bounds (full runs: the case READMEs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "run_helpers.hpp"

using namespace monosph::test;

namespace {
double max_of(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}
double min_of(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}
}  // namespace

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
