// Hourglass control (MMB Eq. 28-34): zero for affine motion, restoring, conserving.
#include <gtest/gtest.h>

#include <random>

#include "core/sph_equations.hpp"
#include "scene_helpers.hpp"
#include "solid/solid_module.hpp"

using namespace monosph;

namespace {

template <int D>
Scene solid_scene(double jitter) {
  return test::solid_block_scene(D, D == 2 ? "[0.16, 0.12]" : "[0.1, 0.08, 0.07]", jitter, 5,
                                 "hourglass: {xi: 1.0, zeta: 10, chi: 0.5}");
}

template <int D>
struct Rig {
  std::unique_ptr<Simulation<D>> sim;
  SolidModule<D>* solid;
  explicit Rig(double jitter) {
    sim = std::make_unique<Simulation<D>>(solid_scene<D>(jitter));
    sim->add_module(std::make_unique<SphEquations<D>>(*sim, true));
    auto s = std::make_unique<SolidModule<D>>(*sim);
    solid = s.get();
    sim->add_module(std::move(s));
    sim->create_particles();
    sim->init();
  }
  // Places every particle at x = A X0 + c, velocities (B X0), recomputes forces.
  void affine(const Mat<D>& A, const Vec<D>& c, const Mat<D>& B, bool rebuild) {
    auto& p = sim->particles();
    auto X0 = p.template view<Vec<D>>("initial_position");
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.x()[i] = A * X0[i] + c;
      p.v()[i] = B * X0[i];
    }
    if (rebuild) sim->rebuild_neighbours();
    sim->update_pair_cache();
    for (auto& m : sim->modules()) m->sums(*sim);
    for (auto& m : sim->modules()) m->constitutive(*sim);
    for (auto& a : p.a()) a.setZero();
    solid->forces(*sim);  // hourglass forces only
  }
};

template <int D>
Mat<D> random_matrix(std::mt19937& rng, double amp) {
  std::uniform_real_distribution<double> u(-amp, amp);
  Mat<D> m = Mat<D>::Identity();
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) m(r, c) += u(rng);
  return m;
}

template <int D>
void affine_motion_gives_no_force() {
  Rig<D> rig(0.3);
  std::mt19937 rng(17);
  auto& p = rig.sim->particles();
  Vec<D> c = Vec<D>::Constant(0.01);
  for (int update = 0; update < 4; ++update) {
    const Mat<D> A = random_matrix<D>(rng, 0.2);
    const Mat<D> B = random_matrix<D>(rng, 1.0);
    // A rotation by 30 degrees on top of the stretch.
    Mat<D> R = Mat<D>::Identity();
    R(0, 0) = R(1, 1) = std::cos(0.5);
    R(0, 1) = -std::sin(0.5), R(1, 0) = std::sin(0.5);
    const Mat<D> F = R * A;
    rig.affine(F, c, B, update > 0);
    rig.sim->diagnostics();
    auto Fd = p.template view<Mat<D>>("deformation_gradient");
    auto dis = p.template view<double>("disorder");
    double fmax = 0, ferr = 0, dmax = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      fmax = std::max(fmax, (p.m()[i] * p.a()[i]).norm());
      ferr = std::max(ferr, (Mat<D>(Fd[i]) - F).cwiseAbs().maxCoeff());
      dmax = std::max(dmax, dis[i]);
    }
    EXPECT_LT(ferr, 1e-12) << "F after " << update << " reference updates";
    EXPECT_LT(dmax, 1e-10);
    // Force scale: E dp (one stiffness-force unit per unit depth).
    EXPECT_LT(fmax, 1e-9 * 2e11 * 0.01) << D << "D after " << update << " updates";
  }
}

}  // namespace

TEST(Hourglass, AffineMotionGivesNoForce2D) {
  affine_motion_gives_no_force<2>();
}
TEST(Hourglass, AffineMotionGivesNoForce3D) {
  affine_motion_gives_no_force<3>();
}

