// Self-contact of a solid body (`self_contact`): Hertz spheres of diameter d_c between its own
// particles. Silent on the lattice, Hertz law in the overlap, central pair forces that conserve
// linear and angular momentum, and two approaching particles turned back before they meet.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sph_equations.hpp"
#include "scene_helpers.hpp"
#include "solid/solid_module.hpp"

using namespace monosph;

namespace {

template <int D>
struct Rig {
  std::unique_ptr<Simulation<D>> sim;
  SolidModule<D>* solid;
  explicit Rig(double distance) {
    sim = std::make_unique<Simulation<D>>(
        test::solid_block_scene(D, D == 2 ? "[0.08, 0.06]" : "[0.05, 0.04, 0.04]", 0.0, 3,
                                fmt::format("self_contact: {{distance: {}}}", distance)));
    sim->add_module(std::make_unique<SphEquations<D>>(*sim, true));
    auto s = std::make_unique<SolidModule<D>>(*sim);
    solid = s.get();
    sim->add_module(std::move(s));
    sim->create_particles();
    sim->init();
  }
  void forces() {
    auto& p = sim->particles();
    sim->rebuild_neighbours();
    sim->update_pair_cache();
    for (auto& m : sim->modules()) m->sums(*sim);
    for (auto& m : sim->modules()) m->constitutive(*sim);
    for (auto& a : p.a()) a.setZero();
    solid->forces(*sim);  // no hourglass control: the self-contact force alone
  }
  // Index of the particle with this id (a neighbour rebuild may reorder the particles).
  std::size_t at(std::int64_t id) {
    auto ids = sim->particles().id();
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (ids[k] == id) return k;
    return ids.size();
  }
  std::size_t nearest(const Vec<D>& x) {
    auto& p = sim->particles();
    std::size_t best = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if ((p.x()[i] - x).norm() < (p.x()[best] - x).norm()) best = i;
    return best;
  }
};

// Steel of solid_block_scene: K 160 GPa, mu 80 GPa.
double contact_modulus() {
  const double K = 160e9, mu = 80e9;
  const double E = 9 * K * mu / (3 * K + mu), nu = (3 * K - 2 * mu) / (2 * (3 * K + mu));
  return E / (2 * (1 - nu * nu));
}

template <int D>
void hertz_law_and_momentum() {
  const double dp = 0.01, s = 0.6, dc = s * dp;
  {
    Rig<D> rig(s);  // the undisturbed lattice: every pair at >= dp, no force
    rig.forces();
    for (const auto& a : rig.sim->particles().a()) EXPECT_EQ(a.norm(), 0.0);
  }
  for (double gap : {0.5, 0.3, 0.1}) {  // overlap 0.1, 0.3, 0.5 dp
    Rig<D> rig(s);
    auto& p = rig.sim->particles();
    Vec<D> c = Vec<D>::Constant(0.025);
    const std::size_t i = rig.nearest(c);
    Vec<D> off = Vec<D>::Zero();
    off[0] = dp;
    std::size_t j = rig.nearest(p.x()[i] + off);
    ASSERT_NE(i, j);
    // j moves towards i to distance gap*dp along a slanted line (not a lattice axis)
    Vec<D> dir = Vec<D>::Ones().normalized();
    p.x()[j] = p.x()[i] + gap * dp * dir;
    const auto idj = p.id()[j];
    rig.forces();
    j = rig.at(idj);
    const double delta = dc - gap * dp, depth = D == 2 ? dp : 1.0;
    const double f =
        4.0 / 3.0 * contact_modulus() * std::sqrt(0.25 * dc) * std::pow(delta, 1.5) / depth;
    const Vec<D> fj = p.m()[j] * p.a()[j];
    EXPECT_NEAR(fj.dot(dir), f, 1e-9 * f) << "gap " << gap;
    EXPECT_NEAR((fj - fj.dot(dir) * dir).norm(), 0.0, 1e-9 * f);
    Vec<D> sum = Vec<D>::Zero();
    double torque = 0;  // z component of sum x ^ F
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Vec<D> fk = p.m()[k] * p.a()[k];
      sum += fk;
      torque += p.x()[k][0] * fk[1] - p.x()[k][1] * fk[0];
    }
    EXPECT_LT(sum.norm(), 1e-12 * f);
    EXPECT_LT(std::abs(torque), 1e-12 * f * 0.1);
    // no hourglass springs: the step is 20 per contact period at the pair's stiffness dF/d(delta)
    const double kn = 2 * contact_modulus() * std::sqrt(0.25 * dc * delta) / depth;
    const double dt = 0.1 * M_PI / std::sqrt(kn / p.m()[j]);
    EXPECT_NEAR(rig.solid->max_dt(*rig.sim), dt, 1e-9 * dt);
  }
}

// Two particles fired at each other (velocity Verlet, no other force): they turn back at a
// distance above zero and leave with their speed (an elastic contact).
template <int D>
void head_on_particles_bounce() {
  const double dp = 0.01, s = 0.5;
  Rig<D> rig(s);
  auto& p = rig.sim->particles();
  std::size_t i = rig.nearest(Vec<D>::Constant(0.025));
  Vec<D> off = Vec<D>::Zero();
  off[0] = dp;
  std::size_t j = rig.nearest(p.x()[i] + off);
  const auto idi = p.id()[i], idj = p.id()[j];
  const double v0 = 200.0;  // m/s, far above the impact speeds of the cases
  const Vec<D> xi0 = p.x()[i], xj0 = p.x()[j];
  double rmin = dp;
  p.v()[i] = v0 * off / dp, p.v()[j] = -v0 * off / dp;
  for (int step = 0; step < 4000; ++step) {
    // only i and j move: every other particle stays on its node
    rig.forces();
    i = rig.at(idi), j = rig.at(idj);
    const double dt = std::min(1e-7, rig.solid->max_dt(*rig.sim));
    const Vec<D> ai = p.a()[i], aj = p.a()[j];
    p.x()[i] += dt * p.v()[i] + 0.5 * dt * dt * ai;
    p.x()[j] += dt * p.v()[j] + 0.5 * dt * dt * aj;
    rig.forces();
    i = rig.at(idi), j = rig.at(idj);
    p.v()[i] += 0.5 * dt * (ai + p.a()[i]);
    p.v()[j] += 0.5 * dt * (aj + p.a()[j]);
    rmin = std::min(rmin, (p.x()[j] - p.x()[i]).norm());
    if ((p.x()[j] - p.x()[i]).norm() > s * dp && p.v()[j].dot(off) > 0) break;
  }
  EXPECT_GT(rmin, 0.05 * dp);
  EXPECT_LT(rmin, s * dp);
  EXPECT_NEAR(p.v()[j].dot(off) / dp, v0, 1e-2 * v0);  // elastic: the speed comes back
  EXPECT_NEAR((p.x()[i] + p.x()[j] - xi0 - xj0).norm(), 0.0, 1e-12);  // centre of mass at rest
}

}  // namespace

TEST(SelfContact, HertzLawSilentLatticeAndMomentum2D) {
  hertz_law_and_momentum<2>();
}
TEST(SelfContact, HertzLawSilentLatticeAndMomentum3D) {
  hertz_law_and_momentum<3>();
}
TEST(SelfContact, HeadOnParticlesTurnBack2D) {
  head_on_particles_bounce<2>();
}
TEST(SelfContact, HeadOnParticlesTurnBack3D) {
  head_on_particles_bounce<3>();
}
