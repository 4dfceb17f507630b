// Restart state (src/core/restart.cpp, issue 50): a simulation that continues from another's
// state at an arbitrary step, as a restart from a checkpoint written there does
// (apps/runner.cpp), goes on bit for bit: the last neighbour rebuild is restored (lists, the
// solid's reference configuration of MMB Eq. 30), and so is a removal still pending.
#include <gtest/gtest.h>

#include "sim_helpers.hpp"

using namespace monosph;

namespace {

// cases/oscillating_plate at dp = 4 mm: an Eulerian solid with a rebuild every ~13 steps.
const char* kPlate = R"(
name: plate
dimension: 2
dp: 0.004
kernel: {type: cubic_spline, h_factor: 1.3}
domain: {min: [-0.06, -0.12], max: [0.21, 0.14]}
materials:
  soft: {density: 1000, bulk_modulus: 3.25e6, shear_modulus: 0.715e6}
bodies:
  - name: plate
    phase: solid
    material: soft
    shape: {box: {min: [-0.056, -0.01], max: [0.2, 0.01]}}
    hourglass: {xi: 0.5}
    initial:
      velocity_profile: {type: cantilever_mode, amplitude: 2.8504, clamp: 0.0, length: 0.2,
                         kl: 1.875}
boundary_conditions:
  - {name: clamp, type: fixed, region: {box: {min: [-0.06, -0.011], max: [0.0, 0.011]}}}
end_time: 1
time_step: {cfl: 0.3, newmark_gamma: 0.6}
)";

// A new simulation with a's particles and state, as a restart from a checkpoint of a.
std::unique_ptr<Simulation<2>> restart_from(Simulation<2>& a) {
  std::map<std::string, double> s;
  a.save_state(s);
  for (const auto& m : a.modules()) m->save_state(s);
  auto b = std::make_unique<Simulation<2>>(a.scene());
  assemble_modules(*b);
  b->particles() = a.particles();
  b->set_state(a.time(), a.step(), a.dt());
  for (const auto& m : b->modules()) m->load_state(*b, s);
  b->load_state(s);
  b->init(true);
  return b;
}

void advance_both(Simulation<2>& a, Simulation<2>& b, int steps) {
  for (int k = 0; k < steps; ++k) a.advance(), b.advance();
}

void expect_same_state(Simulation<2>& a, Simulation<2>& b) {
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.neighbours().builds(), b.neighbours().builds());
  auto& pa = a.particles();
  auto& pb = b.particles();
  ASSERT_EQ(pa.size(), pb.size());
  for (const auto& f : pa.fields()) {
    EXPECT_EQ(f.real, pb.field(f.name).real) << f.name;
    EXPECT_EQ(f.ints, pb.field(f.name).ints) << f.name;
  }
}

TEST(RestartState, ContinuesBitForBitFromAStepWithoutARebuild) {
  for (int steps : {9, 31}) {
    SCOPED_TRACE(steps);
    auto a = test::build<2>(kPlate);
    for (int k = 0; k < steps; ++k) a->advance();
    const int builds = a->neighbours().builds();
    auto b = restart_from(*a);
    EXPECT_EQ(b->neighbours().builds(), builds);  // no rebuild of its own
    advance_both(*a, *b, 60);
    EXPECT_GT(a->neighbours().builds(), builds + 2);
    expect_same_state(*a, *b);
  }
}

TEST(RestartState, AParticleFlaggedForRemovalIsRemovedAtTheSameStep) {
  auto a = test::build<2>(kPlate);
  for (int k = 0; k < 20; ++k) a->advance();
  const std::size_t n = a->particles().size();
  std::vector<char> flag(n, 0);
  flag[n / 2] = 1;
  a->remove_particles(flag);
  auto b = restart_from(*a);
  advance_both(*a, *b, 1);
  EXPECT_EQ(a->particles().size(), n - 1);
  EXPECT_EQ(b->particles().size(), n - 1);
  advance_both(*a, *b, 30);
  expect_same_state(*a, *b);
}

}  // namespace
