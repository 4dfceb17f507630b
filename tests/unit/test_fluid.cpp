// delta-plus SPH fluid and Adami walls (src/fluid): exactness, conservation, wall extrapolation,
// shifting and free-surface detection.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "assemble.hpp"
#include "scene/scene_reader.hpp"
#include "thread_helpers.hpp"

using namespace monosph;

namespace {

// A fluid block [0, 0.3] x [0, h] over a 3-layer wall floor (and side walls when `box`); periodic
// along x when not `box`. `fluid` and `top` add body keys and scene keys.
Scene tank(bool box, double height, const std::string& fluid, const std::string& top,
           double jitter = 0.0) {
  const std::string walls = box ? "difference: [{box: {min: [-0.03, -0.03], max: [0.33, 0.4]}}, "
                                  "{box: {min: [0, 0], max: [0.3, 0.4]}}]"
                                : "box: {min: [0, -0.03], max: [0.3, 0]}";
  const std::string dom = box ? "{min: [-0.03, -0.03], max: [0.33, 0.4]}"
                              : "{min: [0, -0.03], max: [0.3, 0.4], periodic: [x]}";
  return load_scene_text(fmt::format(R"(
name: tank
dimension: 2
dp: 0.01
domain: {0}
materials:
  water: {{density: 1000, sound_speed: 20, viscosity: 0.5}}
bodies:
  - name: water
    phase: fluid
    material: water
    shape: {{box: {{min: [0, 0], max: [0.3, {1}]}}}}
    jitter: {4}
    seed: 3
{2}
  - name: floor
    phase: wall
    material: water
    shape: {{{3}}}
end_time: 1
{5}
)",
                                     dom, height, fluid, walls, jitter, top));
}

template <int D>
std::unique_ptr<Simulation<D>> build(const Scene& s) {
  auto sim = std::make_unique<Simulation<D>>(s);
  assemble_modules(*sim);
  sim->create_particles();
  return sim;
}

}  // namespace

TEST(Fluid, FluidOnlySceneCarriesNoSolidFields) {
  auto sim = build<2>(tank(false, 0.2, "", ""));
  EXPECT_FALSE(sim->particles().has("correction"));
  EXPECT_FALSE(sim->particles().has("shepard"));
  EXPECT_TRUE(sim->particles().has("wall_pressure"));
}

TEST(Fluid, PairForcesWithWallsConserveMomentum) {
  // Random velocities and densities, no gravity: the sum of fluid forces and the reactions on the
  // wall particles vanishes (pressure and no-slip viscosity, each pair exactly opposite).
  auto sim = build<2>(
      tank(true, 0.2, "    artificial_viscosity: {alpha: 0.1}\n    shifting: {speed: 1}", "", 0.2));
  auto& p = sim->particles();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) {
      p.v()[i] = Vec<2>(u(rng), u(rng));
      p.rho()[i] *= 1 + 0.01 * u(rng);
    } else {
      p.v()[i] = Vec<2>(0.3, 0.0);  // a moving wall: no-slip term active
    }
  sim->init();
  Vec<2> f = Vec<2>::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec<2> fi =
        p.phase()[i] == kFluid ? Vec<2>(p.m()[i] * p.a()[i]) : p.view<Vec<2>>("fluid_force")[i];
    f += fi;
    scale += fi.norm();
  }
  EXPECT_GT(scale, 0);
  EXPECT_LT(f.norm(), 1e-13 * scale);
}

