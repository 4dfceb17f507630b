// Non-local damage (solid/nonlocal_damage.hpp): the average of damage increments over a fixed
// length, and the energy a failing point releases (solid/plasticity.hpp, add_damage).
#include <gtest/gtest.h>

#include <cmath>

#include "core/simulation.hpp"
#include "sim_helpers.hpp"
#include "solid/nonlocal_damage.hpp"
#include "solid/plasticity.hpp"

using namespace monosph;

namespace {

// Two 2D boxes of one material (dp = 1e-3), the first periodic along x: 40 x 10 particles from
// x = 0 to 0.04, and a second body beside it in y.
std::string two_boxes(double dp) {
  return "name: t\ndimension: 2\ndp: " + std::to_string(dp) +
         "\ndomain: {min: [0, -0.02], max: [0.04, 0.02], periodic: [x]}\n"
         "materials: {m: {density: 1000, bulk_modulus: 1e9, shear_modulus: 1e8}}\n"
         "bodies:\n"
         "  - {name: a, phase: solid, material: m, shape: {box: {min: [0, 0], max: [0.04, "
         "0.01]}}}\n"
         "  - {name: b, phase: solid, material: m, shape: {box: {min: [0, -0.011], max: [0.04, "
         "-0.001]}}}\n"
         "end_time: 1e-6\n";
}

struct Increments {
  std::vector<double> length, inc, out;
};

TEST(NonlocalDamage, ConstantIncrementsAverageToThemselves) {
  auto sim = test::build<2>(two_boxes(1e-3));
  const std::size_t n = sim->owned();
  Increments f{std::vector<double>(n, 3.5e-3), std::vector<double>(n, 0.25), {}};
  NonlocalAverage<2> avg;
  avg.average(*sim, f.length, f.inc, f.out);
  ASSERT_EQ(f.out.size(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(f.out[i], 0.25, 1e-14) << i;
}

// Averages a unit increment on particle `src` (length l everywhere) and compares every result
// with sum_j w V_j inc_j / sum_j w V_j summed over all particles of the body (minimum image
// along x when `period` > 0). Returns how many particles beyond x = far received some.
int expect_bell_average(Simulation<2>& sim, std::size_t src, double l, double period, double far) {
  const std::size_t n = sim.owned();
  auto x = sim.particles().x();
  auto bd = sim.particles().body();
  auto m = sim.particles().m();
  auto rho = sim.particles().rho();
  Increments f{std::vector<double>(n, l), std::vector<double>(n, 0.0), {}};
  f.inc[src] = 1.0;
  NonlocalAverage<2> avg;
  avg.average(sim, f.length, f.inc, f.out);
  auto r2 = [&](std::size_t i, std::size_t j) {
    double dx = x[j][0] - x[i][0];
    if (period > 0) dx -= period * std::rint(dx / period);
    const double dy = x[j][1] - x[i][1];
    return dx * dx + dy * dy;
  };
  int reached = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = bell_weight(r2(src, i), l * l);
    if (bd[i] != bd[src] || w == 0) {
      EXPECT_EQ(f.out[i], 0.0) << i;  // the other body, or beyond l
      continue;
    }
    double den = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (bd[j] == bd[i]) den += bell_weight(r2(i, j), l * l) * m[j] / rho[j];
    EXPECT_NEAR(f.out[i], w * m[src] / rho[src] / den, 1e-12) << i;
    reached += x[i][0] > far;
  }
  return reached;
}

std::size_t particle_at(Simulation<2>& sim, int body, double x0, double y0) {
  auto x = sim.particles().x();
  auto bd = sim.particles().body();
  for (std::size_t i = 0; i < sim.owned(); ++i)
    if (bd[i] == body && std::abs(x[i][0] - x0) < 1e-9 && std::abs(x[i][1] - y0) < 1e-9) return i;
  return sim.owned();
}

}  // namespace

TEST(NonlocalDamage, OneIncrementSpreadsWithTheBellWeightWithinItsBodyAcrossThePeriod) {
  auto sim = test::build<2>(two_boxes(1e-3));
  // The increment sits on a particle of body a at the periodic edge x = dp/2.
  const std::size_t src = particle_at(*sim, 0, 5e-4, 5e-4);
  ASSERT_LT(src, sim->owned());
  EXPECT_GT(expect_bell_average(*sim, src, 3.5e-3, 0.04, 0.03), 5);  // through the period
}

TEST(NonlocalDamage, ADomainOfManyCellsPerParticleUsesWiderCells) {
  // Two 1 cm boxes 100 m apart: cells of l would be 3e4 per particle; the average is the same.
  auto sim = test::build<2>(
      "name: t\ndimension: 2\ndp: 0.001\ndomain: {min: [0, 0], max: [100, 0.01]}\n"
      "materials: {m: {density: 1000, bulk_modulus: 1e9, shear_modulus: 1e8}}\n"
      "bodies:\n"
      "  - {name: a, phase: solid, material: m, shape: {box: {min: [0, 0], max: [0.01, 0.01]}}}\n"
      "  - {name: b, phase: solid, material: m, shape: {box: {min: [99.99, 0], max: [100, "
      "0.01]}}}\nend_time: 1e-6\n");
  const std::size_t src = particle_at(*sim, 1, 99.9955, 5.5e-3);
  ASSERT_LT(src, sim->owned());
  EXPECT_GT(expect_bell_average(*sim, src, 3.5e-3, 0, 99.99), 10);
}

TEST(NonlocalDamage, KeyNeedsALengthAboveDpAndOneRank) {
  const std::string mat =
      "materials: {m: {preset: Al6061-T6, damage: {D1: 0.1, D2: 0, D3: 0, nonlocal_length: L}}}\n";
  auto scene = [&](const std::string& len) {
    std::string t = two_boxes(1e-3);
    t.replace(t.find("materials:"), t.find("bodies:") - t.find("materials:"),
              std::string(mat).replace(mat.find('L'), 1, len));
    return t;
  };
  EXPECT_NE(test::load_error(scene("-1e-3")).find("nonlocal_length"), std::string::npos);
  EXPECT_NO_THROW(test::build<2>(scene("0")));  // 0: local
  EXPECT_NE(test::load_error(scene("abc")).find("nonlocal_length"), std::string::npos);
  try {
    test::build<2>(scene("1e-3"));
    ADD_FAILURE() << "a length of one dp was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.m.damage.nonlocal_length"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(test::build<2>(scene("3e-3")));
}

TEST(NonlocalDamage, AFailingPointReleasesItsElasticEnergy) {
  Material m;
  m.density = 2700, m.bulk_modulus = 70e9, m.shear_modulus = 26e9;
  Mat3 S = Mat3::Zero();
  S(0, 1) = S(1, 0) = 1e8;
  const double rho = 2700 * (1 - 1e-3);  // tension: p = -7e7
  const double p = m.pressure(rho);
  const double stored = 2e16 / (4 * m.shear_modulus) + p * p / (2 * m.bulk_modulus);
  PlasticPoint pt;
  pt.D = 0.7;
  add_damage(S, pt, m, rho, 0.2);  // not yet failed: nothing released
  EXPECT_NEAR(pt.D, 0.9, 1e-15);
  EXPECT_EQ(pt.released, 0.0);
  EXPECT_NE(S.norm(), 0.0);
  add_damage(S, pt, m, rho, 0.2);
  EXPECT_EQ(pt.D, 1.0);
  EXPECT_NEAR(pt.released, stored, 1e-9 * stored);
  EXPECT_EQ(S.norm(), 0.0);
}
