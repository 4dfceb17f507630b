// Transport-velocity shifting (Adami, Hu & Adams 2013) and the consistent-shifting terms of
// Sun et al. 2019 (src/fluid/shifting_terms.hpp, `shifting: {form, pressure, consistent}`).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "assemble.hpp"
#include "core/kernel.hpp"
#include "fluid/fluid_keys.hpp"
#include "fluid/shifting_terms.hpp"
#include "scene/scene_reader.hpp"

using namespace monosph;

namespace {

// The neighbours of a particle at the origin on a square lattice of spacing dp (Wendland C2,
// h = 2 dp, as cases/couette_cylinder): x_j and grad_i W_ij = f (x_i - x_j).
struct Lattice {
  std::vector<Vec<2>> x, gw;
  double V;
};

Lattice lattice(double dp) {
  const Kernel<2> W(KernelType::WendlandC2, 2 * dp);
  Lattice l{{}, {}, dp * dp};
  for (int a = -6; a <= 6; ++a)
    for (int b = -6; b <= 6; ++b) {
      const Vec<2> xj(a * dp, b * dp);
      const double r = xj.norm();
      if ((a == 0 && b == 0) || r >= W.radius()) continue;
      l.x.push_back(xj);
      l.gw.push_back(W.f(r) * Vec<2>(-xj));
    }
  return l;
}

std::unique_ptr<Simulation<2>> build(const Scene& s) {
  auto sim = std::make_unique<Simulation<2>>(s);
  assemble_modules(*sim);
  sim->create_particles();
  return sim;
}

Scene periodic_lattice(const std::string& shifting) {
  return load_scene_text(fmt::format(R"(
name: lattice
dimension: 2
dp: 0.01
kernel: {{type: wendland_c2, h_factor: 2.0}}
domain: {{min: [0, 0], max: [0.2, 0.2], periodic: [x, y]}}
materials:
  water: {{density: 1000, sound_speed: 20}}
bodies:
  - {{name: water, phase: fluid, material: water, shape: {{box: {{min: [0, 0], max: [0.2, 0.2]}}}},
     shifting: {0}}}
end_time: 1
)",
                                     shifting));
}

}  // namespace

TEST(ShiftingTerms, VanishOnUniformFieldsForAnyShift) {
  // A uniform flow and density are not changed by moving the particles: on a lattice
  // (sum_j V_j grad W_ij = 0) both Sun et al. 2019 terms vanish for arbitrary du_i, du_j.
  const double dp = 0.01;
  const Lattice l = lattice(dp);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec<2> v(0.3, -0.7), dui(u(rng), u(rng));
  Vec<2> mom = Vec<2>::Zero();
  double cont = 0, scale = 0;
  for (std::size_t k = 0; k < l.x.size(); ++k) {
    const Vec<2> duj(u(rng), u(rng));
    mom += ale_momentum_pair<2>(v, v, dui, duj, l.gw[k], l.V);
    cont += ale_continuity_pair<2>(1000.0, 1000.0, dui, duj, l.gw[k], l.V);
    scale += l.V * l.gw[k].norm();  // |a term| ~ |v| |du| sum V |grad W|
  }
  EXPECT_LT(mom.norm(), 1e-12 * scale);
  EXPECT_LT(std::abs(cont), 1e-12 * 1000 * scale);
  EXPECT_GT(scale, 1 / dp);  // the sums are not trivially small (sum V |grad W| = 1.13/dp)
}

