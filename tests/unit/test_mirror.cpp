// Symmetry planes (domain.mirror, src/core/mirror.hpp): a half (quarter) model with mirror planes
// gives the full model's motion; the interpolated normal velocity vanishes on the plane; the
// momentum along the plane is conserved.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim_helpers.hpp"
#include "thread_helpers.hpp"

using namespace monosph;

namespace {

// A 3D cantilever strip (h = b = 0.02 m, l = 0.1 m, 4 particles through the thickness) in its
// first bending mode; the width runs along z over [zlo, 0.01].
std::string strip(const std::string& zlo, const std::string& extra, bool enog,
                  const std::string& solid = "hourglass: {xi: 0.5}") {
  const std::string body = enog ? "formulation: non_hourglass" : solid;
  return R"(
name: mirror_strip
dimension: 3
dp: 0.005
kernel: {type: )" +
         std::string(enog ? "wendland_c2" : "cubic_spline") + R"(, h_factor: 1.3}
domain: {min: [-0.04, -0.05, )" +
         (zlo == "0" ? "0" : "-0.03") + R"(], max: [0.13, 0.05, 0.03])" + extra + R"(}
materials:
  soft: {density: 1000, bulk_modulus: 3.25e6, shear_modulus: 0.715e6}
bodies:
  - name: strip
    phase: solid
    material: soft
    shape: {box: {min: [-0.02, -0.01, )" +
         zlo + R"(], max: [0.1, 0.01, 0.01]}}
    )" + body +
         R"(
    initial:
      velocity_profile: {type: cantilever_mode, amplitude: 0.285, clamp: 0.0, length: 0.1, kl: 1.8751}
boundary_conditions:
  - {name: clamp, type: fixed, region: {box: {min: [-0.04, -0.011, -0.011], max: [0.0, 0.011, 0.011]}}}
end_time: 1
time_step: {cfl: 0.3)" +
         (enog ? "" : ", newmark_gamma: 0.6") + "}\n";
}

// For each owned particle of `part`, the index in `full` of the particle with the nearest
// initial position (taken before the first step, when both lattices are exact).
template <int D>
std::vector<std::size_t> match(Simulation<D>& part, Simulation<D>& full) {
  auto xp = part.particles().x();
  auto xf = full.particles().x();
  std::vector<std::size_t> m(part.owned());
  for (std::size_t i = 0; i < part.owned(); ++i) {
    double best = 1e300;
    for (std::size_t j = 0; j < full.owned(); ++j) {
      const double d = (xp[i] - xf[j]).squaredNorm();
      if (d < best) best = d, m[i] = j;
    }
  }
  return m;
}

// Largest |x_part - x_full| and |v_part - v_full| over the matched particles, by id.
template <int D>
std::pair<double, double> difference(Simulation<D>& part, Simulation<D>& full,
                                     const std::vector<std::int64_t>& idp,
                                     const std::vector<std::int64_t>& idf) {
  auto& pp = part.particles();
  auto& pf = full.particles();
  std::vector<long> at(pf.next_id() + 1, -1);
  for (std::size_t j = 0; j < full.owned(); ++j) at[pf.id()[j]] = static_cast<long>(j);
  std::vector<long> want(pp.next_id() + 1, -1);  // id in part -> id in full
  for (std::size_t k = 0; k < idp.size(); ++k) want[idp[k]] = idf[k];
  double dx = 0, dv = 0;
  for (std::size_t i = 0; i < part.owned(); ++i) {
    const long j = at[want[pp.id()[i]]];
    dx = std::max(dx, (pp.x()[i] - pf.x()[j]).norm());
    dv = std::max(dv, (pp.v()[i] - pf.v()[j]).norm());
  }
  return {dx, dv};
}

// Runs the half and the full model side by side to time t; returns the largest position and
// velocity differences.
template <int D>
std::pair<double, double> half_against_full(Simulation<D>& half, Simulation<D>& full, double t) {
  auto m = match(half, full);
  std::vector<std::int64_t> idp(half.owned()), idf(half.owned());
  for (std::size_t i = 0; i < half.owned(); ++i)
    idp[i] = half.particles().id()[i], idf[i] = full.particles().id()[m[i]];
  while (half.time() < t) half.advance(t);
  while (full.time() < t) full.advance(t);
  EXPECT_EQ(half.step(), full.step());  // the same time steps (the same largest speeds)
  return difference(half, full, idp, idf);
}

}  // namespace

TEST(Mirror, HalfStripEqualsFullStripEulerian) {
  // Mirror at mid-width (z = 0) against the full strip, 0.03 s (about 1000 steps, a quarter of
  // the first period's swing). Measured: |dx| 2e-17 m, |dv| 5e-15 m/s (round-off of the sum
  // order); the tip has moved 0.0027 m.
  auto half = test::build<3>(strip("0", ", mirror: [z_min]", false));
  auto full = test::build<3>(strip("-0.01", "", false));
  EXPECT_EQ(half->owned() * 2, full->owned());
  EXPECT_GT(half->particles().size(), half->owned());  // the images
  auto [dx, dv] = half_against_full(*half, *full, 0.03);
  std::printf("half vs full strip (Eulerian): |dx| %.3g m, |dv| %.3g m/s\n", dx, dv);
  EXPECT_LT(dx, 1e-12);
  EXPECT_LT(dv, 1e-9);
}

TEST(Mirror, HalfStripEqualsFullStripNonHourglass) {
  auto half = test::build<3>(strip("0", ", mirror: [z_min]", true));
  auto full = test::build<3>(strip("-0.01", "", true));
  auto [dx, dv] = half_against_full(*half, *full, 0.03);
  std::printf("half vs full strip (non-hourglass): |dx| %.3g m, |dv| %.3g m/s\n", dx, dv);
  EXPECT_LT(dx, 1e-12);
  EXPECT_LT(dv, 1e-9);
}

TEST(Mirror, HalfStripEqualsFullStripTotalLagrangian) {
  // The reference neighbours of the half strip include the images across z = 0: the full strip's
  // reference pairs, corrections and forces (G15 Eq. 24, 32) within round-off.
  const std::string tl = "formulation: total_lagrangian\n    hourglass: {alpha: 25}";
  auto half = test::build<3>(strip("0", ", mirror: [z_min]", false, tl));
  auto full = test::build<3>(strip("-0.01", "", false, tl));
  auto [dx, dv] = half_against_full(*half, *full, 0.03);
  std::printf("half vs full strip (total-Lagrangian): |dx| %.3g m, |dv| %.3g m/s\n", dx, dv);
  EXPECT_LT(dx, 1e-12);
  EXPECT_LT(dv, 1e-9);
}

TEST(Mirror, ResultsIndependentOfThreadCount) {
  const int before = omp_get_max_threads();
  std::vector<std::vector<Vec<3>>> x(2);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(test::team_size(), threads);
    auto half = test::build<3>(strip("0", ", mirror: [z_min]", false));
    while (half->time() < 0.003) half->advance(0.003);
    auto xs = half->particles().x();
    x[threads - 1].assign(xs.begin(), xs.begin() + half->owned());
  }
  omp_set_num_threads(before);
  ASSERT_EQ(x[0].size(), x[1].size());
  for (std::size_t i = 0; i < x[0].size(); ++i) ASSERT_EQ(x[0][i], x[1][i]) << i;
}

namespace {
// A free 3D block, 4 x 4 x 4 particles, on the mirror plane z = 0, moving along x and into the
// plane.
const char* block = R"(
name: mirror_block
dimension: 3
dp: 0.005
domain: {min: [-0.05, -0.05, 0], max: [0.1, 0.05, 0.05], mirror: [z_min]}
materials:
  soft: {density: 1000, bulk_modulus: 3.25e6, shear_modulus: 0.715e6}
bodies:
  - name: block
    phase: solid
    material: soft
    shape: {box: {min: [0, -0.01, 0], max: [0.02, 0.01, 0.02]}}
    hourglass: {xi: 0.5}
    initial:
      velocity: ["0.5", "0.2*x", "-1 + 10*y"]
end_time: 1
time_step: {cfl: 0.3, newmark_gamma: 0.6}
)";
}  // namespace

