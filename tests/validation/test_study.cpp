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
