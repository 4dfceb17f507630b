// `study --repeat`: statistics of a metric over repeated (seeded) runs (apps/study_stats).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "study_stats.hpp"

namespace monosph {
namespace {

TEST(StudyStats, MeanStdIntervalAndZerosOfKnownData) {
  // {1, 2, 3, 4, 0}: mean 2, sample variance 10/4, t_0.975(4) = 2.7764451052,
  // half-width 2.7764451052 sqrt(2.5) / sqrt(5) = 2.7764451052 / sqrt(2) = 1.96324316148.
  const SampleStats s = sample_stats({1, 2, 3, 4, 0});
  EXPECT_EQ(s.n, 5u);
  EXPECT_EQ(s.zero, 1u);
  EXPECT_DOUBLE_EQ(s.mean, 2);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(2.5));
  EXPECT_NEAR(s.ci95_low, 0.0367568385209, 1e-11);
  EXPECT_NEAR(s.ci95_high, 3.9632431614791, 1e-11);
  // Two values 1 and 3: std sqrt(2), half-width t(1) sqrt(2) / sqrt(2) = 12.7062047362.
  const SampleStats two = sample_stats({1, 3});
  EXPECT_NEAR(two.ci95_low, 2 - 12.7062047362, 1e-10);
  EXPECT_NEAR(two.ci95_high, 2 + 12.7062047362, 1e-10);
  EXPECT_EQ(two.zero, 0u);
}

TEST(StudyStats, OneValueHasNoIntervalAndNoneNoMean) {
  const SampleStats one = sample_stats({0.0});
  EXPECT_EQ(one.n, 1u);
  EXPECT_EQ(one.zero, 1u);
  EXPECT_EQ(one.mean, 0);
  EXPECT_TRUE(std::isnan(one.std) && std::isnan(one.ci95_low) && std::isnan(one.ci95_high));
  const SampleStats none = sample_stats({});
  EXPECT_EQ(none.n, 0u);
  EXPECT_TRUE(std::isnan(none.mean));
}

TEST(StudyStats, StudentTQuantilesMatchTheTableAndTheLimit) {
  EXPECT_NEAR(student_t95(1), 12.7062047362, 1e-9);
  EXPECT_NEAR(student_t95(2), 4.30265272975, 1e-9);
  EXPECT_NEAR(student_t95(10), 2.22813885199, 1e-9);
  EXPECT_NEAR(student_t95(30), 2.0422724563, 1e-9);
  // Above the table: the Cornish-Fisher expansion (exact values from the Student-t CDF).
  EXPECT_NEAR(student_t95(31), 2.0395134464, 1e-7);
  EXPECT_NEAR(student_t95(40), 2.02107539031, 1e-7);
  EXPECT_NEAR(student_t95(100), 1.98397151852, 1e-8);
  EXPECT_NEAR(student_t95(100000), 1.959963984540054, 1e-4);
  EXPECT_TRUE(std::isnan(student_t95(0)));
}

TEST(StudyStats, RunsAreGroupedByTheOtherKeysAndFailedRunsCountedApart) {
  // Keys (angle, seed); seed repeats. Angle 30: seeds 1, 2, 3 (seed 3 failed); angle 60: 1, 2
  // (seed 2 did not measure the metric).
  std::vector<StudyRunValues> runs = {
      {{"30", "1"}, true, {2.0}},           {{"60", "1"}, true, {0.0}},
      {{"30", "2"}, true, {4.0}},           {{"60", "2"}, true, {std::nullopt}},
      {{"30", "3"}, false, {std::nullopt}},
  };
  const auto rows = study_stats(runs, 1, 1);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].values, std::vector<std::string>{"30"});
  EXPECT_EQ(rows[0].n, 2u);
  EXPECT_EQ(rows[0].failed, 1u);
  EXPECT_DOUBLE_EQ(rows[0].metrics[0].mean, 3);
  EXPECT_EQ(rows[1].values, std::vector<std::string>{"60"});
  EXPECT_EQ(rows[1].n, 2u);
  EXPECT_EQ(rows[1].failed, 0u);
  EXPECT_EQ(rows[1].metrics[0].n, 1u);
  EXPECT_EQ(rows[1].metrics[0].zero, 1u);

  const auto file = std::filesystem::temp_directory_path() / "monosph_study_stats_test.csv";
  write_study_stats_csv(file, {"variables.angle", "variables.seed"}, 1, {"removed_mass"}, rows);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "variables.angle,n,failed,removed_mass_mean,removed_mass_ci95_low,removed_mass_ci95_"
            "high,removed_mass_zero,removed_mass_std\n"
            "30,2,1,3,-9.70620474,15.7062047,0,1.41421356\n"
            "60,2,0,0,,,1,\n");
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace monosph
