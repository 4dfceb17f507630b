// Rigid surfaces (MMB 2020 Sect. 3): closest points, Hertz normal force, regularised Coulomb
// friction, prescribed motion, reaction force, STL files.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "assemble.hpp"
#include "output/probes.hpp"
#include "rigid/rigid_surface_module.hpp"
#include "rigid/surface.hpp"
#include "scene/scene.hpp"
#include "thread_helpers.hpp"

using namespace monosph;

namespace {

template <int D>
Vec<D> random_vec(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = u(rng);
  return v;
}

template <int D>
RigidSurfaceModule<D>* rigid_module(Simulation<D>& sim) {
  for (auto& m : sim.modules())
    if (auto* r = dynamic_cast<RigidSurfaceModule<D>*>(m.get())) return r;
  return nullptr;
}

// A soft solid block (dp = 0.01) above a plate `surface` (YAML list item) and gravity.
Scene block_on_plate(const std::string& block_min, const std::string& block_max,
                     const std::string& surface, const std::string& extra = "") {
  return load_scene_text(R"(
name: slide
dimension: 2
dp: 0.01
domain: {min: [-0.5, -0.2], max: [1.5, 0.5]}
materials:
  rubber: {density: 1000, bulk_modulus: 1.0e6, shear_modulus: 0.3e6}
bodies:
  - {name: block, phase: solid, material: rubber, shape: {box: {min: )" +
                         block_min + ", max: " + block_max + R"(}}}
surfaces:
  - )" + surface + R"(
body_force: [0, -9.81]
end_time: 1
)" + extra);
}

}  // namespace

TEST(RigidSurface, ClosestPointOnSegmentMatchesSampling) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec<3> a = random_vec<3>(rng, -1, 1), b = random_vec<3>(rng, -1, 1);
    const Vec<3> p = random_vec<3>(rng, -2, 2);
    const Vec<3> c = closest_point_on_segment<3>(p, a, b);
    // c lies on the segment.
    const double t = (c - a).dot(b - a) / (b - a).squaredNorm();
    EXPECT_GE(t, -1e-12);
    EXPECT_LE(t, 1 + 1e-12);
    EXPECT_LT((a + t * (b - a) - c).norm(), 1e-12);
    // No sample of the segment is closer; the nearest sample is within its spacing.
    const int n = 20000;
    double best = 1e300;
    for (int k = 0; k <= n; ++k) best = std::min(best, (p - (a + (b - a) * k / n)).norm());
    const double d = (p - c).norm();
    EXPECT_LE(d, best + 1e-12);
    EXPECT_GE(d, best - (b - a).norm() / n);
    // 2D version.
    const Vec<2> c2 = closest_point_on_segment<2>(p.head<2>(), a.head<2>(), b.head<2>());
    double best2 = 1e300;
    for (int k = 0; k <= n; ++k)
      best2 = std::min(best2, (p.head<2>() - (a.head<2>() + (b - a).head<2>() * k / n)).norm());
    EXPECT_LE((p.head<2>() - c2).norm(), best2 + 1e-12);
  }
}

TEST(RigidSurface, ClosestPointOnTriangleMatchesSampling) {
  std::mt19937 rng(5);
  int regions[3] = {0, 0, 0};  // vertex, edge, face
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 a = random_vec<3>(rng, -1, 1), b = random_vec<3>(rng, -1, 1),
               c = random_vec<3>(rng, -1, 1);
    const Vec3 p = random_vec<3>(rng, -2, 2);
    const Vec3 q = closest_point_on_triangle(p, a, b, c);
    // q lies in the triangle: barycentric coordinates in [0, 1].
    const Vec3 n = (b - a).cross(c - a);
    const double area = n.squaredNorm();
    const double u = (c - b).cross(q - b).dot(n) / area, v = (a - c).cross(q - c).dot(n) / area,
                 w = (b - a).cross(q - a).dot(n) / area;
    EXPECT_NEAR(u + v + w, 1.0, 1e-9);
    EXPECT_GE(std::min({u, v, w}), -1e-9);
    EXPECT_LT(std::abs((q - a).dot(n)) / std::sqrt(area), 1e-12);  // in the plane
    const int zeros = (u < 1e-9) + (v < 1e-9) + (w < 1e-9);
    ++regions[zeros == 2 ? 0 : zeros == 1 ? 1 : 2];
    // Brute force: barycentric sampling.
    const int m = 300;
    double best = 1e300;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Vec3 s = a + (b - a) * (double(i) / m) + (c - a) * (double(j) / m);
        best = std::min(best, (p - s).norm());
      }
    const double d = (p - q).norm();
    const double spacing = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / m;
    EXPECT_LE(d, best + 1e-12);
    EXPECT_GE(d, best - spacing);
  }
  // Every Voronoi region was visited.
  EXPECT_GT(regions[0], 10);
  EXPECT_GT(regions[1], 10);
  EXPECT_GT(regions[2], 10);
}

