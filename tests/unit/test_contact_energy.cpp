// Energy stored in contacts (Module::potential_energy; probes contact_energy and total_energy):
// the energy laws differentiate to the forces, and elastic bounces keep total_energy.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assemble.hpp"
#include "core/hertz.hpp"
#include "coupling/contact_module.hpp"
#include "output/probes.hpp"
#include "rigid/rigid_surface_module.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

using test::build;
using test::module;

// An iron grain (d = 10 dp) touching an iron wall at t = 0 and moving into it at 1 m/s; no body
// force, no damping. `law` is the scene's contact section.
std::string grain_on_wall(const std::string& law) {
  return fmt::format(R"(
name: bounce
dimension: 2
dp: 0.001
domain: {{min: [0, -0.005], max: [0.04, 0.03]}}
materials:
  iron: {{preset: iron}}
bodies:
  - name: floor
    phase: wall
    material: iron
    shape: {{box: {{min: [0, -0.004], max: [0.04, 0]}}}}
  - name: grain
    phase: rigid
    material: iron
    shape: {{circle: {{center: [0.02, 0.0054], radius: 0.005}}}}
    initial: {{velocity: [0, -1]}}
contact: {}
end_time: 1
probes:
  list:
    - {{name: E, type: total_energy}}
    - {{name: U, type: contact_energy}}
    - {{name: n, type: contact_pairs}}
)",
                     law);
}

struct Dip {
  double with, without;  // largest drop of total_energy below its start / initial kinetic energy
};

// Steps until the contact that starts now has ended (contact_pairs back to 0), sampling the
// probes E (total_energy), U (contact_energy) and n (contact_pairs) every step.
template <int D>
Dip energy_dip(Simulation<D>& sim, int max_steps) {
  Probes<D> probes(sim);
  const auto v0 = probes.sample(sim);
  const double e0 = v0[0];
  double low = e0, low_without = e0;
  bool touched = false;
  for (int k = 0; k < max_steps; ++k) {
    sim.advance();
    const auto v = probes.sample(sim);
    low = std::min(low, v[0]);
    low_without = std::min(low_without, v[0] - v[1]);
    touched = touched || v[2] > 0;
    if (touched && v[2] == 0) break;
  }
  EXPECT_TRUE(touched);
  return {(e0 - low) / e0, (e0 - low_without) / e0};
}

}  // namespace

TEST(ContactEnergy, PairEnergyDifferentiatesToThePairForce) {
  // -dU/dr = F by central differences, for both laws in 2D (per depth) and 3D; U(d_c) = 0.
  auto check = [](auto& ct, double dc) {
    for (double frac : {0.999, 0.99, 0.97, 0.9, 0.8}) {
      const double r = frac * dc, h = 1e-6 * dc;
      const double du =
          ct.pair_energy(r + h, 0, 0, 2.0, 3.0) - ct.pair_energy(r - h, 0, 0, 2.0, 3.0);
      const double f = ct.pair_force(r, 0, 0, 2.0, 3.0);
      EXPECT_GT(f, 0);
      EXPECT_NEAR(-du / (2 * h) / f, 1.0, 1e-6) << "r/d_c = " << frac;
      EXPECT_GT(ct.pair_energy(r, 0, 0, 2.0, 3.0), 0);
    }
    EXPECT_EQ(ct.pair_energy(dc, 0, 0, 2.0, 3.0), 0.0);
    EXPECT_EQ(ct.pair_energy(1.1 * dc, 0, 0, 2.0, 3.0), 0.0);
  };
  for (const std::string law :
       {"{law: hertz, distance: 0.9}", "{law: lennard_jones, strength: 5, p1: 12, p2: 4}"}) {
    auto sim2 = build<2>(grain_on_wall(law));
    check(module<ContactModule<2>>(*sim2),
          (law.find("0.9") != std::string::npos ? 0.9 : 1.0) * 0.001);
    auto sim3 = build<3>(fmt::format(R"(
name: ball
dimension: 3
dp: 0.001
domain: {{min: [0, 0, 0], max: [0.02, 0.02, 0.02]}}
materials:
  iron: {{preset: iron}}
bodies:
  - {{name: ball, phase: rigid, material: iron,
     shape: {{sphere: {{center: [0.01, 0.01, 0.01], radius: 0.003}}}}}}
contact: {}
end_time: 1
)",
                                     law));
    check(module<ContactModule<3>>(*sim3),
          (law.find("0.9") != std::string::npos ? 0.9 : 1.0) * 0.001);
  }
  // Hertz: U = 8/15 E* sqrt(R) delta^2.5 differentiates to F = 4/3 E* sqrt(R) delta^1.5.
  const double d = 1e-5, h = 1e-11;
  EXPECT_NEAR((hertz_energy(2e11, 1e-3, d + h) - hertz_energy(2e11, 1e-3, d - h)) / (2 * h) /
                  hertz_force(2e11, 1e-3, d),
              1.0, 1e-6);
}

