// Measures of a probe series used by references and checks (drift, growth, trend, period).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "output/probes.hpp"
#include "scene/scene.hpp"

using namespace monosph;

namespace {
// y(t) = y0 (1 + slope t) + amplitude sin(2 pi t / period), sampled over [0, 10].
void series(double slope, double amplitude, std::vector<double>& t, std::vector<double>& y) {
  t.clear(), y.clear();
  for (int k = 0; k <= 10000; ++k) {
    const double tk = k * 1e-3;
    t.push_back(tk);
    y.push_back(2.0 * (1 + slope * tk) + amplitude * std::sin(2 * std::numbers::pi * tk / 0.25));
  }
}
}  // namespace

TEST(Measures, TrendIsTheSecularDriftNotTheOscillation) {
  std::vector<double> t, y;
  // Cycle means of y0 (1 + s t) + A sin(w t) are y0 (1 + s t_c). The crossing at t = 0 does not
  // count (no cycle before it), so the first and last whole cycles are centred at t = 0.375 and
  // 9.875, and the trend is s (9.5) / (1 + s 0.375).
  series(-1e-3, 0.1, t, y);  // 5 % oscillation, -1 % drift over the window
  EXPECT_NEAR(measure_series("trend", t, y, 0), -9.5e-3 / (1 - 3.75e-4), 1e-5);
  EXPECT_GT(measure_series("drift", t, y, 0), 0.05);  // drift sees the oscillation
  series(0, 0.1, t, y);
  EXPECT_NEAR(measure_series("trend", t, y, 0), 0.0, 1e-5);
  series(2e-3, 0, t, y);  // no oscillation: the change of the fitted line
  EXPECT_NEAR(measure_series("trend", t, y, 0), 0.02, 1e-12);
  EXPECT_NEAR(measure_series("trend", t, y, 5), 0.01 / 1.01, 1e-12);  // window from t = 5
}

TEST(Measures, GrowthCountsIncreasesOnlyAndDriftBoth) {
  std::vector<double> t = {0, 1, 2, 3}, y = {4, 3, 5, 2};
  EXPECT_DOUBLE_EQ(measure_series("growth", t, y, 0), 0.25);
  EXPECT_DOUBLE_EQ(measure_series("drift", t, y, 0), 0.5);
  y = {4, 3, 2, 1};
  EXPECT_DOUBLE_EQ(measure_series("growth", t, y, 0), 0.0);
}

TEST(Measures, PeriodFromZeroCrossings) {
  std::vector<double> t, y;
  series(0, 0.1, t, y);
  EXPECT_NEAR(measure_series("period", t, y, 0), 0.25, 1e-4);
}

TEST(Measures, PiecesAreTheLinkedClustersOfAPointSet) {
  // Two 2D lattices 10 x 10 (spacing 1) a gap of 1.6 apart, one lone point, one pair: linked
  // below 1.5 the lattices are two pieces of 100, the pair and the lone point pieces of 2 and 1.
  std::vector<double> xy;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      xy.insert(xy.end(), {double(i), double(j)});
      xy.insert(xy.end(), {10.6 + i, double(j)});
    }
  xy.insert(xy.end(), {-5.0, -5.0, 30.0, 0.0, 31.4, 0.0});
  EXPECT_EQ(piece_sizes(xy, 2, 1.5), (std::vector<long>{100, 100, 2, 1}));
  // Closing the gap to 1.4 joins the lattices: diagonal and straight links both count.
  for (std::size_t k = 0; k < xy.size(); k += 2)
    if (xy[k] > 10 && xy[k] < 25) xy[k] -= 0.2;
  EXPECT_EQ(piece_sizes(xy, 2, 1.5).front(), 200);
  // 3D: a column of points spacing 1 split by a gap of 2 at z = 5 is two pieces of 5; it is one
  // when the link reaches 2.5. Coordinates far from the origin and negative cells alike.
  std::vector<double> xyz;
  for (int k = 0; k < 10; ++k) xyz.insert(xyz.end(), {-1e3, 7.0, k + (k >= 5 ? 1.0 : 0.0) - 3});
  EXPECT_EQ(piece_sizes(xyz, 3, 1.5), (std::vector<long>{5, 5}));
  EXPECT_EQ(piece_sizes(xyz, 3, 2.5), (std::vector<long>{10}));
}

TEST(Measures, DiameterProbeIsTwiceTheLargestDistanceFromTheAxisPlusDp) {
  // A 3D cylinder of radius 0.05 along z (dp 0.01) through (0.1, 0.1): its lattice reaches
  // further out along the diagonals than along x. The probe gives 2 max r + dp about the axis,
  // the same after the body is turned about the axis; the x extent changes.
  Scene scene = load_scene_text(R"(
name: cyl
dimension: 3
dp: 0.01
domain: {min: [-0.2, -0.2, -0.2], max: [0.4, 0.4, 0.4]}
materials:
  steel: {density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9}
bodies:
  - name: bar
    phase: solid
    material: steel
    shape: {cylinder: {start: [0.1, 0.1, 0], end: [0.1, 0.1, 0.1], radius: 0.05}}
end_time: 1
probes:
  list:
    - {name: d, type: diameter, point: [0.1, 0.1, 0.3], axis: [0, 0, 2]}
    - {name: wx, type: extent, field: position.x}
)");
  Simulation<3> sim(scene);
  sim.create_particles();
  sim.init();
  Probes<3> probes(sim);
  auto& p = sim.particles();
  double r2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    r2 = std::max(r2, std::pow(p.x()[i][0] - 0.1, 2) + std::pow(p.x()[i][1] - 0.1, 2));
  const auto v0 = probes.sample(sim);
  EXPECT_NEAR(v0[0], 2 * std::sqrt(r2) + 0.01, 1e-14);
  EXPECT_GT(v0[0], v0[1] + 1e-4);  // the diagonal reaches further than the x extent
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dx = p.x()[i][0] - 0.1, dy = p.x()[i][1] - 0.1;
    p.x()[i][0] = 0.1 + c * dx - s * dy, p.x()[i][1] = 0.1 + s * dx + c * dy;
  }
  const auto v1 = probes.sample(sim);
  EXPECT_NEAR(v1[0], v0[0], 1e-14);
  EXPECT_GT(std::abs(v1[1] - v0[1]), 1e-4);
}

TEST(Measures, WhatCannotBeMeasuredSaysWhy) {
  std::vector<double> t, y;
  series(0, 1, t, y);  // 40 periods of 0.25
  std::string why;
  EXPECT_NEAR(measure_series("period", t, y, 0, &why), 0.25, 1e-3);
  EXPECT_EQ(why, "");
  EXPECT_TRUE(std::isnan(measure_series("period", t, y, 9.8, &why)));  // one crossing after 9.8
  EXPECT_EQ(why.rfind("fewer than two upward crossings of the mean (found 1)", 0), 0u) << why;
  EXPECT_TRUE(std::isnan(measure_series("final", t, y, 11, &why)));
  EXPECT_EQ(why, "no probe sample at or after t = 11 s");
  EXPECT_TRUE(std::isnan(measure_series("peak_ratio", t, y, 9.9, &why)));
  EXPECT_EQ(why, "fewer than two peaks above the first sample (found 0)");
}