TEST(Hourglass, PerturbedParticleIsPushedBackAndMomentumIsConserved) {
  Rig<2> rig(0.0);
  auto& p = rig.sim->particles();
  // The particle nearest the centre moves by 0.1 dp.
  std::size_t c = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if ((p.x()[i] - Vec<2>(0.08, 0.06)).norm() < (p.x()[c] - Vec<2>(0.08, 0.06)).norm()) c = i;
  const Vec<2> du(0.001, 0.0004);
  p.x()[c] += du;
  rig.sim->update_pair_cache();
  for (auto& m : rig.sim->modules()) m->sums(*rig.sim);
  for (auto& a : p.a()) a.setZero();
  // Velocities that push the particle further off, so the viscous part acts too.
  p.v()[c] = Vec<2>(1.0, 0.4);
  rig.solid->forces(*rig.sim);
  const Vec<2> f = p.m()[c] * p.a()[c];
  EXPECT_LT(f.dot(du), 0) << "hourglass force must restore";
  Vec<2> sum = Vec<2>::Zero();
  double torque = 0, scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec<2> fi = p.m()[i] * p.a()[i];
    sum += fi;
    torque += p.x()[i][0] * fi[1] - p.x()[i][1] * fi[0];
    scale += fi.norm();
  }
  EXPECT_LT(sum.norm(), 1e-12 * scale);
  EXPECT_LT(std::abs(torque), 1e-12 * scale);
}

// The force pass against MMB Eq. 31-34 written out pair by pair (the textbook form: a branch on
// the viscous condition, a division per denominator), on a jittered 3D block with random
// velocities, so that the viscous part acts on some pairs and not on others.
TEST(Hourglass, ForceEqualsEquations31To34PairByPair3D) {
  Rig<3> rig(0.3);
  auto& sim = *rig.sim;
  auto& p = sim.particles();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Mat<3> A = random_matrix<3>(rng, 0.05);
  auto X0 = p.template view<Vec<3>>("initial_position");
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.x()[i] = A * X0[i] + 0.0005 * Vec<3>(u(rng), u(rng), u(rng));  // and a non-affine part
    p.v()[i] = Vec<3>(u(rng), u(rng), u(rng));
  }
  sim.rebuild_neighbours();  // re-sorts the particles: views are taken anew below
  X0 = p.template view<Vec<3>>("initial_position");
  for (auto& m : sim.modules()) m->sums(sim);
  for (auto& a : p.a()) a.setZero();
  rig.solid->forces(sim);
  const auto& pl = sim.pairs();
  const auto& vol = sim.volumes();
  auto F = p.template view<Mat<3>>("deformation_gradient");
  const Material& mat = sim.materials()[0];
  const double K = mat.bulk_modulus, G = mat.shear_modulus, E = 9 * K * G / (3 * K + G);
  const double xi = 1.0, zeta = 10, chi = 0.5, h = sim.kernel().h(), eta2 = 0.01 * h * h;
  double err = 0, scale = 0;
  int viscous = 0, not_viscous = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec<3> f = Vec<3>::Zero();
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      const Vec<3> d = -pl.r(p.x(), i, k);
      const Vec<3> X = X0[j] - X0[i];
      const Vec<3> eps = 0.5 * (Mat<3>(F[i]) + Mat<3>(F[j])) * X - d;  // Eq. 31
      const double r2 = d.squaredNorm(), X2 = X.squaredNorm(), ed = eps.dot(d);
      // Eq. 32 (weight 1 - chi, Eq. 34)
      f += -xi * (1 - chi) * vol[i] * vol[j] * pl.w[k] * E * ed / (X2 * r2) * d;
      const double vr = (p.v()[j] - p.v()[i]).dot(d);
      if (vr * ed < 0) {  // Eq. 33 (weight chi)
        const double rbar = 0.5 * (p.rho()[i] + p.rho()[j]);
        f += -zeta * chi * p.m()[i] * mat.sound_speed() * h * p.m()[j] / rbar *
             (eps.norm() / X.norm()) * vr / (r2 + eta2) * pl.f[k] * d;
        ++viscous;
      } else {
        ++not_viscous;
      }
    }
    err = std::max(err, (f - p.m()[i] * p.a()[i]).norm());
    scale = std::max(scale, f.norm());
  }
  EXPECT_GT(viscous, 100);
  EXPECT_GT(not_viscous, 100);
  EXPECT_GT(scale, 0);
  EXPECT_LT(err, 1e-12 * scale);
}
