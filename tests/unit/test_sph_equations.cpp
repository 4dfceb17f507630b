// The shared Eulerian SPH equations: momentum conservation, uniform pressure, thread independence.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "core/sph_equations.hpp"
#include "scene_helpers.hpp"
#include "thread_helpers.hpp"

using namespace monosph;

namespace {

template <int D>
std::unique_ptr<Simulation<D>> make(const Scene& s, double vamp, unsigned seed) {
  auto sim = std::make_unique<Simulation<D>>(s);
  sim->add_module(std::make_unique<SphEquations<D>>(*sim));
  sim->create_particles();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto& p = sim->particles();
  for (auto& v : p.v())
    for (int a = 0; a < D; ++a) v[a] = vamp * u(rng);
  for (auto& r : p.rho()) r *= 1 + 0.01 * u(rng);
  sim->init();
  return sim;
}

const char* kAV = "    artificial_viscosity: {alpha: 1.0, beta: 2.0}";

}  // namespace

TEST(SphEquations, PairForcesConserveLinearMomentum) {
  Scene s = test::box_scene(2, 0.01, 0.2, 0.15, 0, "x", 0.3, kAV);
  auto sim = make<2>(s, 0.5, 3);
  auto& p = sim->particles();
  Vec<2> f = Vec<2>::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    f += p.m()[i] * p.a()[i], scale += p.m()[i] * p.a()[i].norm();
  EXPECT_LT(f.norm(), 1e-13 * scale);
}

TEST(SphEquations, PressureForcesConserveAngularMomentum) {
  Scene s = test::box_scene(3, 0.01, 0.1, 0.08, 0.06, "", 0.3, kAV);
  auto sim = make<3>(s, 0.5, 4);
  auto& p = sim->particles();
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Eigen::Vector3d x = p.x()[i], f = p.m()[i] * p.a()[i];
    l += x.cross(f);
    scale += x.norm() * f.norm();
  }
  EXPECT_LT(l.norm(), 1e-13 * scale);
}

TEST(SphEquations, UniformPressureGivesNoForceInTheInterior) {
  Scene s = test::box_scene(2, 0.01, 0.3, 0.3, 0, "", 0.0);
  Simulation<2> sim(s);
  sim.add_module(std::make_unique<SphEquations<2>>(sim));
  sim.create_particles();
  for (auto& r : sim.particles().rho()) r = 1010.0;  // p = K * 0.01 everywhere
  sim.init();
  auto& p = sim.particles();
  const double pr = p.p()[0], h = sim.kernel().h();
  ASSERT_GT(pr, 0);
  int interior = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& x = p.x()[i];
    if (x.minCoeff() < 3 * h || x.maxCoeff() > 0.3 - 3 * h) continue;
    ++interior;
    // Scale: pressure / (rho h), the size of one pair contribution.
    EXPECT_LT(p.a()[i].norm(), 1e-10 * pr / (1010.0 * h));
  }
  EXPECT_GT(interior, 100);
}

TEST(SphEquations, ResultsDoNotDependOnThreadCount) {
  Scene s = test::box_scene(2, 0.01, 0.3, 0.2, 0, "x, y", 0.25, kAV);
  test::expect_thread_independent<2>([&] { return make<2>(s, 1.0, 9); }, 100);
}
