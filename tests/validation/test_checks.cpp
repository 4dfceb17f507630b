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

TEST(Checks, AMeasureThatCannotBeFormedSaysWhy) {
  // 2 ms of a 5 ms period: no two upward crossings of the mean. The reference counts as reached
  // (a frequency needs no window), so its missing value needs a reason in the summary and the
  // closing lines; before, it was null with none.
  const std::string dir = out_dir("checks_unmeasured");
  auto r =
      run_monosph("run " + source("cases/acoustic_wave/scene.yaml") + " --threads 1 --out " + dir +
                  " --set dp=0.005 end_time=0.002 output.every=0"
                  " 'checks=[{name: ringing, probe: mode, measure: period, max: 1}]'");
  EXPECT_EQ(r.code, 5) << r.output;  // a check that cannot be measured fails
  const auto js = summary(dir);
  const auto& m = js["metrics"]["angular_frequency"];
  EXPECT_TRUE(m["reached"].get<bool>());
  EXPECT_TRUE(m["value"].is_null());
  const std::string why = "fewer than two upward crossings of the mean (found ";
  EXPECT_NE(m["why_no_value"].get<std::string>().find(why), std::string::npos) << m.dump();
  EXPECT_NE(js["checks"]["ringing"]["why_no_value"].get<std::string>().find(why),
            std::string::npos);
  EXPECT_NE(r.output.find("angular_frequency could not be measured from probe 'mode': " + why),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("check ringing = not measured: " + why), std::string::npos) << r.output;
}

}  // namespace
}  // namespace monosph::test
