// Contact between solid bodies of different continua (`solid_contact`): silent while the bodies
// only touch (every pair at >= d_c), the Hertz law in the overlap, exactly opposite pair forces,
// no tension when the bodies are pulled apart, friction mu N against the sliding, and no section
// for bodies of one continuum (they are glued by the SPH equations).
#include <gtest/gtest.h>

#include <cmath>

#include "core/sph_equations.hpp"
#include "coupling/solid_contact_module.hpp"
#include "scene_helpers.hpp"

using namespace monosph;

namespace {

// Two steel blocks, 4 x 3 dp (2D), the upper one on top of the lower one (faces dp apart: the
// lattice spacing), of continua `a` and `b`.
Scene two_blocks(const std::string& a, const std::string& b, const std::string& extra) {
  return load_scene_text(fmt::format(R"(
name: blocks
dimension: 2
dp: 0.01
domain: {{min: [-1, -1], max: [1, 1]}}
materials:
  steel: {{density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9}}
bodies:
  - {{name: low, phase: solid, material: steel, continuum: {0}, shape: {{box: {{min: [0, 0], max: [0.04, 0.03]}}}}}}
  - {{name: up, phase: solid, material: steel, continuum: {1}, shape: {{box: {{min: [0, 0.03], max: [0.04, 0.06]}}}}}}
end_time: 1
{2}
)",
                                     a, b, extra));
}

struct Rig {
  std::unique_ptr<Simulation<2>> sim;
  SolidContactModule<2>* contact = nullptr;
  explicit Rig(const Scene& s) {
    sim = std::make_unique<Simulation<2>>(s);
    sim->add_module(std::make_unique<SphEquations<2>>(*sim, true));
    if (module_params<SolidContactSpec>(s.params).on) {
      auto c = std::make_unique<SolidContactModule<2>>(*sim);
      contact = c.get();
      sim->add_module(std::move(c));
    }
    sim->create_particles();
    sim->init();
  }
  // Moves the upper body by d (and gives it velocity u), then the contact forces alone.
  void place(const Vec<2>& d, const Vec<2>& u) {
    auto& p = sim->particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.body()[i] == 1) p.x()[i] += d, p.v()[i] = u;
    sim->rebuild_neighbours();
    sim->update_pair_cache();
    for (auto& a : p.a()) a.setZero();
    contact->forces(*sim);
  }
  Vec<2> force_on(int body) {
    auto& p = sim->particles();
    Vec<2> f = Vec<2>::Zero();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.body()[i] == body) f += p.m()[i] * p.a()[i];
    return f;
  }
};

double steel_estar() {  // both blocks steel: 1/E* = 2 (1 - nu^2)/E (Johnson 1985, Eq. 4.23)
  const double K = 160e9, mu = 80e9;
  const double E = 9 * K * mu / (3 * K + mu), nu = (3 * K - 2 * mu) / (2 * (3 * K + mu));
  return E / (2 * (1 - nu * nu));
}

}  // namespace

TEST(SolidContact, SilentWhileTouchingHertzInTheOverlapAndNoTension) {
  const double dp = 0.01;
  Rig rig(two_blocks("a", "b", "solid_contact: {distance: 1.0}"));
  rig.place(Vec<2>::Zero(), Vec<2>::Zero());  // faces one spacing apart: every pair at >= d_c
  EXPECT_EQ(rig.force_on(1).norm(), 0.0);
  EXPECT_EQ(rig.contact->pairs(), 0);
  // Pressed by 0.1 dp: 4 columns, one pair each at r = 0.9 dp along y (Hertz, per depth dp).
  rig.place(Vec<2>(0, -0.1 * dp), Vec<2>::Zero());
  EXPECT_EQ(rig.contact->pairs(), 4);
  const double f1 = 4.0 / 3.0 * steel_estar() * std::sqrt(0.25 * dp) * std::pow(0.1 * dp, 1.5) / dp;
  const Vec<2> up = rig.force_on(1), low = rig.force_on(0);
  EXPECT_NEAR(up[1] / (4 * f1), 1.0, 1e-12);
  EXPECT_NEAR(up[0], 0.0, 1e-9 * f1);
  EXPECT_LE((up + low).norm(), 1e-12 * f1);  // each particle its own side: exactly opposite
  EXPECT_NEAR(rig.contact->pair_force(0.9 * dp, 0, 0), f1, 1e-12 * f1);
  // Pulled apart by 0.1 dp: no tension (the glued continuum would pull back).
  rig.place(Vec<2>(0, 0.2 * dp), Vec<2>::Zero());
  EXPECT_EQ(rig.force_on(1).norm(), 0.0);
  EXPECT_EQ(rig.contact->pair_force(1.0 * dp, 0, 0), 0.0);
}

TEST(SolidContact, FrictionIsMuTimesTheNormalForceAndOpposesTheSliding) {
  const double dp = 0.01;
  Rig rig(two_blocks("a", "b", "solid_contact: {distance: 1.0, friction: 0.4}"));
  rig.sim->set_state(0, 0, 1e-8);                   // the cap m* |v_t|/dt far above mu N
  rig.place(Vec<2>(0, -0.1 * dp), Vec<2>(2.0, 0));  // sliding along +x at 2 m/s
  const Vec<2> up = rig.force_on(1), low = rig.force_on(0);
  EXPECT_NEAR(-up[0] / up[1], 0.4, 1e-12);
  EXPECT_LE((up + low).norm(), 1e-12 * up.norm());
}

TEST(SolidContact, NotBetweenBodiesOfOneContinuum) {
  // One continuum: the SPH equations join the blocks; the section is refused (nothing to touch).
  EXPECT_THROW(two_blocks("a", "a", "solid_contact: {distance: 1.0}"), InputError);
}
