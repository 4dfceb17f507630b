// Scene `variables`: named numbers every expression can use, changed by --set and study --vary.
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

}  // namespace
}  // namespace monosph
