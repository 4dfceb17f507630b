#pragma once
// `monosph study --repeat KEY`: statistics of every reference metric over the runs that differ
// only in KEY (e.g. variables.seed: seeded impacts), one row per combination of the other keys.
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace monosph {

// Mean, sample standard deviation (n - 1), Student-t 95 % interval of the mean and the count of
// values exactly 0. n = 1: std and interval NaN; n = 0: mean NaN too.
struct SampleStats {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::size_t n = 0, zero = 0;
  double mean = kNaN, std = kNaN, ci95_low = kNaN, ci95_high = kNaN;
};
SampleStats sample_stats(const std::vector<double>& values);

// Two-sided 95 % quantile of Student's t with `dof` degrees of freedom (t_0.975): a table for
// 1-30, the Cornish-Fisher expansion above (Abramowitz & Stegun 26.7.5; error below 3e-8).
double student_t95(std::size_t dof);

// One run of the study as the statistics see it: the values of the varied keys, whether it
// completed, and each metric's value (none: not measured).
struct StudyRunValues {
  std::vector<std::string> values;
  bool completed = false;
  std::vector<std::optional<double>> metrics;
};

// The runs grouped by the values of every key but the repeated one (in the order of their
// first run): n completed runs, failed runs, each metric's statistics over the completed runs
// that measured it.
struct StudyStatsRow {
  std::vector<std::string> values;  // of the keys other than the repeated one
  std::size_t n = 0, failed = 0;
  std::vector<SampleStats> metrics;
};
std::vector<StudyStatsRow> study_stats(const std::vector<StudyRunValues>& runs, std::size_t repeat,
                                       std::size_t nmetrics);

// study_stats.csv: the other keys, n, failed, then per metric <m>_mean, <m>_ci95_low,
// <m>_ci95_high, <m>_zero, <m>_std (NaN as an empty field). Throws InputError when it cannot
// be written.
void write_study_stats_csv(const std::filesystem::path& file, const std::vector<std::string>& keys,
                           std::size_t repeat, const std::vector<std::string>& metrics,
                           const std::vector<StudyStatsRow>& rows);

// A CSV field: quoted when it holds a comma, quote or line break.
std::string csv_escape(const std::string& s);

// study.md's section of the same statistics.
void write_study_stats_md(std::ostream& md, const std::vector<std::string>& keys,
                          std::size_t repeat, const std::vector<std::string>& metrics,
                          const std::vector<StudyStatsRow>& rows);

}  // namespace monosph
