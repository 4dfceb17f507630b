// The tool-chip friction of orthogonal cutting (issue 52): tau = min(mu sigma_n, tau_max) on a
// rigid surface (surface key friction_limit), the friction work turned into heat with the share
// beta (heat_partition) going to the surface, mass scaling (material key mass_scaling), the
// probes chip_ratio (layer and flow) and kinetic_share and the measures std and harmonic_mean.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "assemble.hpp"
#include "output/probes.hpp"
#include "rigid/rigid_surface_module.hpp"
#include "rigid/surface.hpp"
#include "scene/scene.hpp"

using namespace monosph;

namespace {

// Assembles and starts `sim`; its rigid-surface module (nullptr if the scene has none).
RigidSurfaceModule<2>* start(Simulation<2>& sim) {
  assemble_modules(sim);
  sim.create_particles();
  sim.init();
  for (auto& m : sim.modules())
    if (auto* r = dynamic_cast<RigidSurfaceModule<2>*>(m.get())) return r;
  return nullptr;
}

// One particle (dp = 1 mm) of a material with heat capacity pressed by gravity onto a plate
// moving along x at 0.2 m/s; `surface_keys` adds keys to the plate.
Scene slider(const std::string& surface_keys, const std::string& material_keys = "") {
  return load_scene_text(fmt::format(R"(
name: slider
dimension: 2
dp: 0.001
domain: {{min: [-0.05, -0.02], max: [0.2, 0.05]}}
materials:
  m: {{density: 4000, bulk_modulus: 1.0e8, shear_modulus: 3.0e7, heat_capacity: 500{}}}
bodies:
  - {{name: p, phase: solid, material: m, shape: {{box: {{min: [0, 0], max: [0.001, 0.001]}}}}}}
surfaces:
  - {{name: plate, segment: [[-0.04, 0], [0.19, 0]], velocity: [0.2, 0], friction: 0.5{}}}
body_force: [0, -2000]
end_time: 1
)",
                                     material_keys, surface_keys));
}

}  // namespace

TEST(CuttingFriction, LimitingShearStressCapsCoulombFriction) {
  // Zorev's law per particle: |F_t| = mu F_n while mu F_n < tau_max dp^(D-1) (sliding), then
  // tau_max dp^(D-1) (sticking); the friction power is |F_t| |v_t|.
  const double R = 5e-6, e_star = 1.2e11, mu_f = 0.2, m = 1e-4, dt = 1e-8, depth = 2 * R;
  const double cap = 576e6 * (2 * R);  // tau_max dp in 2D (N per metre of depth)
  const Vec<2> c(0, 0), nrm(0, 1), vs(-0.5, 0), v(0.3, 0);
  int sliding = 0, sticking = 0;
  for (double overlap = 1e-9; overlap < R; overlap *= 1.5) {
    double fn, power;
    const Vec<2> f = contact_force<2>(Vec<2>(0, R - overlap), v, m, c, nrm, vs, R, e_star, mu_f, dt,
                                      depth, &fn, 0.0, cap, &power);
    const double ft = std::abs(f[0]), expect = std::min(mu_f * fn, cap);
    EXPECT_NEAR(ft, expect, 1e-12 * expect);
    EXPECT_LT(f[0], 0);  // against the particle's sliding (+x relative to the surface)
    // the force times the mean sliding speed over the step (0.8 m/s less the deceleration)
    EXPECT_NEAR(power, ft * (0.8 - 0.5 * ft * dt / m), 1e-12 * ft);
    (mu_f * fn < cap ? sliding : sticking)++;
  }
  EXPECT_GT(sliding, 3);
  EXPECT_GT(sticking, 3);
}

