// Rigid clusters (src/rigid/cluster_module) and grain contact (src/coupling/contact_module):
// conservation in vacuum, free rotation, periodic crossing, the Hertz pair law, collisions,
// a grain coming to rest on an elastic block, and a grain settling in fluid.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "assemble.hpp"
#include "coupling/contact_module.hpp"
#include "rigid/cluster_module.hpp"
#include "sim_helpers.hpp"
#include "thread_helpers.hpp"

using namespace monosph;

namespace {

using test::build;
using test::module;

// Linear momentum and angular momentum about the origin of all clusters (2D: z only).
template <int D>
void cluster_momenta(const ClusterModule<D>& cm, Vec<D>& p, Vec3& l) {
  p.setZero();
  l.setZero();
  for (std::size_t c = 0; c < cm.size(); ++c) {
    const auto& k = cm.cluster(c);
    p += k.mass * k.velocity;
    l += pad3<D>(k.centre).cross(pad3<D>(Vec<D>(k.mass * k.velocity))) + cm.angular_momentum(k);
  }
}

// Runs `steps` steps and returns the largest per-step error of the momentum balance of fluid +
// clusters, change of momentum - dt (body forces - forces on the walls) averaged over the step's
// ends, and its scale dt |F|. All fluid-grain, fluid-wall and grain-wall forces are exactly
// opposite pairs, so the error is round-off.
template <int D>
std::pair<double, double> momentum_balance(Simulation<D>& sim, const Vec<D>& g, int steps) {
  auto& p = sim.particles();
  auto& cm = module<ClusterModule<D>>(sim);
  auto total = [&](Vec<D>& mom, Vec<D>& net) {
    mom.setZero();
    net.setZero();
    auto ph = p.phase();
    auto ff = p.template view<Vec<D>>("fluid_force");
    auto cf = p.template view<Vec<D>>("contact_force");
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (ph[i] == kFluid) mom += p.m()[i] * p.v()[i];
      if (ph[i] != kWall)
        net += p.m()[i] * g;
      else
        net -= ff[i] + cf[i];
    }
    for (std::size_t c = 0; c < cm.size(); ++c) mom += cm.cluster(c).mass * cm.cluster(c).velocity;
  };
  Vec<D> m0, f0, m1, f1;
  total(m0, f0);
  double worst = 0, scale = 0;
  for (int s = 0; s < steps; ++s) {
    const double t0 = sim.time();
    sim.advance();
    const double dt = sim.time() - t0;
    total(m1, f1);
    worst = std::max(worst, ((m1 - m0) - 0.5 * dt * (f0 + f1)).norm());
    scale = std::max(scale, dt * f1.norm());
    m0 = m1, f0 = f1;
  }
  return {worst, scale};
}

// Grains in vacuum: domain [0, 0.2] x [0, 0.1] (x periodic), dp = 1 mm, iron.
std::string vacuum(const std::string& bodies, const std::string& extra = "") {
  return fmt::format(R"(
name: grains
dimension: 2
dp: 0.001
domain: {{min: [0, 0], max: [0.2, 0.1], periodic: [x]}}
materials:
  iron: {{preset: iron}}
bodies:
{}
end_time: 1
{}
)",
                     bodies, extra);
}

