// Measures of a probe series used by references and checks (drift, growth, trend, period).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/probes.hpp"

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
