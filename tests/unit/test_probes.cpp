// Probes of rigid bodies (rigid_centre, rigid_velocity, rigid_angular_velocity), the profile
// probe (bins along an axis, profile_<name>.csv) and which probes take a `weight`.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "assemble.hpp"
#include "output/probes.hpp"
#include "rigid/cluster_module.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

using test::build;

// Bodies and probes in vacuum: domain [0, 0.2] x [0, 0.1], dp = 1 mm, iron, no body force.
std::string vacuum2(const std::string& bodies, const std::string& probes) {
  return fmt::format(R"(
name: probes
dimension: 2
dp: 0.001
domain: {{min: [0, 0], max: [0.2, 0.1]}}
materials:
  iron: {{preset: iron}}
bodies:
{}
end_time: 1
probes:
  list:
{}
)",
                     bodies, probes);
}

// Clusters of body b.
int clusters_of(Simulation<2>& sim, int b) {
  int n = 0;
  for (auto& m : sim.modules())
    if (auto* c = dynamic_cast<ClusterModule<2>*>(m.get()))
      for (std::size_t k = 0; k < c->size(); ++k) n += c->cluster(k).body == b;
  return n;
}

using test::load_error;

// A fluid box [0, 1] x [0, 0.5] (dp 0.05) at rest but for the initial velocity field, and probes.
std::string channel(const std::string& velocity, const std::string& probes) {
  return fmt::format(R"(
name: channel
dimension: 2
dp: 0.05
domain: {{min: [0, 0], max: [1, 0.7]}}
materials:
  water: {{density: 1000, sound_speed: 10}}
bodies:
  - name: water
    phase: fluid
    material: water
    shape: {{box: {{min: [0, 0], max: [1, 0.5]}}}}
    initial: {{velocity: {}}}
end_time: 1
probes:
  list:
{}
)",
                     velocity, probes);
}

}  // namespace

TEST(RigidProbes, FreeDiscGivesItsExactCentreVelocityAndSpin) {
  // No force acts: the centre moves at V, omega stays; the probes give exactly the cluster's.
  auto sim = build<2>(vacuum2(R"(
  - name: disc
    phase: rigid
    material: iron
    shape: {circle: {center: [0.05, 0.05], radius: 0.005}}
    initial: {velocity: [3, -2], angular_velocity: 40})",
                              R"(
    - {name: c, type: rigid_centre, body: disc}
    - {name: v, type: rigid_velocity, body: disc}
    - {name: w, type: rigid_angular_velocity, body: disc})"));
  Probes<2> probes(*sim);
  ASSERT_EQ(probes.columns(), (std::vector<std::string>{"c_x", "c_y", "v_x", "v_y", "w"}));
  const auto v0 = probes.sample(*sim);
  for (int k = 0; k < 200; ++k) sim->advance();
  const double t = sim->time();
  ASSERT_GT(t, 0);
  const auto v = probes.sample(*sim);
  EXPECT_NEAR(v[0], v0[0] + 3 * t, 1e-15);
  EXPECT_NEAR(v[1], v0[1] - 2 * t, 1e-15);
  EXPECT_NEAR(v0[0], 0.05, 1e-12);  // the disc's lattice is symmetric about its centre
  EXPECT_NEAR(v0[1], 0.05, 1e-12);
  EXPECT_NEAR(v[2], 3, 1e-13);
  EXPECT_NEAR(v[3], -2, 1e-13);
  EXPECT_NEAR(v[4], 40, 1e-11);
}

TEST(RigidProbes, SphereIn3DHasThreeComponentsOfEach) {
  auto sim = build<3>(R"(
name: ball
dimension: 3
dp: 0.001
domain: {min: [0, 0, 0], max: [0.04, 0.04, 0.04]}
materials:
  iron: {preset: iron}
bodies:
  - name: ball
    phase: rigid
    material: iron
    shape: {sphere: {center: [0.02, 0.02, 0.02], radius: 0.004}}
    initial: {velocity: [1, 2, -1], angular_velocity: [5, -7, 11]}
end_time: 1
probes:
  list:
    - {name: c, type: rigid_centre, body: ball}
    - {name: v, type: rigid_velocity, body: ball}
    - {name: w, type: rigid_angular_velocity, body: ball}
)");
  Probes<3> probes(*sim);
  ASSERT_EQ(probes.columns().size(), 9u);
  EXPECT_EQ(probes.columns()[8], "w_z");
  for (int k = 0; k < 50; ++k) sim->advance();
  const double t = sim->time();
  const auto v = probes.sample(*sim);
  const double c[3] = {0.02 + t, 0.02 + 2 * t, 0.02 - t}, vel[3] = {1, 2, -1}, w[3] = {5, -7, 11};
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(v[a], c[a], 1e-12);
    EXPECT_NEAR(v[3 + a], vel[a], 1e-13);
    EXPECT_NEAR(v[6 + a], w[a], 1e-10);  // the lattice sphere's inertia is isotropic
  }
}

