// `monosph stability`: the reduced suite passes; failures and bad input are reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_helpers.hpp"

namespace monosph::test {
namespace {

nlohmann::json read_json(const std::string& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(Stability, ReducedSuitePasses) {
  const std::string dir = out_dir("stability_quick");
  auto r = run_monosph("stability --quick --jobs 2 --threads 1 --out " + dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("failed"), std::string::npos) << r.output;  // the summary line
  auto js = read_json(dir + "/stability.json");
  for (const char* scene : {"steel_plate", "rubber_plate", "rubber_rings_fast", "taylor_bar_400",
                            "grain_impact", "dam_break_stiff", "plate_30_periods"}) {
    ASSERT_TRUE(js.contains(scene)) << scene;
    EXPECT_EQ(js[scene]["status"], "completed") << scene;
    EXPECT_GE(js[scene]["checks"].size(), 4u) << scene;
    for (const auto& [name, c] : js[scene]["checks"].items())
      EXPECT_TRUE(c["pass"].get<bool>()) << scene << " " << name << " = " << c["value"];
  }
}

TEST(Stability, AFailedCheckFailsTheSuite) {
  const std::string dir = out_dir("stability_fail");
  const std::string suite = dir + "/suite.yaml";
  std::filesystem::create_directories(dir);
  std::ofstream(suite) << "scenes:\n  - scene: " << source("cases/acoustic_wave/scene.yaml")
                       << "\n    quick: ['checks=[{name: too_quiet, probe: kinetic_energy, "
                          "measure: max, max: 1e-12}]']\n";
  auto r = run_monosph("stability --quick --suite " + suite + " --out " + dir);
  EXPECT_EQ(r.code, 5) << r.output;
  EXPECT_NE(r.output.find("too_quiet"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAIL"), std::string::npos) << r.output;
  EXPECT_FALSE(read_json(dir + "/stability.json")["acoustic_wave"]["checks"]["too_quiet"]["pass"]
                   .get<bool>());
}

TEST(Stability, BadInputNamesTheProblem) {
  const std::string dir = out_dir("stability_bad");
  auto a = run_monosph("stability --only no_such_scene --out " + dir);
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.output.find("--only no_such_scene"), std::string::npos) << a.output;
  const std::string suite = dir + "/suite.yaml";
  std::filesystem::create_directories(dir);
  std::ofstream(suite) << "scenes:\n  - scene: x.yaml\n    quik: [end_time=1]\n";
  auto b = run_monosph("stability --suite " + suite + " --out " + dir);
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.output.find("scenes[0]"), std::string::npos) << b.output;
  EXPECT_NE(b.output.find("quick"), std::string::npos) << b.output;  // did you mean
}

}  // namespace
}  // namespace monosph::test
