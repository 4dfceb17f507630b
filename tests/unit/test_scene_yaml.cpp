// YAML anchors, aliases and merge keys in scenes: repeated blocks read as if written out; a
// cycle or a runaway expansion is refused with the line (tests/bad_input has the run corpus).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/types.hpp"
#include "scene/scene.hpp"

namespace monosph {
namespace {

// Two fluids from one anchored block (oil overrides the density beside the merge key), two
// bodies sharing an aliased shape and an aliased initial state.
const std::string kScene = R"yaml(
name: aliases
dimension: 2
dp: 0.1
domain: {min: [0, 0], max: [2, 1]}
materials:
  water: &fluid {density: 1000, sound_speed: 10, viscosity: 1.0e-3}
  oil: {<<: *fluid, density: 900}
bodies:
  - name: left
    phase: fluid
    material: water
    shape: {box: &unit {min: [0.1, 0.1], max: [0.5, 0.5]}}
    initial: &still {velocity: [0, 0]}
  - name: right
    phase: fluid
    material: oil
    shape: {box: {<<: *unit, max: [0.5, 0.9]}}
    initial: *still
end_time: 0.01
)yaml";

TEST(SceneYaml, AliasesAndMergeKeysRepeatBlocks) {
  const Scene s = load_scene_text(kScene);
  ASSERT_EQ(s.materials.size(), 2u);
  const Material& water = s.materials[s.material_index("water")];
  const Material& oil = s.materials[s.material_index("oil")];
  EXPECT_EQ(water.density, 1000);
  EXPECT_EQ(oil.density, 900);  // given beside the merge key: wins
  EXPECT_EQ(oil.viscosity, water.viscosity);
  EXPECT_EQ(oil.bulk_modulus, 900.0 * 10 * 10);
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.yaml.find("<<"), std::string::npos);  // the stored scene text has them resolved
}

std::string message(const std::string& text) {
  try {
    load_scene_text(text, {}, "s.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneYaml, CyclesAndRunawayAliasesAreRefusedWithTheLine) {
  EXPECT_EQ(message("name: a\nlist: &l [1, *l]\n"),
            "s.yaml: line 2: an alias refers to the block that contains it (line 2): the scene "
            "would be endless");
  EXPECT_EQ(message("output: &o\n  every: 1\n  nested: {<<: *o}\n"),
            "s.yaml: line 3: an alias refers to the block that contains it (line 1): the scene "
            "would be endless");
  // Level k names ten of level k-1 (11 nodes at level 0): the aliases of levels 1-4 add
  // 123,340 nodes, the eighth alias of level 5 (line 6) passes 10^6.
  std::ostringstream yaml;
  yaml << "a0: &a0 [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]\n";
  for (int k = 1; k <= 6; ++k) {
    yaml << 'a' << k << ": &a" << k << " [*a" << k - 1;
    for (int r = 1; r < 10; ++r) yaml << ", *a" << k - 1;
    yaml << "]\n";
  }
  const std::string text = yaml.str();
  EXPECT_NE(message(text).find("line 6: aliases expand the scene by more than 1000000 nodes"),
            std::string::npos)
      << message(text);
  // An alias used once more than written is fine (the scene fails on its own keys instead).
  EXPECT_EQ(message("a: &x [1, 2]\nb: *x\n").find("aliases"), std::string::npos);
}

}  // namespace
}  // namespace monosph
