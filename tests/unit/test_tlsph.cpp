// Total-Lagrangian SPH (Ganzenmueller 2015, "G15"): exact F for affine maps (Eq. 17), objectivity,
// interior equilibrium under uniform stretch, linear momentum (Eq. 24), hourglass force (Eq. 32).
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <random>

#include "core/sph_equations.hpp"
#include "scene_helpers.hpp"
#include "solid/solid_module.hpp"

using namespace monosph;

namespace {

// Steel block (dp = 0.01) in the domain [-1, 1]^D, total-Lagrangian, hourglass alpha.
Scene tl_scene(int dim, double alpha, bool neo_hookean, double jitter) {
  const std::string lo = dim == 2 ? "[0, 0]" : "[0, 0, 0]";
  const std::string hi = dim == 2 ? "[0.16, 0.12]" : "[0.1, 0.08, 0.07]";
  std::string text =
      fmt::format(R"(
name: tl
dimension: {0}
dp: 0.01
domain: {{min: {1}, max: {2}}}
materials:
  steel: {{density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9, elasticity: {3}}}
bodies:
  - name: block
    phase: solid
    material: steel
    formulation: total_lagrangian
    shape: {{box: {{min: {4}, max: {5}}}}}
    jitter: {6}
    seed: 5
    hourglass: {{alpha: {7}}}
end_time: 1
)",
                  dim, dim == 2 ? "[-1, -1]" : "[-1, -1, -1]", dim == 2 ? "[1, 1]" : "[1, 1, 1]",
                  neo_hookean ? "neo_hookean" : "hypoelastic", lo, hi, jitter, alpha);
  return load_scene_text(text);
}

constexpr double kE = 9 * 160e9 * 80e9 / (3 * 160e9 + 80e9);  // Young's modulus of the steel

template <int D>
struct Rig {
  std::unique_ptr<Simulation<D>> sim;
  SolidModule<D>* solid;
  Rig(double alpha, bool neo, double jitter) {
    sim = std::make_unique<Simulation<D>>(tl_scene(D, alpha, neo, jitter));
    sim->add_module(std::make_unique<SphEquations<D>>(*sim, true));
    auto s = std::make_unique<SolidModule<D>>(*sim);
    solid = s.get();
    sim->add_module(std::move(s));
    sim->create_particles();
    sim->init();
  }
  std::span<Vec<D>> X0() { return sim->particles().template view<Vec<D>>("initial_position"); }
  // x = phi(X0), v = psi(X0); then sums, rates (which read the F of the sums, as after a step's
  // force pass), constitutive and the solid forces alone (no body force): returns the largest
  // |m a|.
  double place(const std::function<Vec<D>(const Vec<D>&)>& phi,
               const std::function<Vec<D>(const Vec<D>&)>& psi) {
    auto& p = sim->particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec<D> X = X0()[i];
      p.x()[i] = phi(X);
      p.v()[i] = psi(X);
    }
    sim->rebuild_neighbours();  // also re-sorts particles: the reference data must follow
    for (auto& m : sim->modules()) m->sums(*sim);
    for (auto& m : sim->modules()) m->rates(*sim);
    for (auto& m : sim->modules()) m->constitutive(*sim);
    for (auto& a : p.a()) a.setZero();
    solid->forces(*sim);
    double fmax = 0;
    for (std::size_t i = 0; i < p.size(); ++i) fmax = std::max(fmax, (p.m()[i] * p.a()[i]).norm());
    return fmax;
  }
  Vec<D> force(std::size_t i) { return sim->particles().m()[i] * sim->particles().a()[i]; }
  // Force unit: E dp^(D-1), the force of a stress E on one particle face.
  static double unit() { return kE * std::pow(0.01, D - 1); }
};

template <int D>
Mat<D> rotation(double angle) {
  Mat<D> R = Mat<D>::Identity();
  R(0, 0) = R(1, 1) = std::cos(angle);
  R(0, 1) = -std::sin(angle), R(1, 0) = std::sin(angle);
  if constexpr (D == 3) {  // and about x
    Mat<D> Q = Mat<D>::Identity();
    Q(1, 1) = Q(2, 2) = std::cos(0.3);
    Q(1, 2) = -std::sin(0.3), Q(2, 1) = std::sin(0.3);
    R = Q * R;
  }
  return R;
}

