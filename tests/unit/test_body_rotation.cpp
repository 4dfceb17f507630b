// A body's `rotate: {degrees, about, axis}`: its particles turned right after the fill (a
// rigid grain then takes mass, centre and inertia from the turned particles).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>

#include "rigid/cluster_module.hpp"
#include "sim_helpers.hpp"

using namespace monosph;

namespace {

using test::build;
using test::module;

// One body of `phase` and `shape` (more body keys in `extra`) in [0, 0.2] x [0, 0.1] (x [0, 0.1]).
std::string scene(int dim, const std::string& phase, const std::string& shape,
                  const std::string& extra = "") {
  return fmt::format(R"(
name: turned
dimension: {0}
dp: 0.002
domain: {{min: [0, 0{1}], max: [0.2, 0.1{2}]}}
variables: {{seed: 0}}
materials:
  iron: {{preset: iron}}
bodies:
  - name: body
    phase: {3}
    material: iron
    shape: {4}
    {5}
end_time: 1
)",
                     dim, dim == 3 ? ", 0" : "", dim == 3 ? ", 0.1" : "", phase, shape, extra);
}

// Particle positions by id (the particles are re-ordered at the start).
template <int D>
std::map<std::int64_t, Vec<D>> positions(Simulation<D>& sim) {
  std::map<std::int64_t, Vec<D>> out;
  auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) out[p.id()[i]] = p.x()[i];
  return out;
}

template <int D>
Vec<D> mass_centre(Simulation<D>& sim) {
  auto& p = sim.particles();
  Vec<D> c = Vec<D>::Zero();
  double m = 0;
  for (std::size_t i = 0; i < p.size(); ++i) c += p.m()[i] * p.x()[i], m += p.m()[i];
  return c / m;
}

const char* const kCircle = "{circle: {center: [0.1, 0.05], radius: 0.011}}";

TEST(BodyRotation, ARotatedCircleIsTheUnrotatedOneTurnedAboutItsCentre) {
  auto plain = build<2>(scene(2, "solid", kCircle));
  auto turned = build<2>(scene(2, "solid", kCircle, "rotate: {degrees: 37.5, about: [0.1, 0.05]}"));
  const auto x0 = positions(*plain), x1 = positions(*turned);
  ASSERT_EQ(x0.size(), x1.size());
  ASSERT_EQ(x0.size(), 88u);  // pi 5.5^2 = 95 cells
  const double th = 37.5 * std::numbers::pi / 180;
  Eigen::Matrix2d r;
  r << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
  const Eigen::Vector2d c(0.1, 0.05);
  for (const auto& [id, x] : x0) {
    const Eigen::Vector2d want = c + r * (Eigen::Vector2d(x) - c);
    EXPECT_NEAR((Eigen::Vector2d(x1.at(id)) - want).norm(), 0, 1e-12) << id;
  }
  // The lattice nodes in a circle centred between nodes are symmetric: same centre of mass.
  EXPECT_NEAR((mass_centre(*plain) - c).norm(), 0, 1e-12);
  EXPECT_NEAR((mass_centre(*turned) - c).norm(), 0, 1e-12);
}

TEST(BodyRotation, ARotatedBoxLiesAtTheRotatedPositions) {
  const std::string box = "{box: {min: [0.08, 0.04], max: [0.12, 0.06]}}";
  auto plain = build<2>(scene(2, "solid", box));
  auto turned = build<2>(scene(2, "solid", box, "rotate: {degrees: 90}"));  // about its centre
  const auto x0 = positions(*plain), x1 = positions(*turned);
  ASSERT_EQ(x0.size(), x1.size());
  for (const auto& [id, x] : x0) {  // 90 deg about (0.1, 0.05): (x, y) -> (0.15 - y, x - 0.05)
    EXPECT_NEAR(x1.at(id)[0], 0.1 - (x[1] - 0.05), 1e-12);
    EXPECT_NEAR(x1.at(id)[1], 0.05 + (x[0] - 0.1), 1e-12);
    // The turned box spans [0.09, 0.11] x [0.03, 0.07].
    EXPECT_TRUE(x1.at(id)[0] > 0.09 && x1.at(id)[0] < 0.11 && x1.at(id)[1] > 0.03 &&
                x1.at(id)[1] < 0.07);
  }
}

TEST(BodyRotation, InThreeDimensionsItTurnsAboutTheAxis) {
  const std::string ball = "{sphere: {center: [0.1, 0.05, 0.05], radius: 0.007}}";
  auto plain = build<3>(scene(3, "solid", ball));
  auto turned = build<3>(scene(3, "solid", ball, "rotate: {degrees: -30, axis: [1, 1, 0]}"));
  const auto x0 = positions(*plain), x1 = positions(*turned);
  ASSERT_EQ(x0.size(), x1.size());
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(-30 * std::numbers::pi / 180, Eigen::Vector3d(1, 1, 0).normalized())
          .toRotationMatrix();
  const Eigen::Vector3d c(0.1, 0.05, 0.05);
  for (const auto& [id, x] : x0)
    EXPECT_NEAR((Eigen::Vector3d(x1.at(id)) - (c + r * (Eigen::Vector3d(x) - c))).norm(), 0, 1e-12);
}

