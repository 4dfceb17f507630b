// Scene `checks`: pass criteria a run evaluates itself (summary.json, exit code 5 on a failure).
#include <gtest/gtest.h>

#include "run_helpers.hpp"

namespace monosph::test {
namespace {

const std::string wave = "run " + source("cases/acoustic_wave/scene.yaml") + " --quiet";

TEST(Checks, PassingAndFailingCriteriaAreReportedAndSetTheExitCode) {
  const std::string ok = out_dir("checks_ok");
  auto a = run_monosph(wave + " --out " + ok +
                       " --set 'checks=[{name: mass_kept, probe: mass, measure: drift, max: 1e-12},"
                       " {name: energy_bounded, probe: kinetic_energy, measure: max, min: 0,"
                       " max: 1e-3}]'");
  ASSERT_EQ(a.code, 0) << a.output;
  auto js = summary(ok);
  EXPECT_TRUE(js["checks_passed"].get<bool>());
  EXPECT_EQ(js["checks"]["mass_kept"]["value"].get<double>(), 0.0);  // every particle keeps m
  EXPECT_GT(js["checks"]["energy_bounded"]["value"].get<double>(), 1e-5);

  const std::string bad = out_dir("checks_fail");
  auto b = run_monosph(wave + " --out " + bad +
                       " --set 'checks=[{name: too_quiet, probe: kinetic_energy, measure: max,"
                       " max: 1e-12}]'");
  EXPECT_EQ(b.code, 5) << b.output;
  auto jb = summary(bad);
  EXPECT_FALSE(jb["checks_passed"].get<bool>());
  EXPECT_FALSE(jb["checks"]["too_quiet"]["pass"].get<bool>());
}

TEST(Checks, AStoppedRunFailsItsChecks) {
  const std::string dir = out_dir("checks_stopped");
  auto r = run_monosph("run " + source("cases/dam_break/scene.yaml") + " --quiet --out " + dir +
                       " --set materials.water.sound_speed=1 end_time=0.1"
                       " 'checks=[{name: front_moves, probe: front, measure: max, min: 0}]'");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_FALSE(summary(dir)["checks"]["front_moves"]["pass"].get<bool>());
}

TEST(Checks, MalformedChecksNameTheKey) {
  const std::string dir = out_dir("checks_bad");
  auto a = run_monosph(wave + " --out " + dir +
                       " --set 'checks=[{name: x, probe: mass, measure: drift}]'");
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.output.find("checks[0]: give min, max or both"), std::string::npos) << a.output;
  auto b = run_monosph(wave + " --out " + dir +
                       " --set 'checks=[{name: x, probe: masss, measure: drift, max: 1}]'");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.output.find("checks[0].probe"), std::string::npos) << b.output;
}

}  // namespace
}  // namespace monosph::test