template <int D>
void deformation_gradient_is_exact_for_affine_maps() {
  Rig<D> rig(1.0, false, 0.3);  // irregular reference lattice
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int trial = 0; trial < 3; ++trial) {
    Mat<D> A = Mat<D>::Identity(), B;
    Vec<D> c;
    for (int r = 0; r < D; ++r) {
      c[r] = u(rng);
      for (int k = 0; k < D; ++k) A(r, k) += u(rng), B(r, k) = 5 * u(rng);
    }
    rig.place([&](const Vec<D>& X) { return Vec<D>(A * X + c); },
              [&](const Vec<D>& X) { return Vec<D>(B * X); });
    auto& p = rig.sim->particles();
    auto F = p.template view<Mat<D>>("deformation_gradient");
    auto L = p.template view<Mat<D>>("velocity_gradient");
    const Mat<D> Lx = B * A.inverse();  // v = B X = B A^-1 (x - c)
    double ferr = 0, lerr = 0, rerr = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {  // every particle, surface and corners included
      ferr = std::max(ferr, (Mat<D>(F[i]) - A).cwiseAbs().maxCoeff());
      lerr = std::max(lerr, (Mat<D>(L[i]) - Lx).cwiseAbs().maxCoeff() / Lx.cwiseAbs().maxCoeff());
      const double rho0 = p.m()[i] / p.template view<double>("reference_volume")[i];
      rerr = std::max(rerr, std::abs(p.rho()[i] * A.determinant() / rho0 - 1));
      EXPECT_GT(rig.solid->total_lagrangian()->reference_neighbours(i),
                std::size_t(D == 2 ? 5 : 8));
    }
    EXPECT_LT(ferr, 1e-12) << D << "D trial " << trial;
    EXPECT_LT(lerr, 1e-12);
    EXPECT_LT(rerr, 1e-12);  // rho = rho0 / det F
  }
}

TEST(Tlsph, DeformationGradientIsExactForAffineMaps2D) {
  deformation_gradient_is_exact_for_affine_maps<2>();
}
TEST(Tlsph, DeformationGradientIsExactForAffineMaps3D) {
  deformation_gradient_is_exact_for_affine_maps<3>();
}

template <int D>
void rigid_motion_gives_no_force(bool neo) {
  Rig<D> rig(1.0, neo, 0.3);
  const Mat<D> R = rotation<D>(0.7);
  const Vec<D> c = Vec<D>::Constant(0.05);
  const double fmax = rig.place([&](const Vec<D>& X) { return Vec<D>(R * X + c); },
                                [&](const Vec<D>&) { return Vec<D>::Zero(); });
  EXPECT_LT(fmax, 1e-10 * Rig<D>::unit()) << D << "D neo_hookean " << neo;
  // The same body stretched by 1 % does feel forces of order 1e-2 E dp^(D-1).
  Mat<D> A = Mat<D>::Identity();
  A(0, 0) = 1.01;
  const double fs = rig.place([&](const Vec<D>& X) { return Vec<D>(R * A * X + c); },
                              [&](const Vec<D>&) { return Vec<D>::Zero(); });
  EXPECT_GT(fs, 1e-3 * Rig<D>::unit());
}

TEST(Tlsph, RigidRotationAndTranslationGiveNoForce) {
  rigid_motion_gives_no_force<2>(false);
  rigid_motion_gives_no_force<2>(true);
  rigid_motion_gives_no_force<3>(false);
  rigid_motion_gives_no_force<3>(true);
}

template <int D>
void uniform_stretch_loads_only_the_boundary(bool neo) {
  Rig<D> rig(1.0, neo, 0.0);  // regular lattice: interior neighbourhoods are complete
  Mat<D> A = Mat<D>::Identity();
  A(0, 0) = 1.02, A(1, 1) = 0.99, A(0, 1) = 0.01;
  rig.place([&](const Vec<D>& X) { return Vec<D>(A * X); },
            [&](const Vec<D>&) { return Vec<D>::Zero(); });
  auto& p = rig.sim->particles();
  const double his[3] = {D == 2 ? 0.16 : 0.1, D == 2 ? 0.12 : 0.08, 0.07};
  const Vec<D> hi = Vec<D>::Map(his);
  // Two supports from the surface: f_i uses g_ji of the neighbours j (their support).
  const double depth = 2 * rig.sim->kernel().radius();
  double inner = 0, outer = 0;
  int ninner = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec<D> X = rig.X0()[i];
    double d = std::numeric_limits<double>::infinity();
    for (int a = 0; a < D; ++a) d = std::min({d, X[a], hi[a] - X[a]});
    const double f = rig.force(i).norm();
    if (d > depth)
      inner = std::max(inner, f), ++ninner;
    else
      outer = std::max(outer, f);
  }
  ASSERT_GT(ninner, 0) << "depth " << depth << " particles " << p.size();
  EXPECT_LT(inner, 1e-10 * Rig<D>::unit()) << D << "D neo_hookean " << neo;
  EXPECT_GT(outer, 1e-3 * Rig<D>::unit());
}

TEST(Tlsph, UniformStretchLoadsOnlyTheBoundary) {
  uniform_stretch_loads_only_the_boundary<2>(false);
  uniform_stretch_loads_only_the_boundary<2>(true);
}