TEST(RigidSurface, TreeFindsTheClosestElementLikeBruteForce) {
  // A triangulated sphere (latitude-longitude) in 3D and a polygon in 2D.
  std::vector<SurfaceElement<3>> tris;
  const int nu = 24, nv = 12;
  auto pt = [](int i, int j) {
    const double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
    return Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      SurfaceElement<3> e;
      if (make_element<3>({pt(i, j), pt(i, j + 1), pt(i + 1, j + 1)}, e)) tris.push_back(e);
      if (make_element<3>({pt(i, j), pt(i + 1, j + 1), pt(i + 1, j)}, e)) tris.push_back(e);
    }
  SurfaceGeometry<3> g3(tris);
  std::mt19937 rng(9);
  int found = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 p = random_vec<3>(rng, -1.3, 1.3);
    Vec3 c1, c2;
    int e1, e2;
    const bool f1 = g3.closest(p, 0.2, c1, e1), f2 = g3.closest_brute_force(p, 0.2, c2, e2);
    ASSERT_EQ(f1, f2);
    if (f1) {
      ++found;
      EXPECT_EQ((p - c1).norm(), (p - c2).norm());
    }
  }
  EXPECT_GT(found, 300);
  std::vector<SurfaceElement<2>> segs;
  for (int i = 0; i < 50; ++i) {
    const double t0 = 2 * M_PI * i / 50, t1 = 2 * M_PI * (i + 1) / 50;
    SurfaceElement<2> e;
    make_element<2>({Vec<2>(std::cos(t0), std::sin(t0)), Vec<2>(std::cos(t1), std::sin(t1))}, e);
    segs.push_back(e);
    EXPECT_GT(e.normal.dot(Vec<2>(std::cos(t0), std::sin(t0))), 0);  // counter-clockwise: out
  }
  SurfaceGeometry<2> g2(segs);
  for (int k = 0; k < 3000; ++k) {
    const Vec<2> p = random_vec<2>(rng, -1.3, 1.3);
    Vec<2> c1, c2;
    int e1, e2;
    ASSERT_EQ(g2.closest(p, 0.1, c1, e1), g2.closest_brute_force(p, 0.1, c2, e2));
    if (e1 >= 0) {
      EXPECT_EQ((p - c1).norm(), (p - c2).norm());
    }
  }
}

