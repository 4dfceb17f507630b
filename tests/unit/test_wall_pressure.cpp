// The wall-pressure probe (`type: wall_pressure`, src/output/wall_pressure_probe.cpp): sensor
// points, the hydrostatic pressure on the floor and on a side wall, a dry sensor, and the checks
// of its keys.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "assemble.hpp"
#include "output/probes.hpp"
#include "output/wall_pressure_probe.hpp"
#include "scene/scene_reader.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

constexpr double kH = 0.2, kG = 9.81, kRho0 = 1000, kDp = 0.01;

// Water [0, 0.3] x [0, H] in a tank of three wall layers (inner faces x = 0, x = 0.3, y = 0),
// dp = 1 cm, c0 = 20 m/s, and the probes `probes` (YAML list items).
std::string tank(const std::string& probes) {
  return fmt::format(R"(
name: sensor_tank
dimension: 2
dp: 0.01
domain: {{min: [-0.03, -0.03], max: [0.33, 0.4]}}
materials:
  water: {{density: 1000, sound_speed: 20}}
bodies:
  - name: water
    phase: fluid
    material: water
    shape: {{box: {{min: [0, 0], max: [0.3, 0.2]}}}}
  - name: tank
    phase: wall
    material: water
    shape: {{difference: [{{box: {{min: [-0.03, -0.03], max: [0.33, 0.4]}}}}, {{box: {{min: [0, 0], max: [0.3, 0.4]}}}}]}}
body_force: [0, -9.81]
end_time: 1
probes:
  list:
{}
)",
                     probes);
}

// The tank with the hydrostatic field p = rho0 g (H - y) set in the fluid (through the inverse
// EOS, c0^2 = 400) and the wall pressures extrapolated from it (Adami Eq. 27).
std::unique_ptr<Simulation<2>> hydrostatic(const std::string& probes) {
  auto sim = std::make_unique<Simulation<2>>(load_scene_text(tank(probes)));
  assemble_modules(*sim);
  sim->create_particles();
  sim->init();
  auto& p = sim->particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) p.rho()[i] = kRho0 * (1 + kG * (kH - p.x()[i][1]) / 400.0);
  sim->update_pair_cache();
  for (auto& m : sim->modules()) m->sums(*sim);
  return sim;
}

using test::load_error;

