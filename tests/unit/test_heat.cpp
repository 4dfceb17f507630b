// Heat conduction (src/heat, `heat_conduction: {conductivity: k}`): a sine temperature mode in a
// periodic block decays at the analytic rate, the heat sum m c T is conserved, and the key is
// checked (value, phase, the material's heat capacity).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "heat/heat_module.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

// A soft solid block at rest filling a periodic box L x L/2 (dp = L/40): rho c = 1e6 J/(m^3 K).
std::string block(const std::string& conduction) {
  return R"(
name: heat
dimension: 2
dp: 5.0e-5
domain: {min: [0, 0], max: [2.0e-3, 1.0e-3], periodic: [x, y]}
materials:
  m: {density: 1000, bulk_modulus: 1.0e4, shear_modulus: 1.0e3, heat_capacity: 1000}
bodies:
  - {name: b, phase: solid, material: m, shape: {box: {min: [0, 0], max: [2.0e-3, 1.0e-3]}})" +
         conduction + R"(}
end_time: 1
)";
}

}  // namespace

// T = 300 + 10 sin(2 pi x / L) decays as exp(-alpha (2 pi / L)^2 t), alpha = k / (rho c).
TEST(Heat, SineModeDecaysAtTheAnalyticRate) {
  auto sim = test::build<2>(block(", heat_conduction: {conductivity: 17}"));
  auto& p = sim->particles();
  const double L = 2.0e-3, kw = 2 * std::numbers::pi / L, alpha = 17 / 1.0e6;
  auto set_or_measure = [&](bool set) {
    auto T = p.view<double>("temperature");
    auto x = p.x();
    double num = 0, den = 0;
    for (std::size_t i = 0; i < sim->owned(); ++i) {
      const double s = std::sin(kw * x[i][0]);
      if (set) T[i] = 300 + 10 * s;
      num += (T[i] - 300) * s, den += s * s;
    }
    return num / den;
  };
  set_or_measure(true);
  EXPECT_NEAR(set_or_measure(false), 10, 1e-9);
  const double t_end = 3.0e-3;  // about 0.5 of the decay time 1 / (alpha kw^2)
  while (sim->time() < t_end) sim->advance(t_end);
  const double expected = 10 * std::exp(-alpha * kw * kw * sim->time());
  const double measured = set_or_measure(false);
  std::printf("amplitude %.6f, analytic %.6f (t = %.3g s, %ld steps)\n", measured, expected,
              sim->time(), sim->step());
  EXPECT_LT(measured, 0.7 * 10);                // the mode has decayed
  EXPECT_NEAR(measured / expected, 1.0, 0.01);  // measured 1.0015
}

// Random temperatures: the pair terms are antisymmetric, so sum m c T stays to round-off while
// the spread falls.
TEST(Heat, ConductionConservesTheHeatSum) {
  auto sim = test::build<2>(block(", heat_conduction: {conductivity: 17}"));
  auto& p = sim->particles();
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(250, 350);
  for (auto& T : p.view<double>("temperature")) T = u(gen);
  auto sums = [&](double& spread) {
    auto T = p.view<double>("temperature");
    auto m = p.m();
    double heat = 0, mean = 0;
    for (std::size_t i = 0; i < sim->owned(); ++i) heat += m[i] * 1000 * T[i], mean += T[i];
    mean /= sim->owned();
    spread = 0;
    for (std::size_t i = 0; i < sim->owned(); ++i) spread = std::max(spread, std::abs(T[i] - mean));
    return heat;
  };
  double spread0, spread1;
  const double heat0 = sums(spread0);
  for (int s = 0; s < 100; ++s) sim->advance();
  const double heat1 = sums(spread1);
  EXPECT_NEAR(heat1 / heat0, 1.0, 1e-12);
  EXPECT_LT(spread1, 0.5 * spread0);
}

TEST(Heat, KeyIsCheckedAndTheModuleRunsOnlyWhenAsked) {
  EXPECT_NE(test::load_error(block(", heat_conduction: {conductivity: -1}"))
                .find("bodies[0] (b).heat_conduction.conductivity"),
            std::string::npos);
  EXPECT_NE(test::load_error(block(", heat_conduction: {conductivty: 1}")).find("conductivity"),
            std::string::npos);  // "did you mean"
  std::string no_capacity = block(", heat_conduction: {conductivity: 1}");
  no_capacity.replace(no_capacity.find(", heat_capacity: 1000"), 21, "");
  EXPECT_NE(test::load_error(no_capacity).find("heat_capacity"), std::string::npos);
  auto plain = test::build<2>(block(""));
  for (const auto& m : plain->modules()) EXPECT_NE(m->name(), "heat");
  EXPECT_FALSE(plain->particles().has("conduction_rate"));
}
