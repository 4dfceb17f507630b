// Coulomb friction of grain contact (contact.friction): the tangential impulse of a sliding
// bounce is mu times the normal impulse, it spins the grain up as a disc, and grain + solid keep
// their total momentum.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "output/probes.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

using test::build;

// An iron grain (d = 10 dp, R = 5 mm) touching a floor at t = 0, moving at (1, -1) m/s; `floor`
// is the floor's phase (wall: held; solid: free), `mu` the contact friction.
std::string sliding_grain(const std::string& floor, double mu) {
  return fmt::format(R"(
name: slide
dimension: 2
dp: 0.001
domain: {{min: [0, -0.005], max: [0.06, 0.03]}}
materials:
  iron: {{preset: iron}}
bodies:
  - {{name: floor, phase: {}, material: iron, shape: {{box: {{min: [0, -0.004], max: [0.06, 0]}}}}}}
  - name: grain
    phase: rigid
    material: iron
    shape: {{circle: {{center: [0.02, 0.0054], radius: 0.005}}}}
    initial: {{velocity: [1, -1]}}
contact: {{law: hertz, friction: {}}}
end_time: 1
probes:
  list:
    - {{name: v, type: rigid_velocity, body: grain}}
    - {{name: w, type: rigid_angular_velocity, body: grain}}
    - {{name: n, type: contact_pairs}}
)",
                     floor, mu);
}

struct Bounce {
  double vx, vy, w;  // grain velocity and angular velocity after the contact
};

Bounce bounce(const std::string& floor, double mu) {
  auto sim = build<2>(sliding_grain(floor, mu));
  Probes<2> probes(*sim);
  bool touched = false;
  std::vector<double> v;
  for (int k = 0; k < 200000; ++k) {
    sim->advance();
    v = probes.sample(*sim);  // v_x, v_y, w, pairs
    touched = touched || v[3] > 0;
    if (touched && v[3] == 0) break;
  }
  EXPECT_TRUE(touched);
  EXPECT_EQ(v[3], 0) << "the contact did not end";
  return {v[0], v[1], v[2]};
}

}  // namespace

TEST(ContactFriction, SlidingBounceTakesMuTimesTheNormalImpulse) {
  // Without friction the particle lattice is a slightly bumpy surface (measured: v_x + 2 %,
  // omega R = 0.04 m/s). With mu = 0.1 the grain slides through the whole contact (slip 1 m/s
  // falls by 3 mu dv_n < 1 for a disc, I = M R^2 / 2), so friction takes dv_t = mu dv_n more and
  // adds omega R = -2 dv_t (clockwise when moving to +x).
  const double R = 0.005, mu = 0.1;
  const Bounce free = bounce("wall", 0.0);
  std::printf("mu = 0: v = (%.4f, %.4f), omega R = %.4f\n", free.vx, free.vy, free.w * R);
  EXPECT_GT(free.vy, 0.9);  // an elastic bounce
  EXPECT_NEAR(free.vx, 1.0, 0.03);
  EXPECT_LT(std::abs(free.w * R), 0.05);
  const Bounce fr = bounce("wall", mu);
  const double dvt = free.vx - fr.vx, dvn = fr.vy + 1, dwr = (free.w - fr.w) * R;
  std::printf("mu = 0.1: v = (%.4f, %.4f), dv_t/(mu dv_n) = %.3f, -d(omega R)/(2 dv_t) = %.3f\n",
              fr.vx, fr.vy, dvt / (mu * dvn), dwr / (2 * dvt));
  EXPECT_NEAR(dvt / (mu * dvn), 1.0, 0.05);
  EXPECT_NEAR(dwr / (2 * dvt), 1.0, 0.1);
}

TEST(ContactFriction, GrainAndSolidKeepTheirMomentum) {
  // Friction pairs are exactly opposite: grain + free solid block conserve momentum.
  auto sim = build<2>(sliding_grain("solid", 0.3));
  auto momentum = [&] {
    auto& p = sim->particles();
    Vec<2> s = Vec<2>::Zero();
    for (std::size_t i = 0; i < sim->owned(); ++i) s += p.m()[i] * p.v()[i];
    return s;
  };
  const Vec<2> p0 = momentum();
  for (int k = 0; k < 3000; ++k) sim->advance();
  const Vec<2> p1 = momentum();
  EXPECT_LT((p1 - p0).norm(), 1e-9 * p0.norm()) << p1.transpose() << " vs " << p0.transpose();
}
