// Multi-rate stepping (docs/theory.md, "Multi-rate stepping"): total momentum of fluid + solid
// kept to round-off while the solid takes sub-steps, and the scene keys' errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scene_helpers.hpp"
#include "sim_helpers.hpp"

using namespace monosph;
using namespace monosph::test;

namespace {

// A periodic box of water in shear flow around a free elastic block (no gravity, no walls): no
// external force, so the total momentum stays what it was.
const char* kBox = R"Y(
name: box
dimension: 2
dp: 0.002
domain: {min: [0, 0], max: [0.04, 0.04], periodic: [x, y]}
materials:
  water: {density: 1000, sound_speed: 20, viscosity: 1.0e-3}
  rubber: {density: 1500, bulk_modulus: 5.0e7, shear_modulus: 2.25e7}
bodies:
  - name: block
    phase: solid
    material: rubber
    shape: {box: {min: [0.014, 0.014], max: [0.026, 0.026]}}
    hourglass: {xi: 0.2, zeta: 10, chi: 0.5}
    initial: {velocity: ["0.3", "-0.2"]}
  - name: water
    phase: fluid
    material: water
    fill: rest
    shape: {box: {min: [0, 0], max: [0.04, 0.04]}}
    density_diffusion: {delta: 0.1}
    shifting: {speed: 0.5}
    initial: {velocity: ["0.5*sin(2*pi*y/0.04)", "0.2*cos(2*pi*x/0.04)"]}
time_step: {multi_rate: true}
end_time: 1
)Y";

Eigen::Vector2d momentum(Simulation<2>& sim, double& scale) {
  auto& p = sim.particles();
  Eigen::Vector2d P = Eigen::Vector2d::Zero();
  scale = 0;
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    P += p.m()[i] * p.v()[i];
    scale += p.m()[i] * p.v()[i].norm();
  }
  return P;
}

}  // namespace

TEST(MultiRate, MomentumOfFluidAndSubSteppedSolidIsKeptToRoundOff) {
  auto sim = build<2>(kBox);
  double scale = 0;
  const Eigen::Vector2d p0 = momentum(*sim, scale);
  long substeps = 0;
  for (int k = 0; k < 300; ++k) sim->advance(), substeps += sim->substeps();
  double s1 = 0;
  const Eigen::Vector2d p1 = momentum(*sim, s1);
  // The block's waves (c_L = 200 m/s) are 10x the water's: about 10 sub-steps per step.
  EXPECT_GE(substeps, 8 * 300);
  EXPECT_GT(sim->neighbours().builds(), 1);  // the lists were rebuilt (and reordered) meanwhile
  EXPECT_LT((p1 - p0).norm(), 1e-13 * scale) << "P0 " << p0.transpose() << " P1 " << p1.transpose();
  EXPECT_GT(s1, 0.5 * scale);  // still moving
  std::printf("momentum drift %.3g of sum m|v|\n", (p1 - p0).norm() / scale);
}

TEST(MultiRate, SceneKeysAreChecked) {
  const std::string base = R"(
name: t
dimension: 2
dp: 0.1
domain: {min: [0, 0], max: [1, 1]}
materials: {water: {density: 1000, sound_speed: 10}}
bodies:
  - {name: w, phase: fluid, material: water, shape: {box: {min: [0, 0], max: [1, 1]}}}
end_time: 1
)";
  EXPECT_NE(load_error(base + "time_step: {multi_rate: true, max_substeps: 2.5}")
                .find("time_step.max_substeps"),
            std::string::npos);
  EXPECT_NE(load_error(base + "time_step: {multi_rate: true, newmark_gamma: 0.6}")
                .find("time_step.multi_rate"),
            std::string::npos);
  EXPECT_NE(load_error(base + "time_step: {multi_rate: true, dual_criteria: {advection_cfl: 0.2}}")
                .find("time_step.multi_rate"),
            std::string::npos);
  // A fluid alone has no solid to sub-step.
  try {
    build<2>(base + "time_step: {multi_rate: true}");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_step.multi_rate"), std::string::npos) << e.what();
  }
}