TEST(RigidProbes, BodyOfSeveralClustersGivesTheWholeBodyMotion) {
  // The same two-disc union as one cluster (body `one`) and as two (`two`, clusters: per_part)
  // in the same rigid-rotation velocity field about its centre: the mass-weighted centre and
  // velocity and I^-1 L about the centre of the two clusters equal the single cluster's.
  const std::string shape =
      "{{union: [{{circle: {{center: [{0}, 0.05], radius: 0.004}}}}, "
      "{{circle: {{center: [{1}, 0.05], radius: 0.003}}}}]}}";
  auto body = [&](const char* name, double x0, const char* clusters) {
    return fmt::format(R"Y(
  - name: {}
    phase: rigid
    material: iron
    clusters: {}
    shape: {}
    initial: {{velocity: ["1 - 50*(y - 0.05)", "50*(x - {})"]}})Y",
                       name, clusters, fmt::format(fmt::runtime(shape), x0, x0 + 0.01), x0);
  };
  auto sim = build<2>(vacuum2(body("one", 0.05, "one") + body("two", 0.12, "per_part"), R"(
    - {name: c1, type: rigid_centre, body: one}
    - {name: c2, type: rigid_centre, body: two}
    - {name: v1, type: rigid_velocity, body: one}
    - {name: v2, type: rigid_velocity, body: two}
    - {name: w1, type: rigid_angular_velocity, body: one}
    - {name: w2, type: rigid_angular_velocity, body: two})"));
  ASSERT_EQ(clusters_of(*sim, 0), 1);
  ASSERT_EQ(clusters_of(*sim, 1), 2);
  Probes<2> probes(*sim);
  const auto v = probes.sample(*sim);
  EXPECT_NEAR(v[2] - v[0], 0.07, 1e-12);  // centres
  EXPECT_NEAR(v[3], v[1], 1e-12);
  EXPECT_NEAR(v[6], v[4], 1e-12);  // velocities (x: 1 - 50 (y_c - 0.05), y: 50 (x_c - x0))
  EXPECT_NEAR(v[7], v[5], 1e-12);
  EXPECT_NEAR(v[9], v[8], 1e-12 * 50);  // omega
  EXPECT_GT(v[8], 45);                  // 50 less the particles' own inertia (dp^2/6 each)
  EXPECT_LT(v[8], 50);
}

TEST(RigidProbes, BodyMustBeARigidBody) {
  const std::string disc = R"(
  - name: disc
    phase: rigid
    material: iron
    shape: {circle: {center: [0.05, 0.05], radius: 0.005}}
  - name: block
    phase: solid
    material: iron
    shape: {box: {min: [0.1, 0.02], max: [0.12, 0.04]}})";
  EXPECT_EQ(load_error(vacuum2(disc, "    - {name: c, type: rigid_centre}")),
            "probes.list[0].body: missing (the name of a rigid body)");
  EXPECT_EQ(load_error(vacuum2(disc, "    - {name: c, type: rigid_velocity, body: dsic}")),
            "probes.list[0].body: no body named 'dsic'");
  EXPECT_EQ(
      load_error(vacuum2(disc, "    - {name: c, type: rigid_angular_velocity, body: block}")),
      "probes.list[0].body: 'block' is not a rigid body (phase solid); rigid_angular_velocity "
      "needs a body with phase: rigid");
  // A reference may name one component (c_y), not the bare vector probe.
  EXPECT_EQ(load_error(vacuum2(disc, "    - {name: c, type: rigid_centre, body: disc}") +
                       "reference: [{name: r, value: 1, probe: c_y, measure: final}]"),
            "");
  EXPECT_NE(load_error(vacuum2(disc, "    - {name: c, type: rigid_centre, body: disc}") +
                       "reference: [{name: r, value: 1, probe: c, measure: final}]"),
            "");
}