TEST(ContactEnergy, SurfaceEnergyDifferentiatesToTheContactForces) {
  // A soft block pressed 0.2 dp into a sloped plate: moving every particle by +-h along y changes
  // the contact energy by -h sum F_y (the Hertz normal forces; no friction, at rest).
  auto sim = build<2>(R"(
name: press
dimension: 2
dp: 0.01
domain: {min: [-0.5, -0.2], max: [1.5, 0.5]}
materials:
  rubber: {density: 1000, bulk_modulus: 1.0e6, shear_modulus: 0.3e6}
bodies:
  - {name: block, phase: solid, material: rubber, shape: {box: {min: [0, 0], max: [0.06, 0.04]}}}
surfaces:
  - {name: floor, segment: [[-0.4, -0.001], [1.4, 0.002]]}
end_time: 1
)");
  auto& rigid = module<RigidSurfaceModule<2>>(*sim);
  auto& p = sim->particles();
  for (auto& x : p.x()) x[1] -= 0.002;
  for (auto& a : p.a()) a.setZero();
  rigid.forces(*sim);
  double fy = 0;
  int touching = 0;
  for (const auto& f : rigid.particle_forces(0)) fy += f[1], touching += f.norm() > 0;
  EXPECT_GE(touching, 3);
  const double h = 1e-8;
  for (auto& x : p.x()) x[1] += h;
  const double up = rigid.potential_energy(*sim);
  for (auto& x : p.x()) x[1] -= 2 * h;
  const double down = rigid.potential_energy(*sim);
  EXPECT_GT(up, 0);
  EXPECT_NEAR(-(up - down) / (2 * h) / fy, 1.0, 1e-5);
}

TEST(ContactEnergy, GrainBouncingOnAWallKeepsTotalEnergy) {
  // Through an elastic impact (damping 0) all kinetic energy is stored in the contact for a
  // moment: total_energy without the contact term drops to 0, with it it stays within 0.5 %.
  for (const std::string law : {"{law: hertz, damping: 0}", "{law: lennard_jones, strength: 5}"}) {
    auto sim = build<2>(grain_on_wall(law));
    const Dip dip = energy_dip(*sim, 200000);
    std::printf("%s: total_energy dip %.4f %% with the contact term, %.2f %% without\n",
                law.c_str(), 100 * dip.with, 100 * dip.without);
    EXPECT_LT(dip.with, 0.005) << law;
    EXPECT_GT(dip.without, 0.5) << law;
  }
}

TEST(ContactEnergy, SolidDiscBouncingOnARigidSurfaceKeepsTotalEnergy) {
  // A rubber disc (d = 10 dp, hourglass springs, no viscous terms) touching a rigid floor at
  // t = 0 and moving into it at 2 m/s: the Hertz energy of the floor contacts fills the dip.
  auto sim = build<2>(R"(
name: disc
dimension: 2
dp: 0.001
domain: {min: [-0.02, -0.01], max: [0.02, 0.03]}
materials:
  rubber: {density: 1000, bulk_modulus: 1.0e7, shear_modulus: 3.0e6}
bodies:
  - name: disc
    phase: solid
    material: rubber
    shape: {circle: {center: [0, 0.0055], radius: 0.005}}
    hourglass: {xi: 0.5, zeta: 0, chi: 0}
    stress_divergence: corrected
    initial: {velocity: [0, -2]}
surfaces:
  - {name: floor, segment: [[-0.02, 0], [0.02, 0]]}
end_time: 1
probes:
  list:
    - {name: E, type: total_energy}
    - {name: U, type: contact_energy}
    - {name: n, type: surface_contacts, surface: floor}
)");
  const Dip dip = energy_dip(*sim, 20000);
  std::printf("total_energy dip %.3f %% with the contact term, %.1f %% without\n", 100 * dip.with,
              100 * dip.without);
  EXPECT_LT(dip.with, 0.01);
  EXPECT_GT(dip.without, 0.2);
}

TEST(ContactEnergy, ProbeTakesNoBody) {
  try {
    load_scene_text(grain_on_wall("{law: hertz}") +
                    "    - {name: U2, type: contact_energy, body: grain}\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "probes.list[3].body: contact_energy is the energy of all contacts; it takes no "
                 "body");
  }
}
