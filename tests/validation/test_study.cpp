// `monosph study`: every combination runs, its error and wall time land in study.csv/md/png;
// bad --vary input fails before any run; a missing gnuplot still leaves the CSV.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_helpers.hpp"

namespace monosph::test {
namespace {

// study.csv with text columns (status): values as strings, numbers through num().
struct TextTable {
  std::vector<std::string> head;
  std::vector<std::vector<std::string>> rows;
  std::string at(std::size_t r, const std::string& col) const {
    for (std::size_t k = 0; k < head.size(); ++k)
      if (head[k] == col) return rows.at(r).at(k);
    throw std::runtime_error("no column " + col);
  }
  double num(std::size_t r, const std::string& col) const { return std::stod(at(r, col)); }
};

TextTable read_text_csv(const std::string& file) {
  TextTable t;
  std::ifstream in(file);
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> v;
    std::stringstream ss(l);
    for (std::string c; std::getline(ss, c, ',');) v.push_back(c);
    if (!l.empty() && l.back() == ',') v.push_back("");
    return v;
  };
  if (std::getline(in, line)) t.head = split(line);
  while (std::getline(in, line)) t.rows.push_back(split(line));
  return t;
}

TEST(Study, AcousticWaveAtTwoResolutionsWritesCsvTableAndPlot) {
  const std::string out = out_dir("study_acoustic");
  auto r = run_monosph("study " + source("cases/acoustic_wave/scene.yaml") +
                       " --vary dp=0.005,0.0025 --jobs 2 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_text_csv(out + "/study.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.num(0, "dp"), 0.005);
  EXPECT_EQ(t.num(0, "particles"), 200);
  EXPECT_EQ(t.num(1, "particles"), 800);
  // The error of each run is the one its own summary reports, and it shrinks with dp here.
  const std::vector<std::string> dirs{"/run00_dp-0.005", "/run01_dp-0.0025"};
  for (std::size_t k = 0; k < 2; ++k) {
    auto js = summary(out + dirs[k]);
    EXPECT_NEAR(t.num(k, "angular_frequency_relative_error"),
                js["metrics"]["angular_frequency"]["relative_error"].get<double>(), 1e-8);
    EXPECT_GT(t.num(k, "wall_seconds"), 0);
    EXPECT_EQ(t.at(k, "status"), "completed");
  }
  EXPECT_LT(t.num(1, "angular_frequency_relative_error"),
            t.num(0, "angular_frequency_relative_error"));
  EXPECT_TRUE(std::filesystem::exists(out + "/study.md"));
  EXPECT_GT(std::filesystem::file_size(out + "/study.png"), 1000u);
}

TEST(Study, StabilisationVariantsSetEverySolidBody) {
  const std::string out = out_dir("study_plate");
  auto r = run_monosph("study " + source("cases/oscillating_plate/scene.yaml") +
                       " --vary stabilisation=none,hourglass --set end_time=1e-4 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_text_csv(out + "/study.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.at(0, "stabilisation"), "none");
  EXPECT_EQ(t.at(1, "stabilisation"), "hourglass");
  EXPECT_GT(t.num(0, "particle_steps_per_second"), 0);
  std::ifstream md(out + "/study.md");
  std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("| none |"), std::string::npos) << text;
  EXPECT_NE(text.find("| hourglass |"), std::string::npos) << text;
}

TEST(Study, BadVaryFailsBeforeAnyRun) {
  const std::string out = out_dir("study_bad");
  auto a = run_monosph("study " + source("cases/acoustic_wave/scene.yaml") +
                       " --vary dpp=0.005,0.0025 --out " + out);
  EXPECT_EQ(a.code, 2) << a.output;
  EXPECT_NE(a.output.find("dpp"), std::string::npos) << a.output;
  EXPECT_FALSE(std::filesystem::exists(out + "/run00_dpp-0.005/summary.json"));
  auto b = run_monosph("study " + source("cases/acoustic_wave/scene.yaml") +
                       " --vary stabilisation=none --out " + out);
  EXPECT_EQ(b.code, 2) << b.output;
  EXPECT_NE(b.output.find("no solid body"), std::string::npos) << b.output;
  auto c = run_monosph("study " + source("cases/acoustic_wave/scene.yaml") +
                       " --vary dp=0.005,0.0025 --metric typo --out " + out);
  EXPECT_EQ(c.code, 2) << c.output;
}