TEST(BodyRotation, ARotatedRigidGrainTakesItsMassCentreAndInertiaFromTheTurnedParticles) {
  const std::string box = "{box: {min: [0.08, 0.04], max: [0.13, 0.06]}}";  // not symmetric in 90
  auto plain = build<2>(scene(2, "rigid", box));
  auto turned = build<2>(scene(2, "rigid", box, "rotate: {degrees: 20, about: [0.09, 0.05]}"));
  const auto& c0 = module<ClusterModule<2>>(*plain).cluster(0);
  const auto& c1 = module<ClusterModule<2>>(*turned).cluster(0);
  EXPECT_NEAR(c1.mass, c0.mass, 1e-12 * c0.mass);
  EXPECT_NEAR(c1.inertia, c0.inertia, 1e-12 * c0.inertia);  // polar inertia: turned alike
  const double th = 20 * std::numbers::pi / 180;
  const Eigen::Vector2d a(0.09, 0.05), d = Eigen::Vector2d(c0.centre) - a;
  const Eigen::Vector2d want(a[0] + std::cos(th) * d[0] - std::sin(th) * d[1],
                             a[1] + std::sin(th) * d[0] + std::cos(th) * d[1]);
  EXPECT_NEAR((Eigen::Vector2d(c1.centre) - want).norm(), 0, 1e-12);
  EXPECT_NEAR((mass_centre(*turned) - c1.centre).norm(), 0, 1e-12);
  // The members sit at centre + offset (the offsets are the turned particles').
  auto& p = turned->particles();
  auto off = p.view<Vec<2>>("cluster_offset");
  for (std::size_t k : c1.members) EXPECT_NEAR((c1.centre + off[k] - p.x()[k]).norm(), 0, 1e-12);
}

TEST(BodyRotation, GrainsPerPartFindTheirPartsWhenTurned) {
  const std::string pair =
      "{union: [{circle: {center: [0.08, 0.05], radius: 0.006}}, {circle: {center: [0.12, 0.05], "
      "radius: 0.006}}]}";
  auto sim = build<2>(scene(2, "rigid", pair, "clusters: per_part\n    rotate: {degrees: 90}"));
  auto& cm = module<ClusterModule<2>>(*sim);
  ASSERT_EQ(cm.size(), 2u);  // the parts now stand one above the other
  EXPECT_NEAR(cm.cluster(0).centre[0], 0.1, 1e-12);
  EXPECT_NEAR(cm.cluster(0).centre[1], 0.03, 1e-12);
  EXPECT_NEAR(cm.cluster(1).centre[1], 0.07, 1e-12);
}

TEST(BodyRotation, TheAngleMayBeAnExpressionOfTheVariables) {
  const Scene s =
      load_scene_text(scene(2, "solid", kCircle, "rotate: {degrees: \"90*uniform(seed, 2)\"}"),
                      {"variables.seed=4"});
  ASSERT_TRUE(s.bodies[0].rotate);
  EXPECT_EQ(s.bodies[0].rotate->degrees, 90 * seeded_uniform(4, 2));
  EXPECT_NEAR(s.bodies[0].rotate->about[0], 0.1, 1e-15);  // default: the shape's centre
  EXPECT_NEAR(s.bodies[0].rotate->about[1], 0.05, 1e-15);
}

TEST(BodyRotation, BadValuesAreOneLineErrorsNamingTheKey) {
  auto err2 = [](const std::string& r) { return test::load_error(scene(2, "solid", kCircle, r)); };
  const std::string ball = "{sphere: {center: [0.1, 0.05, 0.05], radius: 0.007}}";
  EXPECT_NE(test::load_error(scene(3, "solid", ball, "rotate: {degrees: 5, axis: [0, 0, 0]}"))
                .find("bodies[0] (body).rotate.axis: must be a finite non-zero vector"),
            std::string::npos);
  EXPECT_NE(err2("rotate: {degrees: 5, axis: [0, 0, 1]}")
                .find("bodies[0] (body).rotate.axis: applies to 3D scenes only"),
            std::string::npos);
  EXPECT_NE(err2("rotate: {degrees: .inf}")
                .find("bodies[0] (body).rotate.degrees: expected a "
                      "finite number"),
            std::string::npos);
  EXPECT_NE(err2("rotate: {about: [0, 0]}").find("bodies[0] (body).rotate.degrees: missing"),
            std::string::npos);
  EXPECT_NE(err2("rotate: {degrees: 5, about: [0.1]}")
                .find("bodies[0] (body).rotate.about: expected a list of 2 numbers"),
            std::string::npos);
  // Turned about a far point, the particles leave the domain: an error at the fill.
  try {
    build<2>(scene(2, "solid", kCircle, "rotate: {degrees: 90, about: [0, 0]}"));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[0] (body).rotate: turns a particle out of the "
                                         "domain"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
