// Malformed scenes and command lines: exit code 2 and a one-line message naming the problem.
#include <gtest/gtest.h>

#include <filesystem>

#include "../validation/run_helpers.hpp"

using namespace monosph::test;

namespace {

struct Case {
  const char* file;
  const char* message;  // must appear in the output
};

const Case kCases[] = {
    {"typo_key.yaml", "end_tme: unknown key"},
    {"missing_material.yaml", "bodies[0] (block).material: no material named 'watr'"},
    {"negative_dp.yaml", "dp: must be positive"},
    {"body_outside.yaml", "bodies[0] (block).shape: extends outside the domain along y"},
    {"invalid_yaml.yaml", "invalid YAML at line"},
    {"wrong_type.yaml", "dp: expected a number, got 'fine'"},
    {"bad_dimension.yaml", "dimension: must be 2 or 3"},
    {"bad_phase.yaml", "phase: 'plasma' is not allowed"},
    {"bad_shape.yaml", "unknown shape"},
    {"material_typo.yaml", "materials.water.density_typo: unknown key"},
    {"bad_periodic.yaml", "domain.periodic: 'w' is not an axis"},
    {"bad_expression.yaml", "initial.density: invalid expression"},
    {"overlap.yaml", "overlaps body 'block'"},
    {"periodic_too_short.yaml", "periodic axis x"},
    {"probe_unknown_field.yaml", "no particle field 'temperature'"},
    {"output_unknown_field.yaml", "output.fields: no particle field 'vorticity'"},
    {"surface_typo.yaml", "surfaces[0] (floor).frictoin: unknown key"},
    {"missing_stl.yaml", "surfaces[0] (tool).stl: cannot read STL file"},
    {"clusters_not_union.yaml",
     "bodies[0] (grains).clusters: per_part needs a shape that is a union"},
    {"contact_law_typo.yaml", "contact.law: 'herz' is not allowed"},
    {"self_contact_too_large.yaml",
     "bodies[0] (block).self_contact.distance: must be below 1 (a fraction of dp)"},
    {"plasticity_bad_word.yaml",
     "materials.al.plasticity: expected a map {A, B, n, ...} or 'none'"},
    {"plasticity_none_keeps_damage.yaml",
     "damage grows with plastic strain: give `plasticity` too, or `damage: none`"},
    {"profile_zero_bins.yaml", "probes.list[0].bins: must be at least 1, got 0"},
    {"rigid_probe_not_rigid.yaml", "probes.list[0].body: 'block' is not a rigid body"},
    {"lubrication_no_rigid.yaml", "lubrication: needs a rigid body"},
    {"lubrication_min_gap.yaml", "lubrication.min_gap: must be below lubrication.cutoff"},
    {"cavitation_positive.yaml", "materials.water.cavitation_pressure: must be <= 0"},
    {"background_pressure_free_surface.yaml",
     "materials.water.background_pressure: the fluid has a free surface"},
    {"unknown_variable.yaml", "bodies[0] (block).initial.velocity[0]: invalid expression 'sped'"},
    {"weight_ignored.yaml",
     "probes.list[0].weight: only integral, mean and kinetic_energy probes take a weight"},
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.file;
}

}  // namespace

class BadScene : public ::testing::TestWithParam<Case> {};

TEST_P(BadScene, ExitsWithCode2AndNamesTheProblem) {
  const Case& c = GetParam();
  // A folder per case: ctest runs the cases side by side, and a run locks its folder.
  auto r = run_monosph("run " + source("tests/bad_input/scenes/") + c.file + " --out " +
                       out_dir(std::string("bad_") + c.file) + " --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
  // One line, no stack trace.
  EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

INSTANTIATE_TEST_SUITE_P(Scenes, BadScene, ::testing::ValuesIn(kCases), [](const auto& info) {
  std::string n = info.param.file;
  return n.substr(0, n.find('.'));
});

TEST(BadInput, UnreadableSceneFile) {
  auto r = run_monosph("run /nonexistent/scene.yaml --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("/nonexistent/scene.yaml: cannot read scene file"), std::string::npos)
      << r.output;
}

TEST(BadInput, UnwritableOutputFolder) {
  auto r = run_monosph("run " + source("cases/acoustic_wave/scene.yaml") +
                       " --out /proc/monosph-out --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("/proc/monosph-out"), std::string::npos) << r.output;
}

TEST(BadInput, UnknownSetKey) {
  auto r = run_monosph("run " + source("cases/acoustic_wave/scene.yaml") +
                       " --set time_stp.cfl=0.2 --quiet --out " + out_dir("bad"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("time_stp: unknown key"), std::string::npos) << r.output;
}

TEST(BadInput, SetOfAnUndeclaredVariable) {
  auto r = run_monosph("run " + source("cases/erosion_map/scene.yaml") +
                       " --set variables.angel=45 --quiet --out " + out_dir("bad"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--set variables.angel: the scene declares no variable 'angel' "
                          "(variables: angle, speed, seed, length, depth, nonlocal); did you mean "
                          "'angle'?"),
            std::string::npos)
      << r.output;
  EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(BadInput, MissingRestartFile) {
  auto r = run_monosph("run --restart /nonexistent.h5 --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("/nonexistent.h5"), std::string::npos) << r.output;
}

TEST(BadInput, DivergingRunStopsWithDiagnosisAndLastFrame) {
  // A pressure blast far outside the weakly compressible regime: the run must stop with a named
  // particle, exit 3, and leave a last frame and a summary with the reason.
  const std::string out = out_dir("diverging");
  auto d = run_monosph("run " + source("tests/bad_input/scenes/diverging.yaml") +
                       " --quiet --out " + out);
  EXPECT_EQ(d.code, 3) << d.output;
  EXPECT_NE(d.output.find("particle id"), std::string::npos) << d.output;
  auto js = summary(out);
  EXPECT_NE(js["status"].get<std::string>(), "completed");
  EXPECT_TRUE(std::filesystem::exists(out + "/diverging.pvd"));
}
