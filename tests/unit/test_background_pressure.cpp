// Background pressure of a fluid (materials.NAME.background_pressure; Morris et al. 1997): the
// EOS, the force it exerts (none on a lattice, a restoring one on a displaced particle), the
// Adami wall extrapolation, and the input errors (free surface, non-fluid body).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <map>

#include "assemble.hpp"
#include "fluid/fluid_material.hpp"
#include "scene/scene_reader.hpp"

using namespace monosph;

namespace {

// A fluid filling a closed box of 3-layer walls (no free surface), or a box open at the top.
// dp = 0.01, fluid [0, 0.2]^2, rho0 = 1000, c0 = 20 (rho0 c0^2 = 4e5 Pa).
Scene box(double pb, bool closed, const std::string& extra = "") {
  const std::string top = closed ? "0.23" : "0.3";
  return load_scene_text(fmt::format(R"(
name: box
dimension: 2
dp: 0.01
domain: {{min: [-0.03, -0.03], max: [0.23, {1}]}}
materials:
  water: {{density: 1000, sound_speed: 20, background_pressure: {0}}}
  wallmat: {{density: 1000, sound_speed: 20}}
bodies:
  - name: water
    phase: fluid
    material: water
    shape: {{box: {{min: [0, 0], max: [0.2, 0.2]}}}}
  - name: walls
    phase: wall
    material: wallmat
    shape: {{difference: [{{box: {{min: [-0.03, -0.03], max: [0.23, {1}]}}}},
                         {{box: {{min: [0, 0], max: [0.2, {2}]}}}}]}}
end_time: 1
{3}
)",
                                     pb, top, closed ? "0.2" : "0.3", extra));
}

std::unique_ptr<Simulation<2>> build(const Scene& s) {
  auto sim = std::make_unique<Simulation<2>>(s);
  assemble_modules(*sim);
  sim->create_particles();
  return sim;
}

std::size_t find_id(Particles<2>& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id()[i] == id) return i;
  return p.size();
}

}  // namespace

TEST(BackgroundPressure, AddsToTheEquationOfStateAboveTheCavitationFloor) {
  // p = K (rho/rho0 - 1) + p_b; the cavitation floor holds the gauge part (it is the liquid's
  // tension), so the total never falls below p_cav + p_b.
  Material m;
  m.density = 1000, m.bulk_modulus = 4e5;
  FluidMaterial f;
  f.background_pressure = 2500;
  EXPECT_DOUBLE_EQ(f.pressure(m, 1000), 2500);
  EXPECT_NEAR(f.pressure(m, 1010), 4e5 * 0.01 + 2500, 1e-9);
  EXPECT_NEAR(f.pressure(m, 990), -4e5 * 0.01 + 2500, 1e-9);
  f.cavitation_pressure = -1000;
  EXPECT_DOUBLE_EQ(f.pressure(m, 990), -1000 + 2500);
  EXPECT_NEAR(m.pressure(1010), 4e5 * 0.01, 1e-9);  // the solids' EOS (MMB Eq. 13) has none
  // Read from the scene, and the run's pressure field carries it.
  auto sim = build(box(2500, true));
  EXPECT_DOUBLE_EQ(module_params<FluidMaterial>(sim->materials()[0].params).background_pressure,
                   2500);
  EXPECT_DOUBLE_EQ(module_params<FluidMaterial>(sim->materials()[1].params).background_pressure, 0);
  sim->init();
  auto& p = sim->particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) {
      EXPECT_DOUBLE_EQ(p.p()[i], 2500) << i;
    }
}

TEST(BackgroundPressureForce, VanishesOnALatticeAndAtWallsAndPushesADisplacedParticleBack) {
  // The symmetric pair (p_i + p_j) grad W V_j with p = p_b everywhere is 2 p_b sum_j V_j grad W:
  // zero on a complete lattice (fluid and wall particles alike, the walls at the extrapolated
  // p_w = p_b), not zero where the particles are not evenly spaced. There it pushes a particle
  // towards where the others are thinner: a displaced particle is pushed back to its site.
  const double pb = 4e4;
  auto sim = build(box(pb, true));
  auto& p = sim->particles();
  sim->init();
  const double scale = 2 * pb / (1000 * 0.01);  // 2 p_b / (rho dp): a one-sided sum's size
  auto pw = p.view<double>("wall_pressure");
  int walls = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.phase()[i] == kFluid) {
      EXPECT_LT(p.a()[i].norm(), 1e-11 * scale) << i;
    } else if (pw[i] != 0) {  // a wall particle with fluid neighbours
      EXPECT_NEAR(pw[i], pb, 1e-9 * pb) << i;
      ++walls;
    }
  }
  EXPECT_GT(walls, 150);
  // Displace one interior particle by (0.2, 0.1) dp; the densities stay rho0 (continuity), so
  // p = p_b everywhere and the whole force on it is the background pressure's.
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid && (p.x()[i] - Vec<2>(0.105, 0.095)).norm() < 1e-9) k = i;
  const auto id = p.id()[k];
  const Vec<2> site = p.x()[k];
  p.x()[k] += Vec<2>(0.002, 0.001);
  sim->init();
  k = find_id(p, id);
  const Vec<2> back = site - p.x()[k], a = p.a()[k];
  EXPECT_GT(a.norm(), 0.05 * scale);
  EXPECT_GT(a.dot(back), 0.9 * a.norm() * back.norm());
  // Without a background pressure the same displaced particle feels nothing (p = 0, v = 0).
  auto zero = build(box(0, true));
  auto& q = zero->particles();
  zero->init();
  std::size_t kz = find_id(q, id);
  q.x()[kz] += Vec<2>(0.002, 0.001);
  zero->init();
  kz = find_id(q, id);
  EXPECT_LT(q.a()[kz].norm(), 1e-12 * scale);
}

