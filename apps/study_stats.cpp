#include "study_stats.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>

#include "core/types.hpp"

namespace monosph {

namespace {
// t_0.975 for 1-30 degrees of freedom (the Student-t CDF solved to 12 digits).
constexpr std::array<double, 30> kT95 = {
    12.7062047362, 4.30265272975, 3.18244630528, 2.7764451052,  2.57058183564, 2.44691185114,
    2.36462425159, 2.3060041352,  2.2621571628,  2.22813885199, 2.20098516009, 2.17881282967,
    2.16036865646, 2.14478668792, 2.13144954556, 2.11990529922, 2.10981557783, 2.10092204024,
    2.09302405441, 2.08596344727, 2.07961384473, 2.0738730679,  2.06865761042, 2.06389856163,
    2.05953855275, 2.05552943864, 2.05183051648, 2.0484071418,  2.04522964213, 2.0422724563};

// A number for a CSV field or table cell: empty (CSV) when NaN.
std::string num(double v, const char* empty = "") {
  return std::isnan(v) ? std::string(empty) : fmt::format("{:.9g}", v);
}
}  // namespace

double student_t95(std::size_t dof) {
  if (dof == 0) return SampleStats::kNaN;
  if (dof <= kT95.size()) return kT95[dof - 1];
  const double z = 1.959963984540054, z2 = z * z, nu = static_cast<double>(dof);
  const double g1 = (z2 + 1) * z / 4;
  const double g2 = ((5 * z2 + 16) * z2 + 3) * z / 96;
  const double g3 = (((3 * z2 + 19) * z2 + 17) * z2 - 15) * z / 384;
  const double g4 = ((((79 * z2 + 776) * z2 + 1482) * z2 - 1920) * z2 - 945) * z / 92160;
  return z + (g1 + (g2 + (g3 + g4 / nu) / nu) / nu) / nu;
}

SampleStats sample_stats(const std::vector<double>& values) {
  SampleStats s;
  s.n = values.size();
  if (s.n == 0) return s;
  double sum = 0;
  for (double v : values) sum += v, s.zero += v == 0;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n == 1) return s;
  double ss = 0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(ss / static_cast<double>(s.n - 1));
  const double half = student_t95(s.n - 1) * s.std / std::sqrt(static_cast<double>(s.n));
  s.ci95_low = s.mean - half;
  s.ci95_high = s.mean + half;
  return s;
}

std::vector<StudyStatsRow> study_stats(const std::vector<StudyRunValues>& runs, std::size_t repeat,
                                       std::size_t nmetrics) {
  std::vector<StudyStatsRow> rows;
  std::vector<std::vector<std::vector<double>>> values;  // [row][metric][run]
  for (const auto& r : runs) {
    std::vector<std::string> key;
    for (std::size_t a = 0; a < r.values.size(); ++a)
      if (a != repeat) key.push_back(r.values[a]);
    std::size_t k = 0;
    while (k < rows.size() && rows[k].values != key) ++k;
    if (k == rows.size()) {
      rows.push_back({key, 0, 0, {}});
      values.emplace_back(nmetrics);
    }
    if (!r.completed) {
      ++rows[k].failed;
      continue;
    }
    ++rows[k].n;
    for (std::size_t m = 0; m < nmetrics && m < r.metrics.size(); ++m)
      if (r.metrics[m]) values[k][m].push_back(*r.metrics[m]);
  }
  for (std::size_t k = 0; k < rows.size(); ++k)
    for (const auto& v : values[k]) rows[k].metrics.push_back(sample_stats(v));
  return rows;
}

std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string r = "\"";
  for (char c : s) r += c == '"' ? std::string("\"\"") : std::string(1, c);
  return r + "\"";
}

void write_study_stats_csv(const std::filesystem::path& file, const std::vector<std::string>& keys,
                           std::size_t repeat, const std::vector<std::string>& metrics,
                           const std::vector<StudyStatsRow>& rows) {
  std::ofstream csv(file);
  for (std::size_t a = 0; a < keys.size(); ++a)
    if (a != repeat) csv << csv_escape(keys[a]) << ",";
  csv << "n,failed";
  for (const auto& m : metrics)
    for (const char* c : {"_mean", "_ci95_low", "_ci95_high", "_zero", "_std"})
      csv << "," << csv_escape(fmt::format("{}{}", m, c));
  csv << "\n";
  for (const auto& r : rows) {
    for (const auto& v : r.values) csv << csv_escape(v) << ",";
    csv << r.n << "," << r.failed;
    for (const auto& s : r.metrics)
      csv << "," << num(s.mean) << "," << num(s.ci95_low) << "," << num(s.ci95_high) << ","
          << s.zero << "," << num(s.std);
    csv << "\n";
  }
  if (!csv) throw InputError("study: cannot write " + file.string());
}

void write_study_stats_md(std::ostream& md, const std::vector<std::string>& keys,
                          std::size_t repeat, const std::vector<std::string>& metrics,
                          const std::vector<StudyStatsRow>& rows) {
  md << "\n## Statistics over " << keys[repeat] << "\n\n"
     << "Mean, Student-t 95 % interval of the mean and runs that measured exactly 0, over the "
        "completed runs of each combination (study_stats.csv).\n\n|";
  std::size_t cols = 2 + 3 * metrics.size();
  for (std::size_t a = 0; a < keys.size(); ++a)
    if (a != repeat) md << " " << keys[a] << " |", ++cols;
  md << " n | failed |";
  for (const auto& m : metrics) md << " " << m << " mean | 95 % interval | zero |";
  md << "\n|";
  for (std::size_t c = 0; c < cols; ++c) md << "---|";
  md << "\n";
  for (const auto& r : rows) {
    md << "|";
    for (const auto& v : r.values) md << " " << v << " |";
    md << " " << r.n << " | " << r.failed << " |";
    for (const auto& s : r.metrics)
      md << " " << num(s.mean, "–") << " | "
         << (std::isnan(s.ci95_low) ? std::string("–")
                                    : fmt::format("[{}, {}]", num(s.ci95_low), num(s.ci95_high)))
         << " | " << s.zero << " |";
    md << "\n";
  }
}

}  // namespace monosph
