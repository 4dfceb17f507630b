// Scene `variables`: named numbers every expression can use, changed by --set and study --vary.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/types.hpp"
#include "scene/scene.hpp"
#include "sim_helpers.hpp"

namespace monosph {
namespace {

// A fluid block moving at `speed` along `angle` (degrees), density and a weight from variables.
const std::string kScene = R"yaml(
name: vars
dimension: 2
dp: 0.1
domain: {min: [0, 0], max: [1, 1]}
variables: {angle: 30, speed: 2, rho0: 1000}
materials:
  water: {density: 1000, sound_speed: 10}
bodies:
  - name: block
    phase: fluid
    material: water
    shape: {box: {min: [0.2, 0.2], max: [0.6, 0.6]}}
    initial:
      density: "rho0"
      velocity: ["speed*cos(angle*pi/180)", "-speed*sin(angle*pi/180)"]
end_time: 0.01
probes:
  list:
    - {name: weighted, type: integral, field: density, weight: "speed"}
)yaml";

std::string message(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    load_scene_text(text, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneVariables, AreReadAndOverriddenBySet) {
  Scene s = load_scene_text(kScene);
  ASSERT_EQ(s.variables.size(), 3u);
  EXPECT_DOUBLE_EQ(s.variables.at("angle"), 30);
  Scene t = load_scene_text(kScene, {"variables.angle=45", "variables.speed=3"});
  EXPECT_DOUBLE_EQ(t.variables.at("angle"), 45);
  EXPECT_DOUBLE_EQ(t.variables.at("speed"), 3);
}

TEST(SceneVariables, InitialVelocityExpressionsUseThem) {
  auto sim = test::build<2>(load_scene_text(kScene, {"variables.angle=60"}).yaml);
  const double a = 60 * std::numbers::pi / 180;
  auto v = sim->particles().v();
  auto rho = sim->particles().rho();
  ASSERT_GT(sim->particles().size(), 0u);
  for (std::size_t i = 0; i < sim->particles().size(); ++i) {
    EXPECT_NEAR(v[i].x(), 2 * std::cos(a), 1e-12);
    EXPECT_NEAR(v[i].y(), -2 * std::sin(a), 1e-12);
    EXPECT_NEAR(rho[i], 1000, 1e-9);
  }
}

TEST(SceneVariables, ScenesWithoutThemAreUnchanged) {
  std::string text = kScene;
  text.replace(text.find("variables:"),
               text.find('\n', text.find("variables:")) - text.find("variables:") + 1, "");
  EXPECT_NE(message(text).find("invalid expression 'rho0'"), std::string::npos) << message(text);
}

TEST(SceneVariables, AnUnknownNameInAnExpressionIsAnErrorNamingTheKey) {
  std::string text = kScene;
  text.replace(text.find("speed*cos"), 5, "sped");
  const std::string m = message(text);
  EXPECT_NE(m.find("bodies[0] (block).initial.velocity[0]: invalid expression"), std::string::npos)
      << m;
  EXPECT_NE(m.find("did you mean 'speed'?"), std::string::npos) << m;
}

TEST(SceneVariables, SetOfAnUndeclaredVariableIsAnError) {
  const std::string m = message(kScene, {"variables.angel=45"});
  EXPECT_NE(m.find("--set variables.angel: the scene declares no variable 'angel'"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("did you mean 'angle'?"), std::string::npos) << m;
}

TEST(SceneVariables, ReservedNamesAndNonNumbersAreRejected) {
  std::string text = kScene;
  const auto at = text.find("variables: {");
  EXPECT_NE(message(std::string(text).insert(at + 12, "x: 1, ")).find("variables.x:"),
            std::string::npos);
  EXPECT_NE(message(std::string(text).insert(at + 12, "sin: 1, ")).find("variables.sin:"),
            std::string::npos);
  EXPECT_NE(message(kScene, {"variables.speed=fast"})
                .find("variables.speed: expected a number, got 'fast'"),
            std::string::npos);
}

// Number keys (shapes, dp, end_time...) given as expressions of the variables.
const std::string kNumbers = R"yaml(
name: numbers
dimension: 2
dp: "0.05*2"
domain: {min: [0, 0], max: [1, 1]}
variables: {seed: 0, w: 0.4, speed: 2}
materials:
  water: {density: 1000, sound_speed: 10}
bodies:
  - name: block
    phase: fluid
    material: water
    shape: {box: {min: [0.2, 0.2], max: [0.2+w, "0.6"]}}
  - name: drop
    phase: fluid
    material: water
    shape: {circle: {center: ["0.5 + 0.1*(uniform(seed, 1) - 0.5)", 0.85], radius: 0.1}}
end_time: "0.01*speed"
)yaml";

TEST(SceneVariables, NumberKeysMayBeExpressionsOfThem) {
  Scene s = load_scene_text(kNumbers);
  EXPECT_DOUBLE_EQ(s.dp, 0.1);
  EXPECT_DOUBLE_EQ(s.bodies[0].shape.b[0], 0.6);
  EXPECT_DOUBLE_EQ(s.bodies[0].shape.b[1], 0.6);
  EXPECT_DOUBLE_EQ(s.end_time, 0.02);
  EXPECT_DOUBLE_EQ(s.bodies[1].shape.center[0], 0.5 + 0.1 * (seeded_uniform(0, 1) - 0.5));
  Scene t = load_scene_text(kNumbers, {"variables.w=0.3", "variables.speed=3"});
  EXPECT_DOUBLE_EQ(t.bodies[0].shape.b[0], 0.5);
  EXPECT_DOUBLE_EQ(t.end_time, 0.03);
}

TEST(SceneVariables, ASeedVariableChangesASeededKeyReproducibly) {
  auto centre = [](int seed) {
    return load_scene_text(kNumbers, {fmt::format("variables.seed={}", seed)})
        .bodies[1]
        .shape.center[0];
  };
  EXPECT_EQ(centre(3), centre(3));
  EXPECT_NE(centre(3), centre(4));
  EXPECT_EQ(centre(3), 0.5 + 0.1 * (seeded_uniform(3, 1) - 0.5));
}

TEST(SceneVariables, ABadNumberExpressionIsAOneLineErrorNamingTheKey) {
  auto edit = [](const std::string& from, const std::string& to) {
    std::string text = kNumbers;
    text.replace(text.find(from), from.size(), to);
    return message(text);
  };
  const std::string xyz = edit("\"0.01*speed\"", "\"0.01*(1+x)\"");
  EXPECT_NE(xyz.find("end_time: expected a number, got '0.01*(1+x)'"), std::string::npos) << xyz;
  EXPECT_NE(xyz.find("x, y, z and t have no value in a number key"), std::string::npos) << xyz;
  const std::string typo = edit("0.2+w", "0.2+ww");
  EXPECT_NE(typo.find("bodies[0] (block).shape.box.max[0]: expected a number, got '0.2+ww'"),
            std::string::npos)
      << typo;
  EXPECT_NE(typo.find("did you mean 'w'?"), std::string::npos) << typo;
  const std::string open = edit("\"0.01*speed\"", "\"0.01*(speed\"");
  EXPECT_NE(open.find("end_time: expected a number, got '0.01*(speed' (as an expression"),
            std::string::npos)
      << open;
  // A word that is no number stays the error it was (with a hint when near a variable).
  EXPECT_NE(edit("\"0.01*speed\"", "speeed")
                .find("end_time: expected a number, got 'speeed' (did "
                      "you mean 'speed'?)"),
            std::string::npos);
  EXPECT_NE(edit("\"0.01*speed\"", "\"1/0\"").find("end_time: expected a finite number"),
            std::string::npos);
  EXPECT_NE(edit("\"0.01*speed\"", "\"-speed\"")
                .find("end_time: must be positive, got "
                      "'-speed' = -2"),
            std::string::npos);
  // The variables themselves are plain numbers.
  EXPECT_NE(edit("w: 0.4", "w: 2*2").find("variables.w: expected a number, got '2*2'"),
            std::string::npos);
  for (const std::string& m : {xyz, typo, open}) EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

}  // namespace
}  // namespace monosph