TEST(RigidSurface, HertzForceScalesWithOverlapToThePowerOneAndAHalf) {
  // Particle material from E, nu: K = E/(3(1 - 2 nu)), mu = E/(2(1 + nu)).
  const double E = 70e9, nu = 0.3, K = E / (3 * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double e_rigid = contact_modulus(K, mu, 0, 0);
  EXPECT_NEAR(e_rigid, E / (1 - nu * nu), 1e-6 * e_rigid);
  const double e_soft = contact_modulus(K, mu, 3e9, 0.37);  // PMMA-like surface
  EXPECT_NEAR(1 / e_soft, (1 - nu * nu) / E + (1 - 0.37 * 0.37) / 3e9, 1e-9 / e_soft);
  EXPECT_EQ(contact_modulus(2.2e9, 0, 0, 0), 2.2e9);  // a fluid: E/(1 - nu^2) := K
  // The law itself, at arbitrary overlaps.
  for (double d1 : {1.3e-9, 2.7e-6, 4.1e-4}) {
    const double d2 = 0.37 * d1, R = 3.3e-4;
    EXPECT_NEAR(hertz_force(e_rigid, R, d1) / hertz_force(e_rigid, R, d2), std::pow(1 / 0.37, 1.5),
                1e-12 * std::pow(1 / 0.37, 1.5));
    EXPECT_NEAR(hertz_stiffness(e_rigid, R, d1), 2 * e_rigid * std::sqrt(R * d1),
                1e-12 * hertz_stiffness(e_rigid, R, d1));
  }
  // On a particle: R and the overlaps are binary fractions, so that the distance R - delta of the
  // centre from the closest point carries no round-off.
  const double R = std::ldexp(1.0, -11);
  const Vec<2> c(0.25, 0.0), nrm(0, 1), zero = Vec<2>::Zero();
  for (double depth : {1.0, 1e-3}) {
    double fn1, fn2;
    for (int k1 : {13, 16, 19, 25}) {
      const double d1 = std::ldexp(1.0, -k1), d2 = 3 * std::ldexp(1.0, -k1 - 3);
      const Vec<2> f1 = contact_force<2>(c + Vec<2>(0, R - d1), zero, 1.0, c, nrm, zero, R, e_rigid,
                                         0.0, 1e-7, depth, &fn1);
      const Vec<2> f2 = contact_force<2>(c + Vec<2>(0, R - d2), zero, 1.0, c, nrm, zero, R, e_rigid,
                                         0.0, 1e-7, depth, &fn2);
      const double ratio = f1[1] / f2[1], expect = std::pow(d1 / d2, 1.5);
      EXPECT_NEAR(ratio, expect, 1e-12 * expect);
      EXPECT_NEAR(f1[1], 4.0 / 3.0 * e_rigid * std::sqrt(R) * std::pow(d1, 1.5) / depth,
                  1e-12 * f1[1]);
      EXPECT_EQ(f1[0], 0.0);
      EXPECT_EQ(fn1, f1[1]);
      EXPECT_EQ(fn2, f2[1]);
    }
  }
  // No force without overlap; direction from the closest point to the centre, also at an edge.
  EXPECT_EQ(contact_force<2>(c + Vec<2>(0, R), zero, 1.0, c, nrm, zero, R, e_rigid, 0.5, 1e-7, 1.0)
                .norm(),
            0.0);
  const Vec<2> diag = Vec<2>(1, 1).normalized();
  const Vec<2> fd =
      contact_force<2>(c + 0.5 * R * diag, zero, 1.0, c, nrm, zero, R, e_rigid, 0, 1e-7, 1.0);
  EXPECT_NEAR(fd.normalized().dot(diag), 1.0, 1e-14);
  // A centre on the element: pushed along the element normal.
  const Vec<2> f0 = contact_force<2>(c, zero, 1.0, c, nrm, zero, R, e_rigid, 0, 1e-7, 1.0);
  EXPECT_NEAR(f0.normalized().dot(nrm), 1.0, 1e-14);
}

TEST(RigidSurface, FrictionNeverExceedsMuTimesTheNormalForce) {
  const double R = 0.005, e_star = 1e8, mu_f = 0.3, m = 0.1, dt = 1e-5;
  const Vec3 c(0, 0, 0), nrm(0, 0, 1), vs(0.2, -0.1, 0);
  int capped = 0, coulomb = 0;
  for (double speed = 1e-8; speed < 1e4; speed *= 1.7) {
    for (double angle : {0.0, 1.0, 2.5, 4.0}) {
      // Sliding in direction `angle` in the plane plus a normal component that must not matter.
      const Vec3 vt(speed * std::cos(angle), speed * std::sin(angle), 0);
      const Vec3 v = vs + vt + Vec3(0, 0, -0.7);
      double fn;
      const Vec3 x(0.001, 0.002, R - 2e-4), cx(0.001, 0.002, 0);  // closest point below x
      const Vec3 f = contact_force<3>(x, v, m, cx, nrm, vs, R, e_star, mu_f, dt, 1.0, &fn);
      const Vec3 ft = f - f.dot(nrm) * nrm;
      EXPECT_NEAR(f.dot(nrm), fn, 1e-12 * fn);
      EXPECT_LE(ft.norm(), mu_f * fn * (1 + 1e-12));
      EXPECT_LT(ft.dot(vt), 0);  // opposes the sliding
      EXPECT_NEAR(ft.normalized().dot(-vt.normalized()), 1.0, 1e-9);
      // Never more than stops the relative sliding within the step (the sliding speed as the
      // force sees it: v - v_s carries the round-off of the sum v = v_s + v_t).
      const Vec3 vr = v - vs;
      const double slide = (vr - vr.dot(nrm) * nrm).norm();
      EXPECT_NEAR(slide, speed, 1e-6 * speed);
      EXPECT_LE(ft.norm() * dt / m, slide * (1 + 1e-12));
      const double expect = std::min(mu_f * fn, m * slide / dt);
      EXPECT_NEAR(ft.norm(), expect, 1e-12 * expect);
      (mu_f * fn < m * slide / dt ? coulomb : capped)++;
    }
  }
  EXPECT_GT(capped, 10);
  EXPECT_GT(coulomb, 10);
  // No relative sliding: no tangential force.
  double fn;
  const Vec3 f = contact_force<3>(Vec3(0, 0, R - 1e-4), vs + Vec3(0, 0, 1), m, c, nrm, vs, R,
                                  e_star, mu_f, dt, 1.0, &fn);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[1], 0.0);
}