TEST(BackgroundPressureForce, AddsToTheWallPressureAndActsWhereTheVolumesVary) {
  // Closed box under gravity, particles on the lattice with rho from p = rho0 g (H - y) (volumes
  // m/rho grow upwards). The Adami wall pressure is p_b plus the same hydrostatic extrapolation
  // (Adami et al. 2012, Eq. 27): p_w(p_b) - p_w(0) = p_b at every wall particle. The fluid's
  // acceleration changes by -(2 p_b/rho_i) sum_j V_j grad W_ij, which is zero on a lattice of
  // equal volumes (test above) and here sum V grad W = grad V / V = -grad rho / rho: in the
  // interior Delta a = 2 p_b grad rho / rho^2 = -2 p_b rho0 g / (c0^2 rho^2) along y. The
  // lattice with unequal volumes is not at rest under p_b: it is pushed towards equal volumes.
  const double pb = 2e4, g = 9.81, H = 0.2, rho0 = 1000, c2 = 400;
  std::map<std::int64_t, Vec<2>> acc[2];
  std::map<std::int64_t, double> wallp[2], dens;
  std::map<std::int64_t, Vec<2>> pos;
  for (int run = 0; run < 2; ++run) {
    auto sim = build(box(run ? pb : 0, true, "body_force: [0, -9.81]"));
    auto& p = sim->particles();
    sim->init();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.phase()[i] == kFluid) p.rho()[i] = rho0 + rho0 * g * (H - p.x()[i][1]) / c2;
    sim->init();
    auto pw = p.view<double>("wall_pressure");
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto id = p.id()[i];
      acc[run][id] = p.a()[i];
      if (p.phase()[i] != kFluid) wallp[run][id] = pw[i];
      dens[id] = p.phase()[i] == kFluid ? p.rho()[i] : 0.0;
      pos[id] = p.x()[i];
    }
  }
  double worst_w = 0;
  int walls = 0;
  for (auto [id, w0] : wallp[0]) {
    if (w0 == 0) continue;  // no fluid neighbours
    worst_w = std::max(worst_w, std::abs(wallp[1][id] - w0 - pb)), ++walls;
  }
  EXPECT_GT(walls, 150);
  EXPECT_LT(worst_w, 1e-9 * pb);
  double worst = 0;
  int inner = 0;
  for (auto [id, a0] : acc[0]) {
    const Vec<2> x = pos[id];  // interior: 4 dp (more than the support) from every wall
    if (dens[id] == 0 || x.minCoeff() < 0.04 || x.maxCoeff() > 0.16) continue;
    const Vec<2> da = acc[1][id] - a0;
    const double expect = -2 * pb * rho0 * g / (c2 * dens[id] * dens[id]);
    worst = std::max({worst, std::abs(da[1] / expect - 1), std::abs(da[0] / expect)}), ++inner;
  }
  EXPECT_GT(inner, 100);
  EXPECT_LT(worst, 0.02);
}

TEST(BackgroundPressure, WithAFreeSurfaceIsAnInputErrorNamingTheKey) {
  // An open box has a free top: the background pressure would push it outwards.
  auto open = build(box(1e4, false));
  try {
    open->init();
    FAIL() << "no error for a free surface";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("materials.water.background_pressure: the fluid has a free surface"),
              std::string::npos)
        << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  auto open_without = build(box(0, false));  // without a background pressure: fine
  EXPECT_NO_THROW(open_without->init());
  auto closed = build(box(1e4, true));
  EXPECT_NO_THROW(closed->init());
}

TEST(BackgroundPressure, SceneErrors) {
  auto message = [](const std::string& text) {
    try {
      load_scene_text(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string head = R"(
name: bad
dimension: 2
dp: 0.01
domain: {min: [0, 0], max: [0.1, 0.1]}
end_time: 1
)";
  EXPECT_NE(message(head + R"(materials:
  water: {density: 1000, sound_speed: 20, background_pressure: -5}
bodies:
  - {name: water, phase: fluid, material: water, shape: {box: {min: [0, 0], max: [0.1, 0.1]}}}
)")
                .find("materials.water.background_pressure"),
            std::string::npos);
  EXPECT_NE(message(head + R"(materials:
  steel: {density: 7800, bulk_modulus: 1e11, shear_modulus: 8e10, background_pressure: 5}
bodies:
  - {name: block, phase: solid, material: steel, shape: {box: {min: [0, 0], max: [0.1, 0.1]}}}
)")
                .find("materials.steel.background_pressure: applies to fluids only (body 'block' "
                      "is solid)"),
            std::string::npos);
}