TEST(ProfileProbe, LinearVelocityGivesTheExactBinMeansAndAnEmptyBin) {
  // u = 2 y on rows y = 0.025, 0.075, ... 0.475: bins of 0.1 hold two rows each (mean 2 x the bin
  // centre); the range [0, 0.6] has a last bin above the water (no particle: NaN).
  auto sim = build<2>(channel(R"(["2*y", "0"])", R"(
    - {name: u, type: profile, field: velocity.x, axis: y, bins: 6, range: [0, 0.6]}
    - {name: ud, type: profile, field: velocity.x, body: water, axis: [0, 3], bins: 5}
    - {name: e, type: kinetic_energy})"));
  Probes<2> probes(*sim);
  ASSERT_EQ(probes.columns(), std::vector<std::string>{"e"});  // profiles have no column
  probes.sample(*sim);
  const auto& u = probes.profile("u");
  ASSERT_EQ(u.mean.size(), 6u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(u.position[k], 0.05 + 0.1 * k, 1e-15);
    EXPECT_NEAR(u.mean[k], 2 * u.position[k], 1e-14) << k;
    EXPECT_EQ(u.particles[k], 40);
  }
  EXPECT_TRUE(std::isnan(u.mean[5]));
  EXPECT_EQ(u.particles[5], 0);
  // Default range: the body's shape, [0, 0.5] (axis given as a vector).
  const auto& ud = probes.profile("ud");
  ASSERT_EQ(ud.mean.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(ud.position[k], 0.05 + 0.1 * k, 1e-15);
    EXPECT_NEAR(ud.mean[k], u.mean[k], 1e-15);
  }
}

TEST(ProfileProbe, MeanIsWeightedByTheParticleVolume) {
  // Densities set to 1000 (1 + x) (the masses kept): V = m/rho varies along x; bins along x of
  // u = x^2 give sum V u / sum V (not the plain mean of u).
  auto sim = build<2>(channel(R"(["x^2", "0"])", R"(
    - {name: u, type: profile, field: velocity.x, axis: x, bins: 2})"));
  auto& p = sim->particles();
  for (std::size_t i = 0; i < p.size(); ++i) p.rho()[i] = 1000 * (1 + p.x()[i][0]);
  Probes<2> probes(*sim);
  probes.sample(*sim);
  double sv[2] = {0, 0}, s[2] = {0, 0}, plain[2] = {0, 0}, n[2] = {0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int k = p.x()[i][0] < 0.5 ? 0 : 1;
    const double vol = p.m()[i] / p.rho()[i], u = p.v()[i][0];
    sv[k] += vol * u, s[k] += vol, plain[k] += u, n[k] += 1;
  }
  const auto& u = probes.profile("u");
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(u.mean[k], sv[k] / s[k], 1e-15);
    EXPECT_GT(std::abs(u.mean[k] - plain[k] / n[k]), 1e-4);  // the weighting matters here
  }
}

TEST(ProfileProbe, WritesLongFormatCsvAndKeepsRowsUpToTheRestartTime) {
  const auto dir = std::filesystem::temp_directory_path() / "monosph_test_profile";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto sim = build<2>(channel(R"(["2*y", "0"])", R"(
    - {name: u, type: profile, field: velocity.x, axis: y, bins: 6, range: [0, 0.6]})"));
  auto read = [&] {
    std::ifstream in(dir / "profile_u.csv");
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
  };
  {
    Probes<2> probes(*sim);
    probes.open_profiles(dir, false, sim->time());
    probes.sample(*sim);  // t = 0
    sim->set_state(0.5, 7, sim->dt());
    probes.sample(*sim);
    sim->set_state(1.0, 9, sim->dt());
    probes.sample(*sim);
  }
  auto lines = read();
  ASSERT_EQ(lines.size(), 1u + 3 * 6);
  EXPECT_EQ(lines[0], "time,step,position,mean,particles");
  auto cells = [&](std::size_t row) {
    std::vector<std::string> c;
    std::stringstream ss(lines.at(row));
    for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
    return c;
  };
  auto first = cells(1), empty = cells(6);
  ASSERT_EQ(first.size(), 5u);
  EXPECT_EQ(first[0] + "," + first[1] + "," + first[4], "0,0,40");
  EXPECT_NEAR(std::stod(first[2]), 0.05, 1e-16);
  EXPECT_NEAR(std::stod(first[3]), 0.1, 1e-15);
  EXPECT_EQ(empty[3] + "," + empty[4], "nan,0");  // the empty bin
  EXPECT_NEAR(std::stod(empty[2]), 0.55, 1e-15);
  EXPECT_EQ(lines[7].substr(0, 6), "0.5,7,");
  // A restart at t = 0.5 keeps the rows of t <= 0.5 and appends after them; a partly written
  // last row ("0.5" of a row at t = 0.55 of a killed run) is dropped.
  std::ofstream(dir / "profile_u.csv", std::ios::app) << "0.5";
  {
    Probes<2> probes(*sim);
    probes.open_profiles(dir, true, 0.5);
    sim->set_state(0.75, 8, sim->dt());
    probes.sample(*sim);
  }
  lines = read();
  ASSERT_EQ(lines.size(), 1u + 3 * 6);
  EXPECT_EQ(lines[12].substr(0, 6), "0.5,7,");
  EXPECT_EQ(lines[13].substr(0, 7), "0.75,8,");
  std::filesystem::remove_all(dir);
}

TEST(ProfileProbe, BadKeysNameThePath) {
  auto err = [](const std::string& probe) {
    return load_error(channel(R"(["0", "0"])", "    - " + probe));
  };
  EXPECT_EQ(err("{name: u, type: profile, field: velocity.x, axis: y, bins: 0}"),
            "probes.list[0].bins: must be at least 1, got 0");
  EXPECT_EQ(err("{name: u, type: profile, field: velocity.x, axis: y}"),
            "probes.list[0].bins: missing (the number of bins, at least 1)");
  EXPECT_EQ(err("{name: u, type: profile, field: velocity.x, axis: w, bins: 3}"),
            "probes.list[0].axis: 'w' is not an axis (x, y or a vector)");
  EXPECT_EQ(err("{name: u, type: profile, field: velocity.x, axis: y, bins: 3, range: [1, 0]}"),
            "probes.list[0].range: must be [lo, hi] with lo < hi");
  EXPECT_EQ(err("{name: u, type: profile, field: velocity.x, bins: 3}"),
            "probes.list[0].axis: missing (required)");
  EXPECT_NE(err("{name: u, type: mean, field: velocity.x, bins: 3}").find("bins: unknown key"),
            std::string::npos);
  // A profile has no column in probes.csv: a reference cannot name it.
  EXPECT_EQ(
      load_error(channel(R"(["0", "0"])",
                         "    - {name: u, type: profile, field: velocity.x, axis: y, "
                         "bins: 3}\nreference: [{name: r, value: 1, probe: u, measure: final}]")),
      "reference[0].probe: no probe named 'u'");
}

TEST(ProbeWeight, MultipliesTheIntegrandOfIntegralMeanAndKineticEnergyOnly) {
  // weight 3 x: kinetic energy and integral scale by the weight; the mean's denominator (the
  // volume) is not weighted.
  auto sim = build<2>(channel(R"(["1", "0"])", R"(
    - {name: e, type: kinetic_energy}
    - {name: ew, type: kinetic_energy, weight: "3*x"}
    - {name: i, type: integral, field: velocity.x}
    - {name: iw, type: integral, field: velocity.x, weight: "3*x"}
    - {name: m, type: mean, field: velocity.x, weight: "3*x"})"));
  Probes<2> probes(*sim);
  const auto v = probes.sample(*sim);
  EXPECT_NEAR(v[1] / v[0], 1.5, 1e-12);  // mean of 3 x over [0, 1] is 1.5
  EXPECT_NEAR(v[3] / v[2], 1.5, 1e-12);
  EXPECT_NEAR(v[4], 1.5, 1e-12);
  for (const char* type : {"value_at, point: [0.5, 0.2]", "max_speed", "total_energy", "profile"}) {
    const std::string probe = fmt::format(
        "    - {{name: p, type: {}, field: velocity.x, axis: x, bins: 2, weight: \"x\"}}", type);
    std::string err = load_error(channel(R"(["0", "0"])", probe));
    EXPECT_EQ(err.substr(0, err.find(" (")),
              "probes.list[0].weight: only integral, mean and kinetic_energy probes take a weight")
        << type;
  }
}