template <int D>
void linear_momentum_is_conserved(bool neo) {
  Rig<D> rig(2.0, neo, 0.3);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  auto& p = rig.sim->particles();
  // Random deviatoric stress for the hypoelastic model (it is state, not a function of F).
  auto S = p.template view<Mat3>("deviatoric_stress");
  for (std::size_t i = 0; i < p.size(); ++i) {
    Mat3 s;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c <= r; ++c) s(r, c) = s(c, r) = 1e8 * u(rng);
    S[i] = s - s.trace() / 3 * Mat3::Identity();
  }
  rig.place(
      [&](const Vec<D>& X) {
        return Vec<D>(X + 0.002 * Vec<D>::NullaryExpr([&] { return u(rng); }));
      },
      [&](const Vec<D>&) { return Vec<D>(Vec<D>::NullaryExpr([&] { return u(rng); })); });
  Vec<D> sum = Vec<D>::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) sum += rig.force(i), scale += rig.force(i).norm();
  EXPECT_GT(scale, 1e-3 * Rig<D>::unit());
  EXPECT_LT(sum.norm(), 1e-13 * scale) << D << "D neo_hookean " << neo;
}

TEST(Tlsph, LinearMomentumIsConserved) {
  linear_momentum_is_conserved<2>(false);
  linear_momentum_is_conserved<2>(true);
  linear_momentum_is_conserved<3>(false);
  linear_momentum_is_conserved<3>(true);
}

// The hourglass force alone: forces with alpha minus forces with alpha = 0, same placement.
template <int D>
std::vector<Vec<D>> hourglass_forces(bool neo, double jitter,
                                     const std::function<Vec<D>(const Vec<D>&)>& phi) {
  Rig<D> with(5.0, neo, jitter), without(0.0, neo, jitter);
  auto zero = [](const Vec<D>&) { return Vec<D>::Zero(); };
  with.place(phi, zero);
  without.place(phi, zero);
  // Particles are re-sorted identically (same positions): compare by id.
  auto& p = with.sim->particles();
  auto& q = without.sim->particles();
  std::vector<Vec<D>> f(p.size(), Vec<D>::Zero());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.id()[i], q.id()[i]);
    f[i] = with.force(i) - without.force(i);
  }
  return f;
}

TEST(Tlsph, HourglassForceVanishesForAffineMotion) {
  Mat<2> A;
  A << 1.05, 0.1, -0.2, 0.9;
  auto f = hourglass_forces<2>(false, 0.3, [&](const Vec<2>& X) { return Vec<2>(A * X); });
  double fmax = 0;
  for (const auto& x : f) fmax = std::max(fmax, x.norm());
  EXPECT_LT(fmax, 1e-10 * Rig<2>::unit());
}

TEST(Tlsph, HourglassForceRestoresAZeroEnergyMode) {
  // Checkerboard displacement u = eps (-1)^(ix + iy) e_x on the regular lattice: the odd lattice
  // offsets cancel in sum_j (u_j - u_i) (x) g_ij, so F = I inside and the stress gives no force
  // (a zero-energy mode); the hourglass force opposes it.
  const double eps = 1e-4;
  auto mode = [&](const Vec<2>& X) {
    const long ix = std::lround(X[0] / 0.01 - 0.5), iy = std::lround(X[1] / 0.01 - 0.5);
    return Vec<2>(eps * ((ix + iy) % 2 == 0 ? 1.0 : -1.0), 0.0);
  };
  Rig<2> plain(0.0, false, 0.0);
  plain.place([&](const Vec<2>& X) { return Vec<2>(X + mode(X)); },
              [](const Vec<2>&) { return Vec<2>::Zero(); });
  auto& p = plain.sim->particles();
  auto F = p.template view<Mat<2>>("deformation_gradient");
  double inner = 0, ferr = 0;
  const double depth = 2 * plain.sim->kernel().radius();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec<2> X = plain.X0()[i];
    if (std::min({X[0], X[1], 0.16 - X[0], 0.12 - X[1]}) <= depth) continue;
    inner = std::max(inner, plain.force(i).norm());
    ferr = std::max(ferr, (Mat<2>(F[i]) - Mat<2>::Identity()).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(ferr, 1e-12);                    // invisible to F
  EXPECT_LT(inner, 1e-10 * Rig<2>::unit());  // no restoring stress
  auto f = hourglass_forces<2>(false, 0.0, [&](const Vec<2>& X) { return Vec<2>(X + mode(X)); });
  Rig<2> ref(0.0, false, 0.0);  // X0 in the same (sorted) order
  ref.place([&](const Vec<2>& X) { return Vec<2>(X + mode(X)); },
            [](const Vec<2>&) { return Vec<2>::Zero(); });
  double work = 0, fmax = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    work += f[i].dot(mode(ref.X0()[i]));
    fmax = std::max(fmax, f[i].norm());
  }
  EXPECT_GT(fmax, 1e-3 * eps / 0.01 * Rig<2>::unit());  // of order alpha E (u/dp) dp
  EXPECT_LT(work, 0);                                   // restoring
}

