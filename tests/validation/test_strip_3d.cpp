// 3D bending with a few particles through the thickness (cases/oscillating_strip_3d, issue 27):
// short versions of the studies in docs/studies/strip_3d (the strip cantilever and the strip
// clamped at both ends, 3 and 4 particles through the thickness, 1.4 periods), and the bad
// values of domain.mirror. The mirror's half-against-full checks are unit tests (test_mirror.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../mpi/mpi_helpers.hpp"
#include "run_helpers.hpp"

using namespace monosph::test;

namespace {
// Signed period error of a run of the case: (T - T_ref) / T_ref, T_ref the Euler-Bernoulli value.
double period_error(const std::string& scene, const std::string& name, const std::string& set) {
  const std::string out = out_dir("strip3d_" + name);
  auto r = run_monosph("run " + source("cases/oscillating_strip_3d/" + scene) + " --out " + out +
                       " --quiet --threads 1 --set output.every=1 " + set);
  EXPECT_EQ(r.code, 0) << r.output;
  if (r.code != 0) return NAN;
  auto js = summary(out);
  const double t = js["metrics"]["period"]["value"].get<double>();
  const double ref = js["metrics"]["period"]["reference"].get<double>();
  auto tab = read_csv(out + "/probes.csv");
  EXPECT_GT(min_of(tab["min_distance"]), 0.9);  // no particle pairing (in dp); measured >= 0.98
  EXPECT_LT(max_of(tab["disorder"]), 0.02);     // measured <= 0.004 dp
  return (t - ref) / ref;
}
const std::string n3 = "dp=0.006666666666666667", n4 = "dp=0.005";
}  // namespace

TEST(Strip3d, TotalLagrangianAlpha25CantileverWithinFivePercentAtFourThroughThickness) {
  // Total-Lagrangian SPH with the hourglass alpha = 25 of cases/beam_bending (G15's best order):
  // the recommended formulation for thin 3D structures. Measured -3.4 % (T = 0.2675 s against
  // 0.27695 s); with the oscillating plate's alpha = 5: +20.0 %.
  const double e = period_error("scene_tlsph.yaml", "tl25_n4", n4 + " bodies.0.hourglass.alpha=25");
  EXPECT_LT(std::abs(e), 0.05);
}

TEST(Strip3d, TotalLagrangianAlpha25ClampedClampedAtFourThroughThickness) {
  // The strip clamped at both ends (L/h = 20), alpha = 25: measured -5.51 % (T = 0.16450 s
  // against Euler-Bernoulli's 0.17409 s). Against the complete reference, Timoshenko with the
  // mid-plane stretching of this release (0.17056 s, docs/studies/strip_3d): -3.56 %. The bound
  // records the measured value against Euler-Bernoulli.
  const double e =
      period_error("cc_scene_tlsph.yaml", "tl25_cc_n4", n4 + " bodies.0.hourglass.alpha=25");
  EXPECT_GT(e, -0.07);
  EXPECT_LT(e, -0.04);
}

TEST(Strip3d, EulerianCantileverConvergesFromThreeToFourThroughThickness) {
  // MMB hourglass control xi = 0.5, Newmark gamma = 0.6 (the oscillating plate's settings):
  // measured +29.8 % at 3 and +17.5 % at 4 through the thickness (order 1.85); too soft, as the
  // 2D plate at the same resolution (order 1.6 from 10 to 20 across).
  const double e3 = period_error("scene.yaml", "eul_n3", n3);
  const double e4 = period_error("scene.yaml", "eul_n4", n4);
  EXPECT_GT(e3, 0.2);
  EXPECT_LT(e3, 0.4);
  EXPECT_GT(e4, 0.1);
  EXPECT_LT(e4, 0.25);
  EXPECT_GT(std::log(e3 / e4) / std::log(4.0 / 3.0), 1.0);  // observed order
}

TEST(Strip3d, MirrorBadValuesNameTheKey) {
  const std::string scene = "run " + source("cases/oscillating_strip_3d/scene.yaml") +
                            " --quiet --steps 1 --out " + out_dir("strip3d_bad");
  for (const char* set : {"'domain.mirror=[w_min]'", "'domain.mirror=[z_mid]'"}) {
    auto r = run_monosph(scene + " --set " + set);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("domain.mirror"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  auto p = run_monosph(scene + " --set 'domain.periodic=[z]' 'domain.mirror=[z_min]'");
  EXPECT_EQ(p.code, 2) << p.output;
  EXPECT_NE(p.output.find("periodic axis"), std::string::npos) << p.output;
  // Total-Lagrangian bodies take one plane per axis (their reference neighbours hold one image
  // per plane; two parallel planes would need images of images).
  auto t = run_monosph("run " + source("cases/oscillating_strip_3d/scene_tlsph.yaml") +
                       " --quiet --steps 1 --out " + out_dir("strip3d_bad_tl") +
                       " --set 'domain.mirror=[z_min, z_max]'");
  EXPECT_EQ(t.code, 2) << t.output;
  EXPECT_NE(t.output.find("domain.mirror: total_lagrangian bodies take one plane per axis"),
            std::string::npos)
      << t.output;
}

TEST(Strip3d, MirrorOnTwoRanksIsAOneLineError) {
  auto r = mpirun(2, "run " + source("cases/oscillating_strip_3d/scene.yaml") +
                         " --quiet --threads 1 --steps 1 --out " + out_dir("strip3d_mpi") +
                         " --set 'domain.mirror=[z_max]'");
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("monosph: error: domain.mirror: not supported on more than one MPI rank"),
            std::string::npos)
      << r.output;
}
