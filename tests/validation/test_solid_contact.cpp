// Contact between solid bodies of different continua (`solid_contact`, docs/theory.md "Contact
// between solid bodies"): the head-on collision of two equal elastic spheres against Hertz
// (contact duration, restitution, nothing stuck after separation), a block sliding on a block
// against mu N, and the start-up warning for solid bodies that would pass through each other.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "parallel/threads.hpp"
#include "run_helpers.hpp"

using namespace monosph::test;

namespace {

// Quasi-static Hertz impact of two equal spheres (Johnson 1985, Sect. 11.4): mass m, radius R,
// relative speed V; m* = m/2, R* = R/2, 1/E* = 2 (1 - nu^2)/E;
// t_c = 2.868 (m*^2 / (R* E*^2 V))^(1/5).
double hertz_duration(double m, double R, double E, double nu, double V) {
  const double ms = m / 2, rs = R / 2, es = E / (2 * (1 - nu * nu));
  return 2.868 * std::pow(ms * ms / (rs * es * es * V), 0.2);
}

// First and last sample with a non-zero value; the duration between the midpoints to the samples
// around them.
double nonzero_span(const std::vector<double>& t, const std::vector<double>& f) {
  std::size_t a = t.size(), b = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (f[k] != 0) a = std::min(a, k), b = k;
  if (a == t.size() || a == 0 || b + 1 >= t.size()) return std::nan("");
  return 0.5 * (t[b] + t[b + 1]) - 0.5 * (t[a - 1] + t[a]);
}

// Time between the crossings of half the peak of |f| (linear interpolation between samples).
double half_peak_width(const std::vector<double>& t, const std::vector<double>& f) {
  double peak = 0;
  for (double x : f) peak = std::max(peak, std::abs(x));
  std::size_t a = 0, b = 0;
  for (std::size_t k = 0; k < f.size(); ++k)
    if (std::abs(f[k]) >= peak / 2) b = k, a = a ? a : k;
  if (a == 0 || b + 1 >= t.size()) return std::nan("");
  auto cross = [&](std::size_t i, std::size_t j) {
    const double fi = std::abs(f[i]), fj = std::abs(f[j]);
    return t[i] + (peak / 2 - fi) * (t[j] - t[i]) / (fj - fi);
  };
  return cross(b, b + 1) - cross(a - 1, a);
}

// Hertz's force pulse for the impact of hertz_duration: m* d'' = -(4/3) E* sqrt(R*) d^1.5 from
// d = 0, d' = V, integrated in 20000 steps of t_c; returns its half-peak width.
double hertz_half_peak_width(double m, double R, double E, double nu, double V) {
  const double ms = m / 2, k = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * std::sqrt(R / 2);
  const double dt = hertz_duration(m, R, E, nu, V) / 20000;
  std::vector<double> t{0}, f{0};
  for (double d = 0, v = V; d >= 0;) {
    v -= k * std::pow(d, 1.5) / ms * dt, d += v * dt;
    t.push_back(t.back() + dt), f.push_back(k * std::pow(std::max(d, 0.0), 1.5));
  }
  return half_peak_width(t, f);
}

}  // namespace