TEST(Mirror, NormalVelocityVanishesOnThePlaneAndTangentialMomentumIsKept) {
  auto sim = test::build<3>(block);
  auto& p = sim->particles();
  auto momentum = [&] {
    Vec<3> P = Vec<3>::Zero();
    for (std::size_t i = 0; i < sim->owned(); ++i) P += p.m()[i] * p.v()[i];
    return P;
  };
  const Vec<3> P0 = momentum();
  double zmin = 1;
  // 3 ms: the compression wave has crossed the block (c = 65 m/s, 0.02 m) about ten times.
  while (sim->time() < 3e-3) {
    sim->advance(3e-3);
    for (std::size_t i = 0; i < sim->owned(); ++i) zmin = std::min(zmin, p.x()[i][2]);
  }
  const Vec<3> P = momentum();
  std::printf("P0 (%g %g %g), P (%g %g %g), lowest z %g\n", P0[0], P0[1], P0[2], P[0], P[1], P[2],
              zmin);
  EXPECT_NEAR(P[0], P0[0], 1e-12 * std::abs(P0[0]));  // along the plane: kept
  EXPECT_NEAR(P[1], P0[1], 1e-12 * std::abs(P0[0]));
  EXPECT_GT(P[2], P0[2] + 0.2 * std::abs(P0[2]));  // normal: the plane has pushed back
  EXPECT_GT(zmin, 0.0);                            // no particle crossed the plane
  // SPH interpolant of v_z on the plane (owned particles and images): zero by the reflection.
  const auto& W = sim->kernel();
  double num = 0, den = 0;
  for (double x = 0; x <= 0.03; x += 0.0025)
    for (double y = -0.012; y <= 0.012; y += 0.0025) {
      const Vec<3> q(x, y, 0);
      double vz = 0, mag = 0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        const double w = p.m()[j] / p.rho()[j] * W.w((q - p.x()[j]).norm());
        vz += w * p.v()[j][2], mag += w * std::abs(p.v()[j][2]);
      }
      num = std::max(num, std::abs(vz)), den = std::max(den, mag);
    }
  std::printf("interpolated |v_z| on the plane %.3g of %.3g\n", num, den);
  EXPECT_GT(den, 1e-3);
  EXPECT_LT(num, 1e-12 * den);
}