TEST(RigidSurface, ParticlesOnAMovingPlatePickUpItsVelocity) {
  // Three solid particles (one-particle bodies, too far apart to interact) resting on a plate
  // that moves along x at V, starting at 0, V/2 and 1.75 V. Kinetic friction mu_f m g changes
  // their velocity at about mu_f g until they move with the plate; the cap m |v_t|/dt then holds
  // them there without overshoot.
  const double V = 0.2, mu_f = 0.5, g = 9.81;
  const double v0[3] = {0.0, 0.5 * V, 1.75 * V};
  // Lattice nodes at x = 0.005, 0.015, ... and y = 0.005: each particle's centre is R = dp/2
  // above the plate at y = 0 (just touching).
  std::string bodies;
  for (int k = 0; k < 3; ++k)
    bodies += fmt::format(
        "  - {{name: p{0}, phase: solid, material: rubber, shape: {{box: {{min: [{1}, 0], max: "
        "[{2}, 0.01]}}}}, initial: {{velocity: [\"{3}\", \"0\"]}}}}\n",
        k, 0.05 * k, 0.05 * k + 0.01, v0[k]);
  Scene scene = load_scene_text(R"(
name: slide
dimension: 2
dp: 0.01
domain: {min: [-0.5, -0.2], max: [1.5, 0.5]}
materials:
  rubber: {density: 1000, bulk_modulus: 1.0e6, shear_modulus: 0.3e6}
bodies:
)" + bodies +
                                fmt::format(R"(
surfaces:
  - {{name: plate, segment: [[-0.4, 0], [1.4, 0]], velocity: [{}, 0], friction: {}}}
body_force: [0, {}]
end_time: 1
)",
                                            V, mu_f, -g));
  Simulation<2> sim(scene);
  assemble_modules(sim);
  sim.create_particles();
  auto& p = sim.particles();
  ASSERT_EQ(p.size(), 3u);
  sim.init();
  auto* rigid = rigid_module(sim);
  ASSERT_NE(rigid, nullptr);
  double t_pick[3] = {-1, -1, -1}, worst_overshoot = 0;
  while (sim.time() < 0.12) {
    sim.advance();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int b = static_cast<int>(p.body()[i]);
      const double rel = (p.v()[i][0] - V) / V;  // relative sliding, in units of V
      const double sign = v0[b] < V ? 1 : -1;    // approaching V from below or above
      worst_overshoot = std::max(worst_overshoot, sign * rel);
      if (t_pick[b] < 0 && std::abs(rel) < 1e-3) t_pick[b] = sim.time();
      EXPECT_GT(p.x()[i][1], 0);  // stays above the plate
    }
  }
  EXPECT_NEAR(rigid->displacement(0)[0], V * sim.time(), 1e-12);  // the plate moved
  for (int b = 0; b < 3; ++b) {
    // The average normal force is m g, so friction needs |V - v0|/(mu_f g) (+-20 %: the normal
    // force oscillates between 0 and 2 m g in the undamped Hertz contact).
    const double expect = std::abs(V - v0[b]) / (mu_f * g);
    EXPECT_GT(t_pick[b], 0.8 * expect) << b;
    EXPECT_LT(t_pick[b], 1.2 * expect) << b;
  }
  EXPECT_LT(worst_overshoot, 1e-6);  // without the cap: mu_f g dt/V ~ 1e-3
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p.v()[i][0], V, 1e-6 * V) << i;
  std::printf("pick-up times %g %g %g s, worst overshoot %.3g V\n", t_pick[0], t_pick[1], t_pick[2],
              worst_overshoot);
}

