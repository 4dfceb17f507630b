// Fixed and prescribed-velocity particle sets, body force and the reaction probe.
#include <gtest/gtest.h>

#include "core/sph_equations.hpp"
#include "scene/scene.hpp"

using namespace monosph;

TEST(Boundary, FixedAndPrescribedSetsFollowTheirMotion) {
  const std::string bcs = R"(
boundary_conditions:
  - {name: base, type: fixed, region: {box: {min: [0, 0], max: [0.3, 0.03]}}}
  - {name: lid, type: velocity, region: {box: {min: [0, 0.27], max: [0.3, 0.3]}}, velocity: ["0.2*t", "0"]}
body_force: [0, -9.81]
)";
  Scene s = load_scene_text(R"(
name: bc
dimension: 2
dp: 0.01
domain: {min: [-0.5, -0.1], max: [0.8, 0.5]}
materials:
  water: {density: 1000, sound_speed: 10}
bodies:
  - {name: block, phase: fluid, material: water, shape: {box: {min: [0, 0], max: [0.3, 0.3]}},
     artificial_viscosity: {alpha: 0.2, beta: 0.4}}
end_time: 1
)" + bcs);
  Simulation<2> sim(s);
  sim.add_module(std::make_unique<SphEquations<2>>(sim));
  sim.create_particles();
  sim.init();
  auto& p = sim.particles();
  std::vector<Vec<2>> x0(p.x().begin(), p.x().end());
  std::vector<std::int64_t> id0(p.id().begin(), p.id().end());
  for (int k = 0; k < 100; ++k) sim.advance();
  const double t = sim.time();
  auto bc = p.view<std::int64_t>("boundary");
  int fixed = 0, moved = 0, free_fall = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Find the initial position by id (particles are reordered at neighbour rebuilds).
    std::size_t k = std::find(id0.begin(), id0.end(), p.id()[i]) - id0.begin();
    const Vec<2> d = p.x()[i] - x0[k];
    if (bc[i] == 1) {
      EXPECT_EQ(d.norm(), 0.0);
      EXPECT_EQ(p.v()[i].norm(), 0.0);
      ++fixed;
    } else if (bc[i] == 2) {
      // x = x0 + 0.1 t^2 exactly for the midpoint rule on a linear velocity.
      EXPECT_NEAR(d[0], 0.1 * t * t, 1e-12);
      EXPECT_EQ(d[1], 0.0);
      EXPECT_NEAR(p.v()[i][0], 0.2 * t, 1e-12);
      ++moved;
    } else if (d[1] < 0) {
      ++free_fall;
    }
  }
  EXPECT_EQ(fixed, 90);
  EXPECT_EQ(moved, 90);
  EXPECT_GT(free_fall, 0);
  // The base holds the water: its reaction points up.
  EXPECT_GT(sim.reactions()[0][1], 0.0);
}
