// Corrected gradient (MMB Eq. 7-9, 16) is exact for linear fields, also at free surfaces.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "core/sph_equations.hpp"
#include "scene_helpers.hpp"

using namespace monosph;

namespace {

template <int D>
void linear_field_exact(const std::string& periodic, double jitter) {
  Scene s = test::box_scene(D, 0.01, 0.2, 0.15, 0.12, periodic, jitter);
  Simulation<D> sim(s);
  auto* eq = new SphEquations<D>(sim, true);
  sim.add_module(std::unique_ptr<Module<D>>(eq));
  sim.create_particles();
  sim.init();
  auto& p = sim.particles();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  Mat<D> A;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) A(r, c) = u(rng);
  Vec<D> c0;
  for (int r = 0; r < D; ++r) c0[r] = u(rng);
  auto x = p.x();
  auto v = p.v();
  for (std::size_t i = 0; i < p.size(); ++i) v[i] = A * x[i] + c0;
  // Non-periodic velocity field: only meaningful without periodic axes.
  sim.particles();
  eq->rates(sim);
  auto g = p.template view<Mat<D>>("velocity_gradient");
  auto drho = p.drho();
  auto rho = p.rho();
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    worst = std::max(worst, (Mat<D>(g[i]) - A).cwiseAbs().maxCoeff());
    EXPECT_NEAR(drho[i], -rho[i] * A.trace(), 1e-9 * rho[i]);
  }
  EXPECT_LT(worst, 1e-10) << D << "D, jitter " << jitter;
}

}  // namespace

TEST(CorrectedGradient, LinearFieldExactOnRandomCloud2D) {
  linear_field_exact<2>("", 0.0);
  linear_field_exact<2>("", 0.3);
}

TEST(CorrectedGradient, LinearFieldExactOnRandomCloud3D) {
  linear_field_exact<3>("", 0.3);
}

TEST(CorrectedGradient, CorrectionIsIdentityOnPerfectPeriodicLattice) {
  Scene s = test::box_scene(2, 0.01, 0.2, 0.1, 0, "x, y", 0.0);
  Simulation<2> sim(s);
  sim.add_module(std::make_unique<SphEquations<2>>(sim));
  sim.create_particles();
  sim.init();
  auto L = sim.particles().view<Mat<2>>("correction");
  auto shep = sim.particles().view<double>("shepard");
  for (std::size_t i = 0; i < L.size(); ++i) {
    // On a periodic lattice every particle sees the same neighbourhood: L is the same isotropic
    // matrix everywhere, within the kernel's discretisation error of I (1.5 % at h = 1.3 dp).
    EXPECT_LT((Mat<2>(L[i]) - Mat<2>(L[0])).norm(), 1e-12);
    EXPECT_LT(std::abs(L[i](0, 1)), 1e-12);
    EXPECT_NEAR(L[i](0, 0), L[i](1, 1), 1e-12);
    EXPECT_LT((Mat<2>(L[i]) - Mat<2>::Identity()).norm(), 0.02);
    EXPECT_NEAR(shep[i], 1.0, 1e-3);
  }
}