TEST(SolidContact, SpheresFilledByShellsCollideAsHertz) {
  // tests/scenes/sphere_collision_shells.yaml: spheres round at particle scale (`fill: shells`),
  // 18 across (~30 s on one thread). docs/studies/solid_contact: the half-peak width and peak
  // force converge to Hertz (1.29 / 1.15 / 1.03 / 1.03 and 0.73 / 0.86 / 0.94 / 0.96 at 12, 18,
  // 24, 32 across); the lattice spheres' pole facets keep them at 0.70-0.75 and 1.3-1.5.
  const std::string out = out_dir("solid_contact_shells");
  auto r = run_monosph("run " + source("tests/scenes/sphere_collision_shells.yaml") + " --out " +
                       out + " --quiet --threads 1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const double v0 = 0.5, rho = 1000, E = 1e7, nu = 0.3, R = 0.006, V = 2 * v0;
  const double m = t["left_p_x"][0] / v0;
  EXPECT_NEAR(m, rho * 4.0 / 3.0 * std::numbers::pi * R * R * R, 1e-12);  // exact volumes
  const double width = half_peak_width(t["time"], t["force_x"]);
  EXPECT_NEAR(width / hertz_half_peak_width(m, R, E, nu, V), 1.0, 0.2);  // measured 1.149
  const double ms = m / 2, es = E / (2 * (1 - nu * nu));
  const double dmax = std::pow(15 * ms * V * V / (16 * es * std::sqrt(R / 2)), 0.4);
  const double fh = 4.0 / 3.0 * es * std::sqrt(R / 2) * std::pow(dmax, 1.5);
  const double peak = -min_of(t["force_x"]);
  EXPECT_NEAR(peak / fh, 0.9, 0.1);  // measured 0.857
  const double e = (t["right_vx"].back() - t["left_vx"].back()) / V;
  EXPECT_GT(e, 0.98);  // measured 0.997
  EXPECT_LE(e, 1.0);
  EXPECT_EQ(t["near"].back(), 0.0);           // nothing stuck
  EXPECT_GT(min_of(t["min_distance"]), 0.5);  // measured 0.68 dp
}

TEST(SolidContact, EqualSpheresCollideAsHertzAndSeparateCleanly) {
  // 3D, total-Lagrangian spheres R = 6 dp (12 across) at +-0.5 m/s, Hertz delta_max/R = 0.048
  // (tests/scenes; ~10 s on one thread).
  const std::string out = out_dir("solid_contact_spheres");
  auto r = run_monosph("run " + source("tests/scenes/sphere_collision.yaml") + " --out " + out +
                       " --quiet --threads 1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const double v0 = 0.5, rho = 1000, E = 1e7, nu = 0.3;
  const double m = t["left_p_x"][0] / v0, R = std::cbrt(3 * m / (4 * std::numbers::pi * rho));
  const double tc = hertz_duration(m, R, E, nu, 2 * v0);
  const double dur = nonzero_span(t["time"], t["force_x"]);
  // Measured 0.702 (0.64-0.74 at 12-24 across and two lattice alignments,
  // docs/studies/solid_contact): shorter than Hertz. The lattice flattens the sphere's pole into a
  // facet of radius ~sqrt(R dp) = 2.4 dp, larger than the Hertz contact radius (0.93 dp): the
  // contact starts as a flat punch, stiffer than a sphere.
  EXPECT_GT(dur / tc, 0.65);
  EXPECT_LT(dur / tc, 0.75);
  // Peak force against Hertz 4/3 E* sqrt(R*) delta_max^1.5: measured 1.36.
  const double ms = m / 2, es = E / (2 * (1 - nu * nu)), V = 2 * v0;
  const double dmax = std::pow(15 * ms * V * V / (16 * es * std::sqrt(R / 2)), 0.4);
  const double fh = 4.0 / 3.0 * es * std::sqrt(R / 2) * std::pow(dmax, 1.5);
  const double peak = -min_of(t["force_x"]);  // on the left sphere: along -x
  EXPECT_GT(peak / fh, 1.2);
  EXPECT_LT(peak / fh, 1.5);
  const double e = (t["right_vx"].back() - t["left_vx"].back()) / (2 * v0);
  EXPECT_GT(e, 0.99);  // measured 0.9990 (waves left in the spheres take the rest)
  EXPECT_LE(e, 1.0);
  EXPECT_NEAR(t["left_vx"].back(), -t["right_vx"].back(), 1e-9);  // exactly opposite forces
  // Nothing stuck: no particle of one sphere within the kernel support of the other at the end
  // (from 2.19 ms on).
  EXPECT_EQ(t["near"].back(), 0.0);
  EXPECT_GT(min_of(t["min_distance"]), 0.8);  // measured 0.866 dp
}

TEST(SolidContact, SphereCollisionIsBitIdenticalOnOneAndTwoThreads) {
  // 150 steps of tests/scenes/sphere_collision.yaml (in contact from step 2): every field of the
  // final checkpoint bit for bit (each particle sums its own side of its pairs; the pair counts
  // are integer sums, the step a max).
  const std::string args =
      "run " + source("tests/scenes/sphere_collision.yaml") + " --quiet --steps 150 --out ";
  const std::string a = out_dir("solid_contact_threads1"), b = out_dir("solid_contact_threads2");
  if (monosph::usable_cpus() < 2) GTEST_SKIP() << "one usable CPU: no second thread";
  ASSERT_EQ(run_monosph(args + a + " --threads 1").code, 0);
  ASSERT_EQ(run_monosph(args + b + " --threads 2 --fixed-threads").code, 0);
  expect_two_threads(b);
  monosph::Particles<3> pa, pb;
  auto ma = monosph::read_checkpoint<3>(a + "/final.h5", pa);
  auto mb = monosph::read_checkpoint<3>(b + "/final.h5", pb);
  EXPECT_EQ(ma.step, 150);
  EXPECT_EQ(ma.time, mb.time);
  EXPECT_EQ(ma.scalars, mb.scalars);
  ASSERT_EQ(pa.size(), pb.size());
  for (const auto& f : pa.fields()) {
    EXPECT_EQ(f.real, pb.field(f.name).real) << f.name;
    EXPECT_EQ(f.ints, pb.field(f.name).ints) << f.name;
  }
  auto t = read_csv(b + "/probes.csv");
  EXPECT_GT(max_of(t["pairs"]), 0.0);  // the contact acted
}

TEST(SolidContact, SlidingBlockFeelsMuTimesTheNormalForce) {
  // 2D Eulerian blocks (jittered lattices), mu = 0.3, pressed by a body force, launched at 5 m/s
  // (tests/scenes): the mean contact force on the top block while it slides, F_t / N.
  auto ratio = [](const std::string& name, const std::string& set) {
    const std::string out = out_dir(name);
    auto r = run_monosph("run " + source("tests/scenes/sliding_blocks.yaml") + " --out " + out +
                         " --quiet --threads 1" + set);
    EXPECT_EQ(r.code, 0) << r.output;
    auto t = read_csv(out + "/probes.csv");
    double fx = 0, fy = 0;
    int n = 0;
    for (std::size_t k = 0; k < t["time"].size(); ++k)
      if (t["time"][k] > 0.5e-3 && t["top_vx"][k] > 0.5)
        fx += t["force_x"][k], fy += t["force_y"][k], ++n;
    EXPECT_GT(n, 100);
    EXPECT_NEAR(fy / n, 600.0, 120.0);  // N = m g = 0.12 kg/m x 5000 m/s^2; measured 592
    return -fx / fy;
  };
  // Measured 0.357: mu plus the lattice corrugation (0.031 without friction) and the pitching
  // of the block under the friction torque.
  EXPECT_NEAR(ratio("solid_contact_sliding", "") / 0.3, 1.0, 0.25);
  EXPECT_LT(std::abs(ratio("solid_contact_sliding_mu0", " --set solid_contact.friction=0")), 0.06);
}

// Two discs of different continua, 4 dp apart; `left` moves at `speed` towards `right`.
std::string two_discs(const std::string& out, const std::string& speed, const std::string& extra) {
  std::filesystem::create_directories(out);
  const std::string path = out + "/discs.yaml";
  std::ofstream(path) << R"(name: discs
dimension: 2
dp: 0.001
domain: {min: [-0.02, -0.01], max: [0.02, 0.01]}
materials:
  soft: {density: 1000, bulk_modulus: 8.3e6, shear_modulus: 3.8e6}
bodies:
  - {name: left, phase: solid, material: soft, shape: {circle: {center: [-0.007, 0], radius: 0.005}}, initial: {velocity: [)"
                      << speed << R"(, 0]}}
  - {name: right, phase: solid, material: soft, shape: {circle: {center: [0.007, 0], radius: 0.005}}}
end_time: 1.0e-3
)" << extra;
  return path;
}

TEST(SolidContact, WarnsOnceWhenSolidBodiesWouldPassThroughEachOther) {
  // The left disc reaches the right one within end_time (4 m/s x 1 ms = 4 mm): one warning line
  // on stderr naming both; none with solid_contact, none when it stays away (0.1 m/s).
  auto stderr_of = [](const std::string& name, const std::string& speed, const std::string& extra) {
    const std::string out = out_dir(name);
    const std::string scene = two_discs(out, speed, extra + "\n");
    return run_command(std::string(MONOSPH_BIN) + " run " + scene +
                       " --quiet --threads 1 --steps 2 --out " + out + "/run 2>&1 >/dev/null");
  };
  auto r = stderr_of("warn_meet", "4.0", "");
  EXPECT_NE(
      r.output.find("warning: solid bodies 'left' and 'right' may meet but will pass through"),
      std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("warning", r.output.find("warning") + 1), std::string::npos)
      << r.output;  // one line (the other is --quiet's status line)
  auto r2 = stderr_of("warn_contact", "4.0", "solid_contact: {distance: 1.0}");
  EXPECT_EQ(r2.output.find("warning"), std::string::npos) << r2.output;
  auto r3 = stderr_of("warn_apart", "0.1", "");
  EXPECT_EQ(r3.output.find("warning"), std::string::npos) << r3.output;
}

TEST(SolidContact, RubberRingsAsTwoContinuaReboundAndSeparate) {
  // cases/rubber_rings/scene_contact.yaml (rings filled by shells; full run, ~11 s on one lightly
  // loaded thread): measured restitution 0.809 (shared continuum 0.790), smallest distance 0.496 dp
  // (0.339 with the lattice fill).
  const std::string out = out_dir("rings_contact");
  auto r = run_monosph("run " + source("cases/rubber_rings/scene_contact.yaml") + " --out " + out +
                       " --quiet --threads 1 --set output.every=1");
  ASSERT_EQ(r.code, 0) << r.output;
  auto t = read_csv(out + "/probes.csv");
  const double e = (t["right_vx"].back() - t["left_vx"].back()) / (2 * 7.071);
  EXPECT_GT(e, 0.75);
  EXPECT_LT(e, 0.85);
  EXPECT_GT(min_of(t["min_distance"]), 0.4);
  EXPECT_LT(max_of(t["disorder"]), 0.05);
  EXPECT_EQ(t["ring_neighbours"].back(), 0.0);  // apart at the end: nothing stuck
}