// A grain in a water tank under gravity (fluid around it: fill rest); shared with the validation
// test GrainInFluid.SettlesOnTheFloorAndTheTankCarriesTheWeight.
std::string settle_scene() {
  std::ifstream in(std::string(MONOSPH_CASES_DIR) + "/../tests/scenes/grain_in_tank.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(Clusters, GrainInVacuumKeepsMomentumAndShapeAcrossAPeriodicBoundary) {
  // A spinning, translating grain crosses the periodic x boundary several times: V and omega stay
  // exact, the members keep their distances from the centre, the centre moves by V t.
  auto sim = build<2>(vacuum(R"(
  - name: grain
    phase: rigid
    material: iron
    shape: {circle: {center: [0.19, 0.05], radius: 0.005}}
    initial: {velocity: [30, 1], angular_velocity: 400})"));
  auto& cm = module<ClusterModule<2>>(*sim);
  ASSERT_EQ(cm.size(), 1u);
  const auto c0 = cm.cluster(0);
  EXPECT_NEAR(c0.velocity[0], 30, 1e-12);
  EXPECT_GT(c0.members.size(), 70u);
  std::map<std::int64_t, double> dist;  // by particle id (the particles get re-ordered)
  auto& p = sim->particles();
  for (std::size_t k : c0.members) dist[p.id()[k]] = (p.x()[k] - c0.centre).norm();
  const double t_end = 0.02;  // 0.6 m: three periods of the box
  while (sim->time() < t_end - 1e-15) sim->advance(t_end);
  const auto& c = cm.cluster(0);
  EXPECT_NEAR(c.velocity[0], 30, 1e-12);
  EXPECT_NEAR(c.velocity[1], 1, 1e-12);
  EXPECT_NEAR(c.omega[2], 400, 1e-10);
  EXPECT_NEAR(c.angle, 400 * t_end, 1e-10);
  double cx = 0.19 + 30 * t_end;
  cx -= 0.2 * std::floor(cx / 0.2);
  EXPECT_NEAR(c.centre[0], cx, 1e-12);
  EXPECT_NEAR(c.centre[1], 0.05 + t_end, 1e-12);
  sim->rebuild_neighbours();  // wraps the members into the box
  double worst = 0;
  std::size_t q = 0;
  auto id = p.id();
  for (std::size_t k : cm.cluster(0).members) {
    Vec<2> d = p.x()[k] - c.centre;
    d[0] -= 0.2 * std::round(d[0] / 0.2);
    ASSERT_GE(p.x()[k][0], 0.0);
    ASSERT_LT(p.x()[k][0], 0.2);
    worst = std::max(worst, std::abs(d.norm() - dist.at(id[k])));
    ++q;
  }
  EXPECT_EQ(q, dist.size());
  EXPECT_LT(worst, 1e-12);
}

TEST(Clusters, FreeRotationIn3D) {
  // Torque-free asymmetric top (a 6 x 4 x 2 dp brick): L stays exact, the kinetic energy
  // L . omega / 2 within 1e-4 over about two turns; a sphere keeps its angular velocity.
  auto sim = build<3>(R"(
name: top
dimension: 3
dp: 0.001
domain: {min: [0, 0, 0], max: [0.04, 0.04, 0.04]}
materials:
  iron: {preset: iron}
bodies:
  - name: brick
    phase: rigid
    material: iron
    shape: {box: {min: [0.005, 0.005, 0.005], max: [0.011, 0.009, 0.007]}}
    initial: {angular_velocity: [30, 20, 10]}
  - name: ball
    phase: rigid
    material: iron
    shape: {sphere: {center: [0.03, 0.03, 0.03], radius: 0.004}}
    initial: {angular_velocity: [5, -7, 11]}
end_time: 1
)");
  auto& cm = module<ClusterModule<3>>(*sim);
  ASSERT_EQ(cm.size(), 2u);
  const Vec3 l0 = cm.cluster(0).momentum;
  auto energy = [&](const ClusterModule<3>::Cluster& c) {
    const Mat3 r = c.q.toRotationMatrix();
    const Vec3 w = r * c.inertia_body_inv * r.transpose() * c.momentum;
    return 0.5 * w.dot(c.momentum);
  };
  const double e0 = energy(cm.cluster(0));
  const Vec3 w1 = Vec3(5, -7, 11);
  while (sim->time() < 0.3) sim->advance(0.3);
  EXPECT_LT((cm.cluster(0).momentum - l0).norm(), 1e-14 * l0.norm());
  EXPECT_NEAR(energy(cm.cluster(0)) / e0, 1.0, 1e-4);
  const auto& b = cm.cluster(1);
  const Mat3 r = b.q.toRotationMatrix();
  const Vec3 w = r * b.inertia_body_inv * r.transpose() * b.momentum;
  EXPECT_LT((w - w1).norm(), 1e-10 * w1.norm());
}

TEST(Contact, HertzPairLaw) {
  // F(2 delta)/F(delta) = 2^1.5; E* from the two materials; zero beyond the contact distance.
  auto sim = build<2>(vacuum(R"(
  - name: grain
    phase: rigid
    material: iron
    shape: {circle: {center: [0.05, 0.05], radius: 0.003}})"));
  auto& ct = module<ContactModule<2>>(*sim);
  const double dp = 0.001, d1 = 0.01 * dp;
  const double f1 = ct.pair_force(dp - d1, 0, 0, 1, 1), f2 = ct.pair_force(dp - 2 * d1, 0, 0, 1, 1);
  EXPECT_NEAR(f2 / f1, std::pow(2.0, 1.5), 1e-12);
  EXPECT_EQ(ct.pair_force(dp, 0, 0, 1, 1), 0.0);
  const double e = 211e9, nu = 0.29, estar = e / (2 * (1 - nu * nu));
  EXPECT_NEAR(ct.contact_modulus(0, 0) / estar, 1.0, 1e-12);
  // 4/3 E* sqrt(dp/4) delta^1.5 per depth dp
  EXPECT_NEAR(f1 / (4.0 / 3.0 * estar * std::sqrt(dp / 4) * std::pow(d1, 1.5) / dp), 1.0, 1e-12);
}

TEST(Contact, TwoGrainsCollideConservingMomentum) {
  // Two grains meet head-on (and two more obliquely): total linear momentum and angular momentum
  // about the origin are conserved to round-off through the contact; without damping the
  // head-on pair rebounds with a restitution coefficient of 1 within 2 %.
  auto sim = build<2>(vacuum(R"(
  - name: a
    phase: rigid
    material: iron
    shape: {circle: {center: [0.04, 0.03], radius: 0.005}}
    initial: {velocity: [2, 0]}
  - name: b
    phase: rigid
    material: iron
    shape: {circle: {center: [0.06, 0.03], radius: 0.005}}
    initial: {velocity: [-2, 0]}
  - name: c
    phase: rigid
    material: iron
    shape: {circle: {center: [0.12, 0.065], radius: 0.005}}
    initial: {velocity: [2, 0], angular_velocity: 50}
  - name: d
    phase: rigid
    material: iron
    shape: {circle: {center: [0.14, 0.07], radius: 0.005}}
    initial: {velocity: [-1, 0.2]})"));
  auto& cm = module<ClusterModule<2>>(*sim);
  auto& ct = module<ContactModule<2>>(*sim);
  Vec<2> p0;
  Vec3 l0;
  cluster_momenta(cm, p0, l0);
  const double pscale = 4 * cm.cluster(0).mass * 2;
  long max_pairs = 0;
  while (sim->time() < 0.01) {
    sim->advance(0.01);
    max_pairs = std::max(max_pairs, ct.pairs());
  }
  EXPECT_GT(max_pairs, 0);
  EXPECT_EQ(ct.impacts(), 0);  // grain-grain contacts are not impacts on a solid or wall
  Vec<2> p1;
  Vec3 l1;
  cluster_momenta(cm, p1, l1);
  EXPECT_LT((p1 - p0).norm(), 1e-13 * pscale);
  EXPECT_LT(std::abs(l1[2] - l0[2]), 1e-12 * pscale * 0.1);
  const double e = (cm.cluster(1).velocity[0] - cm.cluster(0).velocity[0]) / 4.0;
  EXPECT_NEAR(e, 1.0, 0.02);
  EXPECT_LT(cm.cluster(0).velocity[0], 0);  // rebounded
}

TEST(Clusters, GrainComesToRestOnAnElasticBlock) {
  // A grain (d = 10 dp) dropped from about 1 dp above a soft elastic block (held at its base)
  // under gravity comes to rest on it; the largest overlap with the block stays below 0.5 dp.
  // The contact dashpot (3 x critical for one particle pair, about 0.3 for the grain on its ~5
  // contacts) provides the dissipation; without it the grain keeps bouncing on the barely
  // damped block.
  auto sim = build<2>(R"(
name: drop
dimension: 2
dp: 0.001
domain: {min: [0, -0.01], max: [0.04, 0.04]}
materials:
  iron: {preset: iron}
  rubber: {density: 1000, bulk_modulus: 0.5e6, shear_modulus: 0.15e6}
bodies:
  - name: block
    phase: solid
    material: rubber
    shape: {box: {min: [0, 0], max: [0.04, 0.01]}}
    artificial_viscosity: {alpha: 1.0}
    hourglass: {xi: 0.5, zeta: 10, chi: 0.5}
  - name: grain
    phase: rigid
    material: iron
    shape: {circle: {center: [0.02, 0.0155], radius: 0.005}}
boundary_conditions:
  - {type: fixed, region: {box: {min: [0, 0], max: [0.04, 0.002]}}}
contact: {damping: 3}
body_force: [0, -9.81]
end_time: 1
)");
  auto& cm = module<ClusterModule<2>>(*sim);
  auto& ct = module<ContactModule<2>>(*sim);
  double worst = 0, vmax = 0;
  while (sim->time() < 0.16) {
    sim->advance(0.16);
    worst = std::max(worst, ct.max_overlap());
    vmax = std::max(vmax, cm.cluster(0).velocity.norm());
  }
  EXPECT_GE(ct.impacts(), 1);
  EXPECT_GT(vmax, 0.08);  // it fell (sqrt(2 g dp) = 0.14 m/s)
  EXPECT_LT(cm.cluster(0).velocity.norm(), 0.001 * vmax);
  EXPECT_LT(std::abs(cm.cluster(0).omega[2]) * 0.005, 0.001 * vmax);
  EXPECT_LT(worst, 0.5 * 0.001);
  EXPECT_GT(ct.pairs(), 0);  // resting on the block
  EXPECT_LT(std::abs(cm.cluster(0).centre[1] - 0.0155), 0.0015);
}

TEST(Clusters, GrainInFluidMomentumBalancesTheBodyForces) {
  // A grain in a water tank under gravity. Every step, the change of momentum of fluid + grain
  // equals dt times the mean of (body forces - forces on the walls) at both ends of the step, to
  // round-off: all fluid-grain, fluid-wall and grain-wall forces are exactly opposite pairs.
  auto sim = build<2>(settle_scene());
  const auto [worst, scale] = momentum_balance<2>(*sim, Vec<2>(0, -9.81), 300);
  auto& cm = module<ClusterModule<2>>(*sim);
  EXPECT_LT(worst, 1e-10 * scale);
  EXPECT_LT(cm.cluster(0).velocity[1], 0);  // sinking
}

TEST(Clusters, ResultsDoNotDependOnThreadCount) {
  test::expect_thread_independent<2>(
      [] {
        return build<2>(vacuum(R"(
  - name: a
    phase: rigid
    material: iron
    shape: {circle: {center: [0.04, 0.03], radius: 0.005}}
    initial: {velocity: [2, 0.1], angular_velocity: 30}
  - name: b
    phase: rigid
    material: iron
    shape: {circle: {center: [0.055, 0.032], radius: 0.005}}
    initial: {velocity: [-2, 0]})"));
      },
      300);
  test::expect_thread_independent<2>([] { return build<2>(settle_scene()); }, 100);
}

// Two cylinders in oil, close to each other and to the floor: the lubrication films (cluster-wall
// and cluster-cluster) act from the first step; they are found per particle in parallel and
// summed per cluster in index order, so 1 and 2 threads give the same bits.
std::string lubricated_pair(bool lubricated) {
  return std::string(R"(
name: lubricated_pair
dimension: 2
dp: 1.0e-4
kernel: {type: cubic_spline, h_factor: 1.3}
domain: {min: [0, -3.0e-4], max: [8.0e-3, 5.3e-3], periodic: [x]}
materials:
  oil: {density: 1000, sound_speed: 0.316, viscosity: 5.0e-3}
  iron: {preset: iron}
  wall: {density: 1000, sound_speed: 0.316}
bodies:
  - name: grains
    phase: rigid
    material: iron
    clusters: per_part
    shape:
      union:
        - {circle: {center: [3.0e-3, 1.07e-3], radius: 1.0e-3}}
        - {circle: {center: [5.07e-3, 1.2e-3], radius: 1.0e-3}}
    initial: {velocity: ["x < 4e-3 ? 1e-3 : -1e-3", "-1.0e-3"]}
  - name: fluid
    phase: fluid
    material: oil
    fill: rest
    shape: {box: {min: [0, 0], max: [8.0e-3, 5.0e-3]}}
    density_diffusion: {delta: 0.1}
  - name: floor
    phase: wall
    material: wall
    shape: {box: {min: [0, -3.0e-4], max: [8.0e-3, 0]}}
end_time: 1
time_step: {cfl: 0.3}
)") + (lubricated ? "lubrication: {cutoff: 1.5, min_gap: 0.05}\n" : "");
}

TEST(Clusters, LubricatedGrainsDoNotDependOnThreadCount) {
  auto with = build<2>(lubricated_pair(true)), without = build<2>(lubricated_pair(false));
  for (int k = 0; k < 5; ++k) with->advance(), without->advance();
  // The films act: the left cylinder closes on the right one (its closest partner) more slowly
  // than with the resolved fluid alone.
  const auto& v = module<ClusterModule<2>>(*with).cluster(0).velocity;
  const auto& v0 = module<ClusterModule<2>>(*without).cluster(0).velocity;
  EXPECT_LT(v[0], v0[0]);
  test::expect_thread_independent<2>([] { return build<2>(lubricated_pair(true)); }, 40);
}

// The free cylinder in plane Couette flow (the torque of the fluid on a cluster, over 10 shear
// times) is the validation test CouetteCylinder.TurnsAtTheConfinedStokesRateWithoutPairingOver10-
// ShearTimes (tests/validation/test_fluid_cases.cpp; cases/couette_cylinder).

TEST(Clusters, SphereInFluidMomentumBalanceIn3D) {
  // 3D: an iron sphere in a water box under gravity. Every step the momentum of fluid + sphere
  // changes by dt times (body forces - forces on the walls), to round-off; the sphere sinks and
  // starts to turn only by round-off (the set-up is symmetric about the sphere's vertical axis).
  auto sim = build<3>(R"(
name: settle3d
dimension: 3
dp: 0.004
domain: {min: [-0.012, -0.012, -0.012], max: [0.052, 0.052, 0.06]}
materials:
  water: {density: 1000, sound_speed: 15, viscosity: 0.01}
  iron: {preset: iron}
bodies:
  - name: grain
    phase: rigid
    material: iron
    shape: {sphere: {center: [0.02, 0.02, 0.024], radius: 0.008}}
  - name: water
    phase: fluid
    material: water
    fill: rest
    shape: {box: {min: [0, 0, 0], max: [0.04, 0.04, 0.044]}}
    density_diffusion: {delta: 0.1}
  - name: tank
    phase: wall
    material: water
    shape: {difference: [{box: {min: [-0.012, -0.012, -0.012], max: [0.052, 0.052, 0.06]}}, {box: {min: [0, 0, 0], max: [0.04, 0.04, 0.06]}}]}
body_force: [0, 0, -9.81]
end_time: 1
)");
  const auto [worst, scale] = momentum_balance<3>(*sim, Vec<3>(0, 0, -9.81), 100);
  auto& cm = module<ClusterModule<3>>(*sim);
  EXPECT_LT(worst, 1e-10 * scale);
  EXPECT_LT(cm.cluster(0).velocity[2], 0);  // sinking
  const auto& c = cm.cluster(0);
  const Mat3 r = c.q.toRotationMatrix();
  const Vec3 w = r * c.inertia_body_inv * r.transpose() * c.momentum;
  EXPECT_LT(w.norm() * 0.008, 1e-6 * std::abs(c.velocity[2]));
}
