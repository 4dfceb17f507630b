// Sub-grid lubrication between a rigid cluster and a surface (src/coupling/lubrication_module):
// the force law, its cut-offs, and exactly opposite pair forces (momentum kept to round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupling/lubrication_module.hpp"
#include "output/probes.hpp"
#include "rigid/cluster_module.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

// An iron grain (d = 10 dp) 0.5 dp above a steel block, closing at 1 m/s; no fluid: the film's
// viscosity is given. No body force.
const char* kGrainOverBlock = R"(
name: film
dimension: 2
dp: 0.001
domain: {min: [0, -0.005], max: [0.04, 0.03]}
materials:
  iron: {preset: iron}
  steel: {density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9}
bodies:
  - name: block
    phase: solid
    material: steel
    shape: {box: {min: [0, -0.004], max: [0.04, 0]}}
  - name: grain
    phase: rigid
    material: iron
    shape: {circle: {center: [0.02, 0.0055], radius: 0.005}}
    initial: {velocity: [0.3, -1]}
lubrication: {viscosity: 1.0, cutoff: 1.5, min_gap: 0.05}
end_time: 1
probes:
  list:
    - {name: F, type: lubrication_force}
    - {name: h, type: lubrication_gap}
    - {name: P, type: momentum}
)";

}  // namespace

TEST(Lubrication, ForceFollowsTheCylinderPlaneLawWithinItsCutoffs) {
  auto sim = test::build<2>(kGrainOverBlock);
  const auto& lub = test::module<LubricationModule<2>>(*sim);
  const double dp = 0.001, mu = 1.0, a = 0.005, U = 2.0;
  // Jeffrey & Onishi 1981, leading order, shifted at h_c = 1.5 dp.
  auto law = [&](double h) {
    return 3 * std::numbers::sqrt2 * std::numbers::pi * mu * U * std::pow(a, 1.5) *
           (std::pow(h, -1.5) - std::pow(1.5 * dp, -1.5));
  };
  EXPECT_NEAR(lub.force(0.5 * dp, U, a), law(0.5 * dp), 1e-12 * law(0.5 * dp));
  EXPECT_NEAR(lub.force(0.01 * dp, U, a), law(0.05 * dp), 1e-12 * law(0.05 * dp));  // h_min
  EXPECT_EQ(lub.force(1.5 * dp, U, a), 0.0);   // resolved: the SPH fluid carries it
  EXPECT_EQ(lub.force(0.5 * dp, -U, a), 0.0);  // separating: the film cavitates
  EXPECT_GT(lub.force(0.5 * dp, U, a), lub.force(1.0 * dp, U, a));
}

TEST(Lubrication, PairForcesAreOppositeAndMatchTheLaw) {
  auto sim = test::build<2>(kGrainOverBlock);
  const auto& lub = test::module<LubricationModule<2>>(*sim);
  const auto& cm = test::module<ClusterModule<2>>(*sim);
  Probes<2> probes(*sim);
  const auto p0 = probes.sample(*sim);  // F_x, F_y, h, P_x, P_y
  const double m_grain = cm.cluster(0).mass;
  const double a = std::sqrt(2 * cm.cluster(0).inertia / m_grain);
  double acted = 0;
  for (int k = 0; k < 20; ++k) {
    sim->advance();
    const auto v = probes.sample(*sim);
    // Momentum of grain + block: the pair forces cancel (the block is free, nothing else acts).
    EXPECT_NEAR(v[3], p0[3], 1e-12 * m_grain);
    EXPECT_NEAR(v[4], p0[4], 1e-12 * m_grain);
    acted = std::max(acted, v[1]);
  }
  EXPECT_GT(acted, 0.0);
  // One more step: the force on the grain is the law at the film's gap and approach speed,
  // shared among its pairs along their lines of centres (so the normal sum is a little less).
  sim->advance();
  const auto v = probes.sample(*sim);
  const double U = -cm.cluster(0).velocity.y(), law = lub.force(v[2], U, a);
  EXPECT_LE(v[1], law);
  EXPECT_GT(v[1], 0.8 * law);
  EXPECT_LT(std::abs(v[0]), 0.1 * v[1]);
}