TEST(RigidSurface, ReactionIsMinusTheSumOfTheContactForces) {
  // A block pressed into a sloped plate and into a second, horizontal one.
  Scene scene = block_on_plate(
      "[0, 0.0]", "[0.06, 0.04]",
      "{name: floor, segment: [[-0.4, 0.0015], [1.4, -0.002]], velocity: [0.1, 0], "
      "friction: 0.3}\n  - {name: wall, polygon: [[0.0035, -0.1], [0.0035, 0.1], [-0.1, 0.1], "
      "[-0.1, -0.1]], velocity: [\"0.1*t\", 0], stiffness: 1e7}");
  Simulation<2> sim(scene);
  assemble_modules(sim);
  sim.create_particles();
  sim.init();
  for (int k = 0; k < 20; ++k) sim.advance();
  auto* rigid = rigid_module(sim);
  ASSERT_EQ(rigid->size(), 2u);
  auto& p = sim.particles();
  // Accelerations from the contact forces alone.
  for (auto& a : p.a()) a.setZero();
  rigid->forces(sim);
  for (int s = 0; s < 2; ++s) {
    Vec<2> sum = Vec<2>::Zero();
    int touching = 0;
    for (const auto& f : rigid->particle_forces(s)) sum += f, touching += f.norm() > 0;
    EXPECT_GT(touching, 0);
    EXPECT_EQ(rigid->contacts(s), touching);
    EXPECT_LT((rigid->reaction(s) + sum).norm(), 1e-12 * sum.norm());
  }
  Vec<2> ma = Vec<2>::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) ma += p.m()[i] * p.a()[i];
  const Vec<2> total = rigid->reaction(0) + rigid->reaction(1);
  EXPECT_LT((ma + total).norm(), 1e-10 * total.norm());
  // Thread-count independence of the reaction.
  const Vec<2> r1 = rigid->reaction(0);
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);
  EXPECT_EQ(test::team_size(), 2);
  for (auto& a : p.a()) a.setZero();
  rigid->forces(sim);
  omp_set_num_threads(before);
  EXPECT_EQ(rigid->reaction(0), r1);
}

TEST(RigidSurface, ProbesReportTheReactionAndContacts) {
  Scene scene = block_on_plate("[0, 0.0]", "[0.04, 0.02]",
                               "{name: plate, box: {min: [-0.4, -0.1], max: [1.4, 0.0]}}",
                               R"(probes:
  list:
    - {name: F, type: surface_force, surface: plate}
    - {name: n, type: surface_contacts, body: plate}
)");
  Simulation<2> sim(scene);
  assemble_modules(sim);
  sim.create_particles();
  sim.init();
  for (int k = 0; k < 30; ++k) sim.advance();
  Probes<2> probes(sim);
  ASSERT_EQ(probes.columns(), (std::vector<std::string>{"F_x", "F_y", "n"}));
  auto* rigid = rigid_module(sim);
  const auto values = probes.sample(sim);
  EXPECT_EQ(values[0], rigid->reaction(0)[0]);
  EXPECT_EQ(values[1], rigid->reaction(0)[1]);
  EXPECT_EQ(values[2], rigid->contacts(0));
  EXPECT_EQ(values[2], 4);  // the bottom row
  EXPECT_LT(values[1], 0);  // the block pushes the plate down
}

TEST(RigidSurface, PrescribedMotionIsIntegratedExactly) {
  // Velocity 0.3 t^2 (Simpson's rule is exact): displacement 0.1 t^3 at the force pass.
  Scene scene = block_on_plate("[0, 0.05]", "[0.04, 0.07]",
                               "{name: plate, segment: [[-0.4, 0], [1.4, 0]], velocity: "
                               "[\"0.3*t^2\", \"-0.01\"]}");
  Simulation<2> sim(scene);
  assemble_modules(sim);
  sim.create_particles();
  sim.init();
  auto* rigid = rigid_module(sim);
  for (int k = 0; k < 50; ++k) sim.advance();
  const double t = sim.time();
  EXPECT_NEAR(rigid->displacement(0)[0], 0.1 * t * t * t, 1e-15);
  EXPECT_NEAR(rigid->displacement(0)[1], -0.01 * t, 1e-15);
  EXPECT_NEAR(rigid->velocity(0)[0], 0.3 * t * t, 1e-15);
}

