// The stabilisation variants of `monosph study` as scene keys of every solid body.
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "solid/solid_keys.hpp"
#include "study.hpp"

namespace monosph {
namespace {

const std::string plate = MONOSPH_CASES_DIR "/oscillating_plate/scene.yaml";

Scene with(const std::string& variant) {
  auto sets = stabilisation_overrides(plate, {}, variant);
  return load_scene_file(plate, sets);
}

TEST(StudyVariants, NoneTurnsOffHourglassControlAndArtificialStress) {
  Scene s = with("none");
  ASSERT_EQ(s.bodies[0].phase, "solid");
  EXPECT_EQ(module_params<SolidBodyKeys>(s.bodies[0].params).hg_xi, 0);
  EXPECT_EQ(s.bodies[0].as_epsilon, 0);
}

TEST(StudyVariants, ArtificialStressReplacesHourglassControl) {
  Scene s = with("artificial_stress");
  EXPECT_EQ(module_params<SolidBodyKeys>(s.bodies[0].params).hg_xi, 0);
  EXPECT_DOUBLE_EQ(s.bodies[0].as_epsilon, 0.3);
  EXPECT_DOUBLE_EQ(s.bodies[0].as_n, 4);
}

TEST(StudyVariants, HourglassKeepsTheScenesOwnControl) {
  Scene s = with("hourglass");
  EXPECT_DOUBLE_EQ(module_params<SolidBodyKeys>(s.bodies[0].params).hg_xi,
                   0.5);  // the plate's xi (MMB Table 2)
  EXPECT_EQ(s.bodies[0].as_epsilon, 0);
}

}  // namespace
}  // namespace monosph