namespace {
// A free square plate, 0.06 x 0.06 m (x, z), 0.01 m thick (y, 4 particles), released with
// v_y = 0.1 cos(pi x / 0.06) cos(pi z / 0.06): symmetric about x = 0 and z = 0.
std::string plate(bool quarter, const std::string& solid = "hourglass: {xi: 0.5}") {
  const std::string lo = quarter ? "0" : "-0.05", blo = quarter ? "0" : "-0.03";
  return R"(
name: mirror_plate
dimension: 3
dp: 0.0025
domain: {min: [)" +
         lo + ", -0.03, " + lo + R"(], max: [0.05, 0.03, 0.05])" +
         (quarter ? ", mirror: [x_min, z_min]" : "") + R"(}
materials:
  soft: {density: 1000, bulk_modulus: 3.25e6, shear_modulus: 0.715e6}
bodies:
  - name: plate
    phase: solid
    material: soft
    shape: {box: {min: [)" +
         blo + ", -0.005, " + blo + R"yaml(], max: [0.03, 0.005, 0.03]}}
    )yaml" +
         solid + R"yaml(
    initial:
      velocity: ["0", "0.1*cos(52.35987755982988*x)*cos(52.35987755982988*z)", "0"]
end_time: 1
time_step: {cfl: 0.3, newmark_gamma: 0.6}
)yaml";
}
}  // namespace

TEST(Mirror, QuarterPlateWithTwoPlanesEqualsFullPlate) {
  auto quarter = test::build<3>(plate(true));
  auto full = test::build<3>(plate(false));
  EXPECT_EQ(quarter->owned() * 4, full->owned());
  auto [dx, dv] = half_against_full(*quarter, *full, 0.004);
  std::printf("quarter vs full plate: |dx| %.3g m, |dv| %.3g m/s\n", dx, dv);
  EXPECT_LT(dx, 1e-12);
  EXPECT_LT(dv, 1e-9);
}

TEST(Mirror, QuarterPlateEqualsFullPlateTotalLagrangian) {
  // Two planes: the images across x = 0, across z = 0 and across both (the corner) in the
  // reference neighbours of the total-Lagrangian quarter plate.
  const std::string tl = "formulation: total_lagrangian\n    hourglass: {alpha: 25}";
  auto quarter = test::build<3>(plate(true, tl));
  auto full = test::build<3>(plate(false, tl));
  EXPECT_EQ(quarter->owned() * 4, full->owned());
  auto [dx, dv] = half_against_full(*quarter, *full, 0.004);
  std::printf("quarter vs full plate (total-Lagrangian): |dx| %.3g m, |dv| %.3g m/s\n", dx, dv);
  EXPECT_LT(dx, 1e-12);
  EXPECT_LT(dv, 1e-9);
}