// Seeded runs (tests/scenes/seeded_block.yaml: start, lattice turn and speed from
// uniform(seed, k)): three seeds at two speeds give two rows of statistics over three runs each,
// and a seed run again gives the same value bit for bit.
TEST(Study, RepeatedSeedsGiveStatisticsPerCombinationAndAreReproducible) {
  const std::string out = out_dir("study_repeat");
  const std::string scene = source("tests/scenes/seeded_block.yaml");
  auto r = run_monosph("study " + scene +
                       " --vary variables.seed=1,2,3 --vary variables.speed=1,2 --repeat "
                       "variables.seed --jobs 2 --out " +
                       out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_text_csv(out + "/study.csv").rows.size(), 6u);
  auto t = read_text_csv(out + "/study_stats.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.head.front(), "variables.speed");
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(t.at(k, "variables.speed"), k == 0 ? "1" : "2");
    EXPECT_EQ(t.num(k, "n"), 3);
    EXPECT_EQ(t.num(k, "failed"), 0);
    EXPECT_GT(t.num(k, "ke_std"), 0);  // the seed changes the speed
    EXPECT_LT(t.num(k, "ke_ci95_low"), t.num(k, "ke_mean"));
    EXPECT_GT(t.num(k, "ke_ci95_high"), t.num(k, "ke_mean"));
    EXPECT_EQ(t.num(k, "ke_zero"), 0);
  }
  // The mean of speed 1 is the mean of its three runs' values.
  double sum = 0;
  for (const char* d :
       {"/run00_variables.seed-1_variables.speed-1", "/run01_variables.seed-2_variables.speed-1",
        "/run02_variables.seed-3_variables.speed-1"})
    sum += summary(out + d)["metrics"]["ke"]["value"].get<double>();
  EXPECT_NEAR(t.num(0, "ke_mean"), sum / 3, 1e-8 * sum);
  std::ifstream md(out + "/study.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("## Statistics over variables.seed"), std::string::npos);
  // Seed 2 at speed 1 again: the same kinetic energy, bit for bit.
  const std::string again = out_dir("study_repeat_again");
  auto a = run_monosph("run " + scene +
                       " --set variables.seed=2 --set variables.speed=1 --quiet --out " + again);
  ASSERT_EQ(a.code, 0) << a.output;
  EXPECT_EQ(summary(again)["metrics"]["ke"]["value"].get<double>(),
            summary(out + "/run01_variables.seed-2_variables.speed-1")["metrics"]["ke"]["value"]
                .get<double>());
}

TEST(Study, RepeatMustNameAVariedKey) {
  const std::string out = out_dir("study_repeat_bad");
  auto r = run_monosph("study " + source("tests/scenes/seeded_block.yaml") +
                       " --vary variables.speed=1,2 --repeat variables.seed --out " + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--repeat variables.seed is not one of the --vary keys"),
            std::string::npos)
      << r.output;
}

TEST(Study, WithoutGnuplotSaysSoAndKeepsTheCsv) {
  const std::string out = out_dir("study_nognuplot");
  auto r = run_command("PATH=/nonexistent " + std::string(MONOSPH_BIN) + " study " +
                       source("cases/acoustic_wave/scene.yaml") + " --vary dp=0.005 --out " + out +
                       " 2>&1");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("gnuplot not found"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out + "/study.csv"));
  EXPECT_FALSE(std::filesystem::exists(out + "/study.png"));
}

}  // namespace
}  // namespace monosph::test