TEST(Tlsph, SceneKeysAreChecked) {
  auto bad = [](const std::string& extra_material, const std::string& extra_body) {
    std::string text = fmt::format(R"(
name: t
dimension: 2
dp: 0.01
domain: {{min: [-1, -1], max: [1, 1]}}
materials:
  m: {{density: 1000, bulk_modulus: 1e6, shear_modulus: 1e5{0}}}
bodies:
  - name: b
    phase: solid
    material: m
    shape: {{box: {{min: [0, 0], max: [0.1, 0.1]}}}}
    {1}
end_time: 1
)",
                                   extra_material, extra_body);
    try {
      load_scene_text(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(bad("", "formulation: total_lagrangian"), "");
  EXPECT_NE(bad("", "formulation: lagrangian"), "");
  EXPECT_NE(bad(", elasticity: neo_hookean", "formulation: eulerian"), "");
  EXPECT_NE(bad("", "formulation: total_lagrangian\n    artificial_stress: {epsilon: 0.3}"), "");
  EXPECT_NE(bad("", "formulation: total_lagrangian\n    hourglass: {alpha: 1, xi: 1}"), "");
  EXPECT_NE(bad("", "formulation: total_lagrangian\n    hourglass: {zeta: 1}"), "");
  EXPECT_EQ(bad(", elasticity: neo_hookean", "formulation: total_lagrangian"), "");
}

// No module reads the pair rows of a total-Lagrangian body (its forces use the reference pairs):
// a step leaves them empty; diagnostics (output, probes) see complete rows and the exact smallest
// distance.
TEST(Tlsph, StepsLeaveUnreadPairRowsEmptyButDiagnosticsSeeThemAll) {
  Rig<3> rig(1.0, false, 0.3);
  auto& sim = *rig.sim;
  auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i)  // moving and shearing: distances change
    p.v()[i] = Vec<3>(5000 * p.x()[i].z(), 0, -1000);
  for (int s = 0; s < 20; ++s) sim.advance();
  EXPECT_GT(sim.neighbours().builds(), 2);
  const auto& pl = sim.pairs();
  long filled = 0;
  for (std::size_t i = 0; i < p.size(); ++i) filled += pl.count[i];
  EXPECT_EQ(filled, 0);
  sim.diagnostics();
  for (std::size_t i = 0; i < p.size(); ++i) filled += pl.count[i];
  EXPECT_GT(filled, long(8 * p.size()));  // every particle has at least 8 neighbours
  double brute = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) brute = std::min(brute, (p.x()[i] - p.x()[j]).norm());
  EXPECT_EQ(sim.min_distance(), brute);
}

// The guard still sees unread rows: two total-Lagrangian blocks (no contact between them) flying
// into each other stop the run when two particles come closer than min_distance dp, although
// between rebuilds only the rows that could reach the limit are revisited.
TEST(Tlsph, BlocksFlyingIntoEachOtherTripTheGuard) {
  const Scene sc = load_scene_text(R"(
name: tl_meet
dimension: 2
dp: 0.01
domain: {min: [-1, -1], max: [1, 1]}
materials:
  steel: {density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9}
bodies:
  - {name: a, phase: solid, material: steel, formulation: total_lagrangian,
     shape: {box: {min: [0, 0], max: [0.1, 0.1]}}, initial: {velocity: ["200", "0"]}}
  - {name: b, phase: solid, material: steel, formulation: total_lagrangian,
     shape: {box: {min: [0.13, 0.005], max: [0.23, 0.105]}}, initial: {velocity: ["-200", "0"]}}
end_time: 1
)");
  Simulation<2> sim(sc);
  sim.add_module(std::make_unique<SphEquations<2>>(sim, true));
  sim.add_module(std::make_unique<SolidModule<2>>(sim));
  sim.create_particles();
  sim.init();
  auto closest = [&] {
    auto x = sim.particles().x();  // a rebuild re-sorts the particles
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) d = std::min(d, (x[i] - x[j]).norm());
    return d;
  };
  std::string msg;
  const double gap = 0.135 - 0.095;  // between the facing particle rows (centres)
  try {
    while (sim.time() < 2 * gap / 400) {
      sim.advance();
      // Every step that passes the guard has no pair closer than the limit.
      ASSERT_GE(closest(), 0.1 * sim.dp()) << "t = " << sim.time();
    }
  } catch (const RunAborted& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("dp apart (limit 0.1 dp)"), std::string::npos) << msg;
  EXPECT_GT(sim.time(), 0.5 * gap / 400);  // not before the rows met
  EXPECT_LT(closest(), 0.1 * sim.dp());
}

}  // namespace