std::string probes_error(const std::string& probes) {
  auto sim = std::make_unique<Simulation<2>>(load_scene_text(tank(probes)));
  assemble_modules(*sim);
  sim->create_particles();
  try {
    Probes<2> pr(*sim);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(WallPressure, SensorPointsCoverTheSegmentAndTheDisc) {
  // 2D: m = max(10, ceil(size / spacing)) midpoints of equal parts, on the line through c
  // perpendicular to n. 3D: grid cells of side size/m whose centres lie in the disc.
  auto seg = sensor_points<2>(Vec<2>(1, 2), Vec<2>(-1, 0), 0.1, 0.004);
  ASSERT_EQ(seg.size(), 25u);
  for (const auto& x : seg) EXPECT_DOUBLE_EQ(x[0], 1.0);
  EXPECT_NEAR(std::abs(seg.front()[1] - seg.back()[1]), 0.096, 1e-12);  // size - size/m
  EXPECT_EQ(sensor_points<2>(Vec<2>(0, 0), Vec<2>(0, 1), 0.001, 0.01).size(), 10u);
  const Vec<3> n = Vec<3>(1, 1, 0).normalized(), c(0.5, 0.5, 0.5);
  auto disc = sensor_points<3>(c, n, 0.2, 0.01);  // m = 20: pi/4 m^2 = 314 cells
  EXPECT_NEAR(static_cast<double>(disc.size()), M_PI / 4 * 400, 12);
  Vec<3> mean = Vec<3>::Zero();
  for (const auto& x : disc) {
    EXPECT_NEAR((x - c).dot(n), 0.0, 1e-12);  // on the face
    EXPECT_LE((x - c).norm(), 0.1 + 1e-12);
    mean += x / static_cast<double>(disc.size());
  }
  EXPECT_LT((mean - c).norm(), 1e-12);  // symmetric about the centre
}

TEST(WallPressure, HydrostaticPressureOnTheFloorAndOnASideWall) {
  // Sensors of 2 cm on the floor (depth H) and on both side walls at depth H/2 and 3H/4: within
  // 0.1 % of rho0 g depth (measured +0.02 %, -0.003 %, -0.003 %). A Shepard sum over the fluid
  // alone sits about h/2 inside the fluid, 3.2 % short of rho0 g H on the floor: the wall
  // particles' p_w centre the interpolation on the face.
  auto sim = hydrostatic(R"(
    - {name: floor, type: wall_pressure, body: tank, center: [0.15, 0], normal: y, size: 0.02}
    - {name: left, type: wall_pressure, body: tank, center: [0, 0.1], normal: [1, 0], size: 0.02}
    - {name: right, type: wall_pressure, body: tank, center: [0.3, 0.05], normal: -x, size: 0.02}
    - {name: dry, type: wall_pressure, body: tank, center: [0.3, 0.35], normal: -x, size: 0.02})");
  Probes<2> probes(*sim);
  const auto v = probes.sample(*sim);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_NEAR(v[0], kRho0 * kG * kH, 0.001 * kRho0 * kG * kH);
  EXPECT_NEAR(v[1], kRho0 * kG * (kH - 0.1), 0.001 * kRho0 * kG * (kH - 0.1));
  EXPECT_NEAR(v[2], kRho0 * kG * (kH - 0.05), 0.001 * kRho0 * kG * (kH - 0.05));
  EXPECT_EQ(v[3], 0.0);  // no fluid within the kernel: the wall there carries no pressure
  // The same floor sensor from the fluid particles alone: measurably short (the test can fail).
  auto& p = sim->particles();
  const auto& W = sim->kernel();
  double num = 0, den = 0;
  for (const auto& s : sensor_points<2>(Vec<2>(0.15, 0), Vec<2>(0, 1), 0.02, 0.25 * kDp)) {
    double a = 0, b = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.phase()[i] != kFluid) continue;
      const double w = p.m()[i] / p.rho()[i] * W.w((p.x()[i] - s).norm());
      a += p.p()[i] * w, b += w;
    }
    num += a / b, den += 1;
  }
  EXPECT_LT(num / den, 0.985 * kRho0 * kG * kH);
}

TEST(WallPressure, HydrostaticPressureOnADiscIn3D) {
  // 3D: water 0.2 m deep in a box of three layers (dp = 2 cm), sensors of 4 cm diameter on the
  // floor and on a side wall at half depth: within 0.2 % of rho0 g depth (measured +0.04 %,
  // -0.005 %).
  auto sim = std::make_unique<Simulation<3>>(load_scene_text(R"(
name: sensor_tank_3d
dimension: 3
dp: 0.02
domain: {min: [-0.06, -0.06, -0.06], max: [0.26, 0.26, 0.36]}
materials:
  water: {density: 1000, sound_speed: 20}
bodies:
  - name: water
    phase: fluid
    material: water
    shape: {box: {min: [0, 0, 0], max: [0.2, 0.2, 0.2]}}
  - name: tank
    phase: wall
    material: water
    shape: {difference: [{box: {min: [-0.06, -0.06, -0.06], max: [0.26, 0.26, 0.36]}}, {box: {min: [0, 0, 0], max: [0.2, 0.2, 0.36]}}]}
body_force: [0, 0, -9.81]
end_time: 1
probes:
  list:
    - {name: floor, type: wall_pressure, body: tank, center: [0.1, 0.1, 0], normal: z, size: 0.04}
    - {name: side, type: wall_pressure, body: tank, center: [0, 0.1, 0.1], normal: x, size: 0.04}
)"));
  assemble_modules(*sim);
  sim->create_particles();
  sim->init();
  auto& p = sim->particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) p.rho()[i] = kRho0 * (1 + kG * (kH - p.x()[i][2]) / 400.0);
  sim->update_pair_cache();
  for (auto& m : sim->modules()) m->sums(*sim);
  Probes<3> probes(*sim);
  const auto v = probes.sample(*sim);
  EXPECT_NEAR(v[0], kRho0 * kG * kH, 0.002 * kRho0 * kG * kH);
  EXPECT_NEAR(v[1], kRho0 * kG * (kH - 0.1), 0.002 * kRho0 * kG * (kH - 0.1));
}