TEST(Fluid, DensityDiffusionVanishesForALinearDensityAndConservesMass) {
  // Periodic column, v = 0: only the delta term acts. Linear rho(y): zero to round-off with the
  // renormalised gradient (Antuono et al. 2012) -- at the free surface too. Random rho: the term
  // only redistributes, sum_i V_i drho_i = 0.
  Scene s = tank(false, 0.2, "    density_diffusion: {delta: 0.1}", "", 0.15);
  auto sim = build<2>(s);
  auto& p = sim->particles();
  sim->init();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) p.rho()[i] = 1000.0 + 300.0 * p.x()[i][1];
  sim->update_pair_cache();
  for (auto& m : sim->modules()) m->sums(*sim);
  for (auto& m : sim->modules()) m->rates(*sim);
  const double scale = 0.1 * 20.0 * 300.0;  // delta c0 |grad rho|: the size of the term
  double worst = 0;
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) worst = std::max(worst, std::abs(p.drho()[i])), ++n;
  EXPECT_GT(n, 500);
  EXPECT_LT(worst, 1e-9 * scale);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) p.rho()[i] = 1000.0 * (1 + 0.01 * u(rng));
  sim->update_pair_cache();
  for (auto& m : sim->modules()) m->sums(*sim);
  for (auto& m : sim->modules()) m->rates(*sim);
  double sum = 0, abs_sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) {
      const double vi = p.m()[i] / p.rho()[i];
      sum += vi * p.drho()[i], abs_sum += std::abs(vi * p.drho()[i]);
    }
  EXPECT_GT(abs_sum, 0);
  EXPECT_LT(std::abs(sum), 1e-12 * abs_sum);
}

TEST(Fluid, AdamiWallPressureIsExactForHydrostatics) {
  // Fluid with p = rho0 g (H - y) (rho = rho0 exactly in the extrapolation sums) over a floor at
  // rest: p_w = rho0 g (H - y_w) at every wall particle with fluid neighbours (Adami Eq. 27).
  // Checks the sign of the g . r_wf term (p_w > p of the fluid above it).
  Scene s = tank(false, 0.2, "", "body_force: [0, -9.81]");
  auto sim = build<2>(s);
  auto& p = sim->particles();
  sim->init();
  // rho from the inverse EOS, so that the EOS pass gives p = rho0 g (H - y) exactly (c0^2 = 400).
  const double H = 0.2, g = 9.81, rho0 = 1000;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) p.rho()[i] = rho0 + rho0 * g * (H - p.x()[i][1]) / 400.0;
  sim->update_pair_cache();
  for (auto& m : sim->modules()) m->sums(*sim);
  auto pw = p.view<double>("wall_pressure");
  int walls = 0;
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.phase()[i] != kWall || p.x()[i][1] < -0.02) continue;  // fluid within 2h = 0.026
    const double exact = rho0 * g * (H - p.x()[i][1]);
    worst = std::max(worst, std::abs(pw[i] - exact) / (rho0 * g * H));
    EXPECT_GT(pw[i], rho0 * g * (H - 0.005));  // above the lowest fluid row's pressure
    ++walls;
  }
  EXPECT_GT(walls, 30);
  // rho_f varies by p / c0^2 = 0.5 %: the g-term carries that variation (about 0.5 % of the
  // layer's g dp rho term), far below 1e-3 of rho0 g H.
  EXPECT_LT(worst, 1e-3);
}

TEST(Fluid, ShiftingVanishesOnALatticeAndPullsADisplacedParticleBack) {
  Scene s = load_scene_text(R"(
name: lattice
dimension: 2
dp: 0.01
domain: {min: [0, 0], max: [0.2, 0.2], periodic: [x, y]}
materials:
  water: {density: 1000, sound_speed: 20}
bodies:
  - {name: water, phase: fluid, material: water, shape: {box: {min: [0, 0], max: [0.2, 0.2]}},
     shifting: {speed: 1}}
end_time: 1
)");
  auto sim = build<2>(s);
  auto& p = sim->particles();
  sim->init();
  auto sh = p.view<Vec<2>>("shift_rate");
  auto lam = p.view<double>("free_surface");
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LT(sh[i].norm(), 1e-12) << i;
    EXPECT_NEAR(lam[i], 1.0, 0.02) << i;
  }
  // Displace one particle by 0.2 dp: its shift points back to its lattice site.
  std::size_t k = p.size() / 2 + 7;
  const auto id = p.id()[k];
  const Vec<2> site = p.x()[k];
  p.x()[k] += Vec<2>(0.002, 0.001);
  sim->init();  // the rebuild reorders the particles: find it again
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id()[i] == id) k = i;
  sh = p.view<Vec<2>>("shift_rate");  // fields were permuted: fresh view
  const Vec<2> back = site - p.x()[k];
  EXPECT_GT(sh[k].dot(back), 0.9 * sh[k].norm() * back.norm());
}