TEST(RigidSurface, StlRoundTripAsciiAndBinary) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "monosph_stl_test";
  fs::create_directories(dir);
  // A closed box with float-exact coordinates, plus one sliver that is dropped.
  SurfaceSpec box;
  box.kind = "box";
  box.points = {{-0.25, 0.0, 0.5}, {0.75, 1.5, 2.0}};
  box.translate = {0, 0, 0};
  std::vector<SurfaceElement<3>> elements = surface_elements<3>(box, "test");
  ASSERT_EQ(elements.size(), 12u);
  std::vector<std::array<Vec3, 3>> tris;
  for (const auto& e : elements) {
    tris.push_back(e.v);
    // Outward normals: away from the centre.
    EXPECT_GT(e.normal.dot(e.v[0] - Vec3(0.25, 0.75, 1.25)), 0);
  }
  auto with_sliver = tris;
  with_sliver.push_back({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)});
  for (bool binary : {false, true}) {
    const std::string file = (dir / (binary ? "box_bin.stl" : "box_ascii.stl")).string();
    write_stl(file, with_sliver, binary);
    const auto back = read_stl(file);
    ASSERT_EQ(back.size(), tris.size()) << file;
    for (std::size_t k = 0; k < tris.size(); ++k)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(back[k][c], tris[k][c]) << file << " " << k;
  }
  // Through a scene: path relative to the scene file, scaled and translated.
  {
    std::ofstream(dir / "scene.yaml") << R"(
name: stl
dimension: 3
dp: 0.1
domain: {min: [-2, -2, -2], max: [4, 4, 4]}
materials:
  steel: {density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9}
bodies:
  - {name: ball, phase: solid, material: steel, shape: {sphere: {center: [3, 3, 3], radius: 0.3}}}
surfaces:
  - {name: part, stl: box_bin.stl, scale: 2, translate: [1, 0, 0], friction: 0.1}
end_time: 1
)";
    Scene scene = load_scene_file((dir / "scene.yaml").string());
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].file, (dir / "box_bin.stl").string());
    Simulation<3> sim(scene);
    assemble_modules(sim);
    auto* rigid = rigid_module(sim);
    ASSERT_NE(rigid, nullptr);
    const auto& el = rigid->geometry(0).elements();
    ASSERT_EQ(el.size(), 12u);
    for (std::size_t k = 0; k < 12; ++k)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(el[k].v[c], 2 * tris[k][c] + Vec3(1, 0, 0));
  }
  // Not an STL file: the error names the file.
  std::ofstream(dir / "bad.stl") << "hello";
  try {
    read_stl((dir / "bad.stl").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.stl"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(RigidSurface, SceneKeysAreChecked) {
  auto error = [](const std::string& surface, const std::string& extra = "") {
    try {
      block_on_plate("[0, 0.05]", "[0.04, 0.07]", surface, extra);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{name: p, segment: [[0, 0], [1, 0]], frictoin: 0.2}")
                .find("surfaces[0] (p).frictoin: unknown key"),
            std::string::npos);
  EXPECT_NE(error("{name: p, segmnt: [[0, 0], [1, 0]]}").find("surfaces[0] (p).segmnt: unknown"),
            std::string::npos);
  EXPECT_NE(error("{name: p, segment: [[0, 0], [1, 0]], friction: -1}")
                .find("surfaces[0] (p).friction: must not be negative"),
            std::string::npos);
  EXPECT_NE(error("{name: p, segment: [[0, 0], [0, 0]]}").find("coincide"), std::string::npos);
  EXPECT_NE(error("{name: p, segment: [[0, 0], [1, 0]], box: {min: [0, 0], max: [1, 1]}}")
                .find("exactly one geometry key"),
            std::string::npos);
  EXPECT_NE(error("{name: p, stl: a.stl}").find("surfaces[0] (p).stl: unknown key"),
            std::string::npos);
  EXPECT_NE(error("{name: p, segment: [[0, 0], [1, 0]], stiffness: 0}")
                .find("stiffness: must be positive"),
            std::string::npos);
  EXPECT_NE(error("{name: p, segment: [[0, 0], [1, 0]]}",
                  "probes:\n  list:\n    - {name: F, type: surface_force, surface: plat}\n")
                .find("no surface named 'plat'"),
            std::string::npos);
  // A scene with surfaces switches the rigid module on.
  Scene s = block_on_plate("[0, 0.05]", "[0.04, 0.07]", "{name: p, segment: [[0, 0], [1, 0]]}");
  EXPECT_NE(std::find(s.modules.begin(), s.modules.end(), "rigid"), s.modules.end());
}