TEST(CuttingFriction, FrictionWorkHeatsTheParticleByItsShare) {
  // The plate drags the particle up to its speed; the work the friction dissipates is the plate's
  // work minus the particle's kinetic energy gain along the plate (from rest: m V^2 / 2, as much
  // as the particle gains). The particle gets (1 - beta) of it as heat:
  // m C_p dT = (1 - beta) (W_plate - dKE); with beta = 1 nothing is heated.
  for (double beta : {0.3, 1.0}) {
    Scene scene = slider(fmt::format(", heat_partition: {}", beta));
    Simulation<2> sim(scene);
    auto* rigid = start(sim);
    ASSERT_NE(rigid, nullptr);
    auto& p = sim.particles();
    const int kT = p.find("temperature");
    if (beta == 1) {  // nothing heats: no temperature field at all (no plasticity, no conduction)
      EXPECT_LT(kT, 0);
      continue;
    }
    ASSERT_GE(kT, 0);
    const double T0 = p.view<double>(kT)[0], m = p.m()[0], ke0 = 0.5 * m * std::pow(p.v()[0][0], 2);
    double work = 0;
    while (sim.time() < 0.05) {
      const double t0 = sim.time();
      sim.advance();
      // The force of the last pass acts over the step that follows it (kick-drift-kick): the
      // plate's power F.V times the step.
      work += rigid->reaction(0)[0] * -0.2 * (sim.time() - t0);
    }
    const double ke = 0.5 * m * std::pow(p.v()[0][0], 2);
    EXPECT_NEAR(p.v()[0][0], 0.2, 1e-6);  // picked up the plate's speed
    const double heat = m * 500 * (p.view<double>(kT)[0] - T0), dissipated = work - (ke - ke0);
    EXPECT_NEAR(dissipated, 0.5 * m * 0.2 * 0.2, 0.01 * dissipated);
    EXPECT_NEAR(heat, (1 - beta) * dissipated, 0.005 * dissipated) << beta;
    std::printf("beta %.1f: dissipated %.6g J/m, heat %.6g J/m\n", beta, dissipated, heat);
  }
}

TEST(CuttingFriction, MassScalingScalesInertiaNotHeat) {
  // mass_scaling f: the particle's mass is f times, its heat capacity 1/f times, so m C_p and
  // the friction heat stay the same.
  Scene a = slider(", heat_partition: 0"), b = slider(", heat_partition: 0", ", mass_scaling: 100");
  EXPECT_DOUBLE_EQ(b.materials[0].density, 100 * a.materials[0].density);
  EXPECT_DOUBLE_EQ(b.materials[0].density * b.materials[0].heat_capacity,
                   a.materials[0].density * a.materials[0].heat_capacity);
  EXPECT_DOUBLE_EQ(b.materials[0].bulk_modulus, a.materials[0].bulk_modulus);
  EXPECT_THROW(slider("", ", mass_scaling: 0.5"), InputError);
  EXPECT_THROW(slider(", heat_partition: 1.5"), InputError);
  EXPECT_THROW(slider(", friction_limit: -1"), InputError);
}