TEST(ShiftingTerms, AreTheConvectiveDerivativesOfLinearFields) {
  // v = G x + c and rho = rho0 + g . x with a uniform shift du: the momentum term is
  // (du . grad) v = G du, the continuity term du . grad rho = du . g, to the lattice's
  // first-moment error (sum_j V_j x_ji (x) grad W_ij = I to 1.1e-3 with Wendland C2 at h = 2 dp).
  const double dp = 0.01;
  const Lattice l = lattice(dp);
  Mat<2> G;
  G << 0.5, 2.0, -1.0, 0.25;
  const Vec<2> c(0.1, 0.2), g(30.0, -50.0), du(0.02, -0.03);
  const double rho0 = 1000;
  Vec<2> mom = Vec<2>::Zero();
  double cont = 0;
  Mat<2> B = Mat<2>::Zero();
  for (std::size_t k = 0; k < l.x.size(); ++k) {
    mom += ale_momentum_pair<2>(c, Vec<2>(G * l.x[k] + c), du, du, l.gw[k], l.V);
    cont += ale_continuity_pair<2>(rho0, rho0 + g.dot(l.x[k]), du, du, l.gw[k], l.V);
    B += l.V * l.x[k] * l.gw[k].transpose();
  }
  EXPECT_NEAR((B - Mat<2>::Identity()).norm(), 0.0, 2e-3);
  EXPECT_LT((mom - G * du).norm(), 2e-3 * (G * du).norm());
  EXPECT_NEAR(cont, du.dot(g), 2e-3 * std::abs(du.dot(g)));
  // Exactly the first moment B applied (the lattice sum of V_j grad W_ij is zero).
  EXPECT_LT((mom - G * B.transpose() * du).norm(), 1e-12);
}

TEST(ShiftingTerms, TransportVelocityVanishesOnALatticeAndPullsADisplacedParticleBack) {
  // Adami et al. 2013: du_i = -(dt/2)(p_b/m_i) sum_j (V_i^2 + V_j^2) grad W_ij. Zero on a
  // lattice; towards the site for a displaced particle; proportional to p_b and to the step.
  auto shift_of_displaced = [](double pb, double& dt) {
    auto sim = build(periodic_lattice(
        fmt::format("{{form: transport_velocity, pressure: {}, consistent: true}}", pb)));
    auto& p = sim->particles();
    sim->init();
    sim->init();  // the first pass has no step yet (dt = 0: no shift)
    auto sh = p.view<Vec<2>>("shift_rate");
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_LT(sh[i].norm(), 1e-12) << i;
    std::size_t k = p.size() / 2 + 7;
    const auto id = p.id()[k];
    const Vec<2> site = p.x()[k];
    p.x()[k] += Vec<2>(0.002, 0.001);
    sim->init();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id()[i] == id) k = i;
    dt = sim->dt();
    sh = p.view<Vec<2>>("shift_rate");
    const Vec<2> back = site - p.x()[k];
    EXPECT_GT(sh[k].dot(back), 0.9 * sh[k].norm() * back.norm());
    return Vec<2>(sh[k]);
  };
  double dt1 = 0, dt2 = 0;
  const Vec<2> s1 = shift_of_displaced(1000, dt1), s2 = shift_of_displaced(2000, dt2);
  EXPECT_GT(s1.norm(), 0);
  EXPECT_DOUBLE_EQ(dt1, dt2);
  EXPECT_NEAR((s2 - 2 * s1).norm(), 0.0, 1e-9 * s1.norm());
}

TEST(ShiftingTerms, SceneKeys) {
  auto s = periodic_lattice("{form: transport_velocity, pressure: 400, consistent: true}");
  EXPECT_DOUBLE_EQ(module_params<FluidBodyKeys>(s.bodies[0].params).shift_pb, 400);
  EXPECT_DOUBLE_EQ(module_params<FluidBodyKeys>(s.bodies[0].params).shift_speed, 0);
  EXPECT_TRUE(module_params<FluidBodyKeys>(s.bodies[0].params).shift_consistent);
  auto d = periodic_lattice("{speed: 0.1}");  // the delta-plus default is unchanged
  EXPECT_DOUBLE_EQ(module_params<FluidBodyKeys>(d.bodies[0].params).shift_speed, 0.1);
  EXPECT_DOUBLE_EQ(module_params<FluidBodyKeys>(d.bodies[0].params).shift_pb, 0);
  EXPECT_FALSE(module_params<FluidBodyKeys>(d.bodies[0].params).shift_consistent);
  EXPECT_THROW(periodic_lattice("{form: transport_velocity}"), InputError);  // no pressure
  EXPECT_THROW(periodic_lattice("{form: transport_velocity, pressure: 1, speed: 1}"),
               InputError);  // speed belongs to delta_plus
  EXPECT_THROW(periodic_lattice("{form: tvf, pressure: 1}"), InputError);
}
