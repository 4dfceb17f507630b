// `monosph bench --suite`: every kind of scene measured, the slowest pass named, JSON written and
// a block appended to the markdown file (timings themselves are not asserted).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "run_helpers.hpp"

namespace monosph::test {
namespace {

TEST(BenchSuite, QuickSuiteMeasuresSixKindsOfSceneAndAppendsARowBlock) {
  const std::string dir = out_dir("bench_suite");
  std::filesystem::create_directories(dir);
  const std::string md = dir + "/performance.md";
  std::ofstream(md) << "# Performance\n";
  auto r = run_monosph("bench --suite --quick --steps 3 --threads 1 --json " + dir +
                       "/suite.json --append " + md);
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream js(dir + "/suite.json");
  auto j = nlohmann::json::parse(js);
  ASSERT_EQ(j["suite"].size(), 6u);
  for (const auto& row : j["suite"]) {
    EXPECT_GT(row["particles"].get<long>(), 5000) << row["case"];
    EXPECT_EQ(row["steps"], 3);
    EXPECT_GT(row["particle_steps_per_second"].get<double>(), 0);
    const std::string slow = row["slowest_pass"];
    EXPECT_TRUE(row["ns_per_particle_step_by_pass"].contains(slow)) << slow;
    for (const char* pass : {"integration", "neighbours", "pair_cache", "sums", "forces"})
      EXPECT_TRUE(row["ns_per_particle_step_by_pass"].contains(pass)) << pass;
  }
  // The machine's triad bandwidth in the cache (8 MiB) and in main memory (512 MiB).
  ASSERT_EQ(j["memory_bandwidth"].size(), 2u);
  for (const auto& b : j["memory_bandwidth"]) {
    EXPECT_EQ(b["threads"], 1);
    EXPECT_GT(b["gb_per_s"].get<double>(), 0.1) << b["mib"];
  }
  EXPECT_EQ(j["memory_bandwidth"][0]["mib"], 8);
  EXPECT_EQ(j["memory_bandwidth"][1]["mib"], 512);
  std::ifstream in(md);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str().rfind("# Performance\n", 0), 0u);  // appended, not overwritten
  EXPECT_NE(text.str().find("### `monosph bench --suite`"), std::string::npos);
  EXPECT_NE(text.str().find("| 3D solid (Taylor bar) |"), std::string::npos);
  EXPECT_NE(text.str().find("| 3D solid, total Lagrangian (Taylor bar) |"), std::string::npos);
  EXPECT_NE(text.str().find("memory bandwidth (STREAM triad, GB/s): 8 MiB on 1 thread"),
            std::string::npos);
}

TEST(BenchScene, JsonRowsHoldTheTimeOfEveryPass) {
  const std::string dir = out_dir("bench_scene");
  std::filesystem::create_directories(dir);
  auto r = run_monosph("bench --scene " + source("cases/oscillating_plate/scene.yaml") +
                       " --steps 3 --threads 1 --json " + dir + "/bench.json");
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream js(dir + "/bench.json");
  auto j = nlohmann::json::parse(js);
  ASSERT_EQ(j["results"].size(), 1u);
  const auto& row = j["results"][0];
  EXPECT_EQ(row["steps"], 3);
  double sum = 0;
  for (const char* pass : {"integration", "neighbours", "pair_cache", "sums", "forces"}) {
    ASSERT_TRUE(row["ns_per_particle_step_by_pass"].contains(pass)) << pass;
    sum += row["ns_per_particle_step_by_pass"][pass].get<double>();
  }
  // The passes are inside the timed steps: together not above the wall time per particle-step.
  const double wall_ns =
      1e9 * row["wall_seconds"].get<double>() / (3.0 * row["particles"].get<double>());
  EXPECT_GT(sum, 0);
  EXPECT_LE(sum, wall_ns * 1.0001);
}

}  // namespace
}  // namespace monosph::test