TEST(WallPressure, FollowsARisingLevel) {
  // Raising the whole hydrostatic field by dp0 = 0.5 rho0 g H (as a water level 1.5 H would):
  // every sensor rises by the same amount (the interpolation is linear in the pressures).
  auto sim = hydrostatic(R"(
    - {name: floor, type: wall_pressure, body: tank, center: [0.15, 0], normal: y, size: 0.02}
    - {name: left, type: wall_pressure, body: tank, center: [0, 0.1], normal: x, size: 0.02})");
  Probes<2> probes(*sim);
  const auto v0 = probes.sample(*sim);
  auto& p = sim->particles();
  const double dp0 = 0.5 * kRho0 * kG * kH;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.phase()[i] == kFluid) p.rho()[i] += dp0 / 400.0;
  for (auto& m : sim->modules()) m->sums(*sim);
  const auto v1 = probes.sample(*sim);
  EXPECT_NEAR(v1[0] - v0[0], dp0, 1e-3 * dp0);
  EXPECT_NEAR(v1[1] - v0[1], dp0, 1e-3 * dp0);
}

TEST(WallPressure, KeysAreChecked) {
  const std::string ok = "{name: s, type: wall_pressure, body: tank, center: [0.3, 0.05], ";
  auto scene = [&](const std::string& rest) { return tank("    - " + ok + rest + "}"); };
  EXPECT_EQ(load_error(scene("normal: -x, size: 0.02")), "");
  EXPECT_NE(load_error(scene("normal: -x, size: 0")).find("probes.list[0].size: must be positive"),
            std::string::npos);
  EXPECT_NE(load_error(scene("normal: [0, 0], size: 0.02"))
                .find("probes.list[0].normal: must be a finite non-zero vector"),
            std::string::npos);
  EXPECT_NE(load_error(scene("normal: w, size: 0.02")).find("probes.list[0].normal: 'w' is not"),
            std::string::npos);
  EXPECT_NE(load_error(scene("size: 0.02")).find("probes.list[0].normal: missing"),
            std::string::npos);
  EXPECT_NE(
      load_error(tank("    - {name: s, type: wall_pressure, body: water, center: [0.3, 0.05], "
                      "normal: -x, size: 0.02}"))
          .find("probes.list[0].body: 'water' is a fluid"),
      std::string::npos);
  EXPECT_NE(load_error(tank("    - {name: s, type: wall_pressure, center: [0.3, 0.05], normal: "
                            "-x, size: 0.02}"))
                .find("probes.list[0].body: missing"),
            std::string::npos);
  EXPECT_NE(load_error(tank("    - {name: s, type: kinetic_energy, size: 0.02}"))
                .find("probes.list[0].size: unknown key"),
            std::string::npos);
  // On the face, and the normal out of the wall: checked against the particles at the start.
  EXPECT_EQ(probes_error("    - " + ok + "normal: -x, size: 0.02}"), "");
  EXPECT_NE(probes_error("    - {name: s, type: wall_pressure, body: tank, center: [0.2, 0.05], "
                         "normal: -x, size: 0.02}")
                .find("probes.list[0].center: not on the face of 'tank'"),
            std::string::npos);
  EXPECT_NE(probes_error("    - " + ok + "normal: x, size: 0.02}")
                .find("probes.list[0].normal: points into 'tank'"),
            std::string::npos);
}