TEST(Fluid, NoShiftAcrossAFreeSurface) {
  // A periodic layer with a free top: lambda is low at the top rows, and the shift of every
  // particle there has no component along the surface normal (y).
  auto sim = build<2>(tank(false, 0.2, "    shifting: {speed: 1}", "", 0.1));
  auto& p = sim->particles();
  sim->init();
  auto sh = p.view<Vec<2>>("shift_rate");
  auto lam = p.view<double>("free_surface");
  int surface = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.phase()[i] != kFluid) continue;
    const double y = p.x()[i][1];
    if (y > 0.2 - 0.01) {
      EXPECT_LT(lam[i], 0.75) << i;
      ++surface;
    }
    if (y < 0.12 && y > 0.05) {  // interior, and above the floor
      EXPECT_GT(lam[i], 0.75) << i;
    }
    if (lam[i] < 0.75) {
      EXPECT_LT(std::abs(sh[i][1]), 0.35 * sh[i].norm() + 1e-14) << i;
    }
  }
  EXPECT_GT(surface, 20);
}

TEST(Fluid, ResultsDoNotDependOnThreadCount) {
  // Fluid with diffusion, viscosity and shifting in a tank of no-slip walls, under gravity.
  Scene s = tank(true, 0.2,
                 "    density_diffusion: {delta: 0.1}\n    artificial_viscosity: {alpha: 0.05}\n"
                 "    shifting: {speed: 1}",
                 "body_force: [0, -9.81]", 0.2);
  test::expect_thread_independent<2>(
      [&] {
        auto sim = build<2>(s);
        sim->init();
        return sim;
      },
      100);
}

TEST(Fluid, CouetteFlowBetweenAFixedAndAMovingNoSlipWall) {
  // Periodic channel H = 1, nu = 1, top wall moving at U = 1 (Adami no-slip with the wall's own
  // velocity): after t = 1 (the slowest mode decays as exp(-pi^2 nu t / H^2) = 5e-5) the profile
  // is u = U y / H.
  Scene s = load_scene_text(R"(
name: couette
dimension: 2
dp: 0.05
domain: {min: [0, -0.15], max: [0.5, 1.15], periodic: [x]}
materials:
  fluid: {density: 1, sound_speed: 10, viscosity: 1}
bodies:
  - {name: fluid, phase: fluid, material: fluid, shape: {box: {min: [0, 0], max: [0.5, 1]}},
     density_diffusion: {delta: 0.1}}
  - {name: bottom, phase: wall, material: fluid, shape: {box: {min: [0, -0.15], max: [0.5, 0]}}}
  - {name: top, phase: wall, material: fluid, shape: {box: {min: [0, 1], max: [0.5, 1.15]}},
     initial: {velocity: ["1", "0"]}}
end_time: 1
)");
  auto sim = build<2>(s);
  sim->init();
  while (sim->time() < 1.0) sim->advance(1.0);
  auto& p = sim->particles();
  double err2 = 0, ref2 = 0, vy = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.phase()[i] == kWall) {
      EXPECT_EQ(p.v()[i][0], p.x()[i][1] > 0.5 ? 1.0 : 0.0);  // walls keep their velocity
      continue;
    }
    const double u = p.x()[i][1];
    err2 += std::pow(p.v()[i][0] - u, 2), ref2 += u * u;
    vy = std::max(vy, std::abs(p.v()[i][1]));
  }
  EXPECT_LT(std::sqrt(err2 / ref2), 0.02);
  EXPECT_LT(vy, 0.01);
}