TEST(CuttingFriction, ChipRatioIsTheLayerOnTheRakeFace) {
  // A vertical "rake face" at x = 0 (normal -x into the chip), a layer 4 dp thick on it and,
  // 3 dp further out, a block standing for a chip curled back into the window: the probe gives
  // the layer's thickness (4 dp) over size, not the extent of both (11 dp).
  Scene scene = load_scene_text(R"(
name: chip
dimension: 2
dp: 1.0e-5
domain: {min: [-3.0e-4, -1.0e-4], max: [1.0e-4, 3.0e-4]}
materials:
  m: {density: 4000, bulk_modulus: 1.0e8, shear_modulus: 3.0e7}
bodies:
  - {name: layer, phase: solid, continuum: a, material: m, shape: {box: {min: [-4.0e-5, 0], max: [0, 2.0e-4]}}}
  - {name: curl, phase: solid, continuum: a, material: m, shape: {box: {min: [-1.1e-4, 0], max: [-7.0e-5, 2.0e-4]}}}
surfaces:
  - {name: tool, segment: [[5.0e-6, -5.0e-5], [5.0e-6, 2.5e-4]]}
end_time: 1
probes:
  list:
    - {name: ratio, type: chip_ratio, surface: tool, body: layer, size: 2.0e-5, point: [5.0e-6, 0],
       axis: [0, 1], normal: [-1, 0], range: [5.0e-5, 1.5e-4]}
)");
  Simulation<2> sim(scene);
  auto* rigid = start(sim);
  ASSERT_NE(rigid, nullptr);
  std::vector<double> out;
  rigid->probe(sim, scene.probes[0], out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0], 4e-5 / 2e-5, 1e-9);        // the layer: 4 dp over 2 dp
  for (auto& b : sim.particles().body()) b = 0;  // the curled block joins the body
  out.clear();
  rigid->probe(sim, scene.probes[0], out);
  EXPECT_NEAR(out[0], 4e-5 / 2e-5, 1e-9);  // a 3 dp gap: still the layer only
  // method: section takes the widest run and the thickness normal to its mean flow e. With a
  // window 10 dp deep (size 4 dp) the block is in it whole; layer and block are 4 dp wide.
  ProbeSpec section = scene.probes[0];
  section.method = "section", section.size = 4e-5;
  auto& p = sim.particles();
  for (std::size_t i = 0; i < sim.owned(); ++i) p.v()[i] = Vec<2>(0, 1);
  auto ratio = [&] {
    out.clear();
    rigid->probe(sim, section, out);
    return out.at(0);
  };
  EXPECT_NEAR(ratio(), 1.0, 1e-9);
  // The layer sheared to a strip at 20 degrees, flowing along it: 4 dp wide across the window
  // (plus the shear over the window's 9 rows), 4 dp cos 20 thick normal to its flow.
  const double c = std::cos(0.349066), sn = std::sin(0.349066);
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    if (p.x()[i][0] < -5e-5) continue;
    p.x()[i][0] += (p.x()[i][1] - 1e-4) * sn / c;
    p.v()[i] = Vec<2>(sn, c);
  }
  EXPECT_NEAR(ratio(), c, 1e-9);
  // The layer leaves the window and the block flows at 0.8 along the axis: the block's
  // thickness normal to that flow is 0.8 of its width.
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    if (p.x()[i][0] > -6e-5) p.x()[i][1] += 1e-3;
    if (p.x()[i][0] < -6e-5) p.v()[i] = Vec<2>(0.6, 0.8);
  }
  EXPECT_NEAR(ratio(), 0.8, 1e-9);
}

TEST(CuttingFriction, ChipRatioFromFlowIsTheToolSpeedOverTheChipSpeed) {
  // A chip 4 dp thick flowing up a vertical rake face that moves at v_s = (-1, 0) m/s: the chip
  // moves with the tool plus 0.5 m/s up the face, so it is vc / 0.5 = 2 h thick (h = vc h /
  // v_chip by mass conservation). Particles outside the window or of another body do not count;
  // a chip whose particles also move across the face counts its full speed.
  Scene scene = load_scene_text(R"(
name: chip
dimension: 2
dp: 1.0e-5
domain: {min: [-3.0e-4, -1.0e-4], max: [1.0e-4, 3.0e-4]}
materials:
  m: {density: 4000, bulk_modulus: 1.0e8, shear_modulus: 3.0e7}
bodies:
  - {name: chip, phase: solid, continuum: a, material: m, shape: {box: {min: [-4.0e-5, -5.0e-5], max: [0, 2.5e-4]}}}
  - {name: other, phase: solid, continuum: a, material: m, shape: {box: {min: [-1.1e-4, 0], max: [-7.0e-5, 2.0e-4]}}}
surfaces:
  - {name: tool, segment: [[5.0e-6, -5.0e-5], [5.0e-6, 2.5e-4]], velocity: [-1, 0]}
end_time: 1
probes:
  list:
    - {name: ratio, type: chip_ratio, method: flow, surface: tool, body: chip, size: 2.0e-5,
       point: [5.0e-6, 0], axis: [0, 1], normal: [-1, 0], range: [5.0e-5, 1.5e-4]}
)");
  Simulation<2> sim(scene);
  auto* rigid = start(sim);
  ASSERT_NE(rigid, nullptr);
  auto& p = sim.particles();
  const auto body = p.body();
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    const double y = p.x()[i][1];
    const bool window = body[i] == 0 && y >= 5e-5 && y <= 1.5e-4;
    p.v()[i] = window ? Vec<2>(-1, 0.5) : Vec<2>(-1, 5.0);  // outside: a fast decoy
  }
  std::vector<double> out;
  rigid->probe(sim, scene.probes[0], out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0], 2.0, 1e-12);
  for (std::size_t i = 0; i < sim.owned(); ++i) p.v()[i] += Vec<2>(0.3, 0.4);  // 0.3, 0.9 rel.
  out.clear();
  rigid->probe(sim, scene.probes[0], out);
  EXPECT_NEAR(out[0], 1.0 / std::hypot(0.3, 0.9), 1e-12);
  // Over time the ratio is vc / (mean chip speed): the harmonic mean of the samples.
  const std::vector<double> t{0, 1, 2}, r{1, 2, 4};
  EXPECT_NEAR(measure_series("harmonic_mean", t, r, 0), 3 / (1 + 0.5 + 0.25), 1e-14);
  std::string why;
  EXPECT_TRUE(std::isnan(measure_series("harmonic_mean", t, {1, 0, 4}, 0, &why)));
  EXPECT_EQ(why, "a probe sample is not positive (0)");
}

TEST(CuttingFriction, SurfaceHeatTransferCoolsATouchingParticle) {
  // A particle at 400 K resting on a plate at 300 K with conductance h_c: m C_p dT/dt =
  // h_c dp (T_s - T) per metre of depth, so T - T_s decays as exp(-t/tau), tau = rho C_p dp/h_c
  // = 0.02 s; after tau it is 100/e K.
  const std::string text = R"(
name: sink
dimension: 2
dp: 0.001
domain: {min: [-0.05, -0.02], max: [0.2, 0.05]}
materials:
  m: {density: 4000, bulk_modulus: 1.0e8, shear_modulus: 3.0e7, heat_capacity: 500}
bodies:
  - {name: p, phase: solid, material: m, shape: {box: {min: [0, 0], max: [0.001, 0.001]}},
     heat_conduction: {conductivity: 1}, initial: {temperature: 400}}
surfaces:
  - {name: plate, segment: [[-0.04, 0], [0.19, 0]], heat_transfer: 1.0e5, temperature: 300,
     damping: 1}
body_force: [0, -2000]
end_time: 1
)";
  Scene scene = load_scene_text(text);
  Simulation<2> sim(scene);
  ASSERT_NE(start(sim), nullptr);
  auto& p = sim.particles();
  const int kT = p.find("temperature");
  ASSERT_GE(kT, 0);
  EXPECT_DOUBLE_EQ(p.view<double>(kT)[0], 400);
  while (sim.time() < 0.02) sim.advance(0.02);
  const double dT = p.view<double>(kT)[0] - 300;
  EXPECT_NEAR(dT, 100 * std::exp(-1.0), 0.05);  // measured 36.7899 K
  std::printf("T - T_s after tau: %.4f K (exact %.4f K)\n", dT, 100 * std::exp(-1.0));
  // Without conduction (or plasticity) the temperature field is the surface module's alone: it
  // starts at the body's temperature all the same.
  std::string bare = text;
  bare.erase(bare.find("heat_conduction"),
             std::string("heat_conduction: {conductivity: 1}, ").size());
  Scene bare_scene = load_scene_text(bare);
  Simulation<2> cold(bare_scene);
  ASSERT_NE(start(cold), nullptr);
  EXPECT_EQ(cold.particles().find("conduction_rate"), -1);  // no heat module
  EXPECT_DOUBLE_EQ(cold.particles().view<double>(cold.particles().find("temperature"))[0], 400);
  EXPECT_THROW(load_scene_text(R"(
name: bad
dimension: 2
dp: 0.001
domain: {min: [-0.05, -0.02], max: [0.2, 0.05]}
materials:
  m: {density: 4000, bulk_modulus: 1.0e8, shear_modulus: 3.0e7}
bodies:
  - {name: p, phase: solid, material: m, shape: {box: {min: [0, 0], max: [0.001, 0.001]}}}
surfaces:
  - {name: plate, segment: [[-0.04, 0], [0.19, 0]], temperature: 300}
end_time: 1
)"),
               InputError);
}