TEST(Fluid, CentralViscousFormIsStableAtItsTimeStep) {
  // Random velocities in a periodic box (Wendland C2, h = 1.3 dp), viscosity-limited steps: the
  // kinetic energy falls at every step with either viscous form. The central form 2 (d + 2) nu
  // pi_ij (nu lap v + 2 nu grad div v) has a largest lattice eigenvalue 10.1 nu/dp^2 against
  // Morris's 3.66, so its step is a third of Morris's 0.125 h^2/nu; at 0.125 h^2/nu (dt lambda =
  // 2.14) the central form's shortest modes grew by 14 % a step.
  for (const char* form : {"central", "morris"}) {
    Scene s = load_scene_text(fmt::format(R"(
name: noise
dimension: 2
dp: 0.01
kernel: {{type: wendland_c2, h_factor: 1.3}}
domain: {{min: [0, 0], max: [0.2, 0.2], periodic: [x, y]}}
materials:
  oil: {{density: 1000, sound_speed: 1, viscosity: 1000}}
bodies:
  - {{name: oil, phase: fluid, material: oil, shape: {{box: {{min: [0, 0], max: [0.2, 0.2]}}}},
     viscous_form: {0}}}
end_time: 1
)",
                                          form));
    auto sim = build<2>(s);
    auto& p = sim->particles();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1e-3, 1e-3);
    for (std::size_t i = 0; i < p.size(); ++i) p.v()[i] = Vec<2>(u(rng), u(rng));
    sim->init();
    auto energy = [&] {
      double e = 0;
      for (std::size_t i = 0; i < p.size(); ++i) e += 0.5 * p.m()[i] * p.v()[i].squaredNorm();
      return e;
    };
    const double nu = 1.0, h = 0.013, expect = 0.125 * h * h / nu / (form[0] == 'c' ? 3 : 1);
    EXPECT_NEAR(sim->dt(), expect, 1e-9 * expect) << form;
    double e = energy();
    const double e0 = e;
    for (int k = 0; k < 300; ++k) {
      sim->advance(1.0);
      const double en = energy();
      ASSERT_LT(en, e) << form << " step " << k;
      e = en;
    }
    EXPECT_LT(e, 1e-3 * e0) << form;  // the noise is damped, not just held
  }
}

namespace {

// Plane Couette flow started from rest: channel H = 1 (20 dp), period 1, nu = 0.1, c0 = 10, top
// wall at U = 1 (Re = U H / nu = 10), fluid lattice jittered by 0.05 dp, no shifting. Runs
// `shear_times` shear times H / U and returns the smallest pair distance seen (in dp).
double couette_min_distance(const std::string& kernel, double pb, double shear_times) {
  Scene s = load_scene_text(fmt::format(R"(
name: couette
dimension: 2
dp: 0.05
kernel: {{type: {0}, h_factor: 1.3}}
domain: {{min: [0, -0.2], max: [1, 1.2], periodic: [x]}}
materials:
  fluid: {{density: 1, sound_speed: 10, viscosity: 0.1, background_pressure: {1}}}
  wall: {{density: 1, sound_speed: 10}}
bodies:
  - {{name: fluid, phase: fluid, material: fluid, shape: {{box: {{min: [0, 0], max: [1, 1]}}}},
     density_diffusion: {{delta: 0.1}}, jitter: 0.05, seed: 4}}
  - {{name: bottom, phase: wall, material: wall, shape: {{box: {{min: [0, -0.2], max: [1, 0]}}}}}}
  - {{name: top, phase: wall, material: wall, shape: {{box: {{min: [0, 1], max: [1, 1.2]}}}},
     initial: {{velocity: ["1", "0"]}}}}
end_time: {2}
)",
                                        kernel, pb, shear_times));
  auto sim = build<2>(s);
  sim->init();
  double worst = 1;
  while (sim->time() < shear_times) {
    sim->advance(shear_times);
    worst = std::min(worst, sim->min_distance() / sim->dp());
  }
  return worst;
}

}  // namespace

TEST(Fluid, ShearedFluidWithBackgroundPressureStaysOrderedWithoutShifting) {
  // Issue 24: without shifting, sheared particles that start off the lattice pair up (cubic
  // spline, no background pressure: 0.29 dp after 10 shear times, 0.18 dp after 20; measured).
  // Nothing resists it: the continuity density does not see particles that close in along one
  // direction and open along another. A background pressure of 0.3 rho0 c0^2 with the Wendland
  // C2 kernel (no pairing instability under positive pressure, Dehnen & Aly 2012) pushes them
  // back: over 20 shear times the pairs never come closer than the jitter made them (0.90 dp)
  // and the lattice re-forms (measured 0.997 dp at the end). With the cubic spline a background
  // pressure helps less (pairing instability: 0.33 dp after 20 shear times at 0.3 rho0 c0^2).
  const double before = couette_min_distance("cubic_spline", 0, 20);
  const double after = couette_min_distance("wendland_c2", 30, 20);
  std::printf("min distance / dp over 20 shear times: %.3f before, %.3f after\n", before, after);
  EXPECT_LT(before, 0.4);
  EXPECT_GT(after, 0.85);
}
