// Bad-input corpus, part 1: the YAML itself and the scene-wide keys (name, dp, kernel, domain,
// neighbours, variables, limits, time_step, guards, output, materials).
#include "corpus.hpp"

using namespace monosph::test;

namespace {

const SceneCase kYaml[] = {
    {"duplicate_top_key", kFluid, "dp: 0.01\n", "dp: 0.01\ndp: 0.02\n",
     "dp: given twice (lines 4 and 5)"},
    {"duplicate_nested_key", kFluid, "{density: 1000, sound_speed: 10,",
     "{density: 1000, density: 900, sound_speed: 10,", "materials.water.density: given twice"},
    {"duplicate_material", kFluid, "  steel: {density: 7800,",
     "  water: {density: 1}\n  steel: {density: 7800,", "materials.water: given twice"},
    {"duplicate_list_item_key", kFluid, "    hourglass: {xi: 1}",
     "    hourglass: {xi: 1}\n    hourglass: {xi: 2}", "bodies[2].hourglass: given twice"},
    {"complex_key", kFluid, "", "[a, b]: 1\n", "a key must be a plain name, got a list"},
    {"complex_key_nested", kFluid, "{type: cubic_spline,", "{type: cubic_spline, {x: 1}: 2,",
     "kernel: a key must be a plain name, got a map"},
    {"invalid_utf8_name", kFluid, "name: corpus", "name: \"corpus\xff\xfe\"",
     "name: not valid UTF-8"},
    {"invalid_utf8_description", kFluid, "a tank with water", "a tank \xc3\x28 water",
     "description: not valid UTF-8"},
    {"empty_scene", "", "", "", "a scene must be a YAML map of keys"},
    {"scene_is_a_list", "", "", "- dp\n- 0.01\n", "a scene must be a YAML map of keys"},
    {"unknown_alias", kFluid, "dp: 0.01", "dp: *fine", "invalid YAML at line 4"},
    {"tab_indent", kFluid, "    phase: wall", "\tphase: wall", "invalid YAML at line"},
    {"null_required_key", kFluid, "dp: 0.01", "dp:", "dp: missing (required)"},
    // Aliases: one inside the block it names, a merge key of its own map (both a cycle that made
    // the tree check recurse until SIGSEGV), nine levels of nine aliases (3.9e8 nodes expanded).
    {"alias_cycle_in_list", kFluid, "bodies:\n  - name: tank\n",
     "bodies: &b\n  - name: tank\n    seed: *b\n",
     "line 14: an alias refers to the block that contains it (line 12)"},
    {"merge_key_cycle", kFluid, "output: {every: 5.0e-6, checkpoint_every: 0}",
     "output: &o {every: 5.0e-6, <<: *o}", "an alias refers to the block that contains it"},
    {"billion_laughs", kFluid, "",
     "lol0: &a0 [lol]\n"
     "lol1: &a1 [*a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0]\n"
     "lol2: &a2 [*a1, *a1, *a1, *a1, *a1, *a1, *a1, *a1, *a1]\n"
     "lol3: &a3 [*a2, *a2, *a2, *a2, *a2, *a2, *a2, *a2, *a2]\n"
     "lol4: &a4 [*a3, *a3, *a3, *a3, *a3, *a3, *a3, *a3, *a3]\n"
     "lol5: &a5 [*a4, *a4, *a4, *a4, *a4, *a4, *a4, *a4, *a4]\n"
     "lol6: &a6 [*a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5]\n"
     "lol7: &a7 [*a6, *a6, *a6, *a6, *a6, *a6, *a6, *a6, *a6]\n"
     "lol8: &a8 [*a7, *a7, *a7, *a7, *a7, *a7, *a7, *a7, *a7]\n"
     "lol9: &a9 [*a8, *a8, *a8, *a8, *a8, *a8, *a8, *a8, *a8]\n",
     "aliases expand the scene by more than 1000000 nodes"},
    // A merge key brings the keys of another block (YAML 1.1); a misspelt one beside them is named.
    {"merge_key_beside_a_typo", kFluid,
     "  water: {density: 1000, sound_speed: 10, viscosity: 1.0e-3}",
     "  water: &w {density: 1000, sound_speed: 10, viscosity: 1.0e-3}\n  oil: {<<: *w, densty: "
     "900}",
     "materials.oil.densty: unknown key"},
};

const SceneCase kTopLevel[] = {
    {"name_empty", kFluid, "name: corpus", "name: \"\"", "name: must not be empty"},
    {"name_dotdot", kFluid, "name: corpus", "name: \"..\"", "name: '..' is not a plain file name"},
    {"name_slash", kFluid, "name: corpus", "name: out/corpus",
     "name: 'out/corpus' is not a plain file name"},
    {"name_newline", kFluid, "name: corpus", "name: \"a\\nb\"", "is not a plain file name"},
    // Bidirectional controls: "corpus\u202Eexe.txt" displays as "corpustxt.exe".
    {"name_bidi_override", kFluid, "name: corpus", "name: \"corpus\\u202Eexe.txt\"",
     "name: 'corpus\\u202Eexe.txt' is not a plain file name"},
    {"name_bidi_isolate", kFluid, "name: corpus", "name: \"a\\u2067b\"",
     "name: 'a\\u2067b' is not a plain file name"},
    {"name_too_long", kFluid, "name: corpus",
     "name: "
     "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
     "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
     "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa",
     "name: longer than 200 characters"},
    {"name_a_list", kFluid, "name: corpus", "name: [a, b]", "name: expected a text value"},
    {"dimension_text", kFluid, "dimension: 2", "dimension: two",
     "dimension: expected a number, got 'two'"},
    {"dimension_fraction", kFluid, "dimension: 2", "dimension: 2.5",
     "dimension: expected a whole number, got 2.5"},
    {"dp_zero", kFluid, "dp: 0.01", "dp: 0", "dp: must be positive, got 0"},
    {"dp_infinite", kFluid, "dp: 0.01", "dp: .inf", "dp: expected a finite number"},
    {"dp_nan", kFluid, "dp: 0.01", "dp: .nan", "dp: expected a finite number"},
    {"dp_overflow", kFluid, "dp: 0.01", "dp: 1e400", "dp: expected a finite number"},
    {"dp_larger_than_the_body", kFluid, "dp: 0.01", "dp: 0.2",
     "bodies[0] (tank).shape: contains no lattice node at dp = 0.2"},
    {"end_time_missing", kFluid, "end_time: 1.0e-5\n", "", "end_time: missing (required)"},
    {"end_time_negative", kFluid, "end_time: 1.0e-5", "end_time: -1", "end_time: must be positive"},
    {"body_force_short", kFluid, "body_force: [0, -9.81]", "body_force: [-9.81]",
     "body_force: expected a list of 2 numbers, got a list of 1"},
    {"modules_unknown", kFluid, "", "modules: [magic]\n", "modules: unknown module 'magic'"},
    {"domain_missing", kFluid, "domain: {min: [0, 0], max: [0.4, 0.3]}\n", "",
     "domain: missing (required)"},
    {"domain_inverted", kFluid, "domain: {min: [0, 0], max: [0.4, 0.3]}",
     "domain: {min: [0, 0], max: [-0.4, 0.3]}", "domain.max: must be greater than domain.min"},
    {"domain_3_numbers", kFluid, "domain: {min: [0, 0], max: [0.4, 0.3]}",
     "domain: {min: [0, 0, 0], max: [0.4, 0.3]}",
     "domain.min: expected a list of 2 numbers, got a list of 3"},
    {"domain_unknown_key", kFluid, "domain: {min: [0, 0], max: [0.4, 0.3]}",
     "domain: {min: [0, 0], max: [0.4, 0.3], periodc: [x]}", "domain.periodc: unknown key"},
    {"kernel_unknown", kFluid, "kernel: {type: cubic_spline, h_factor: 1.3}", "kernel: gauss",
     "kernel: 'gauss' is not allowed"},
    {"kernel_h_factor_tiny", kFluid, "h_factor: 1.3", "h_factor: 1e-9",
     "kernel.h_factor: must lie in [1, 3] (h / dp), got 1e-09"},
    {"kernel_h_factor_huge", kFluid, "h_factor: 1.3", "h_factor: 1e9",
     "kernel.h_factor: must lie in [1, 3] (h / dp), got 1e+09"},
    {"kernel_unknown_key", kFluid, "h_factor: 1.3", "hfactor: 1.3", "kernel.hfactor: unknown key"},
    {"neighbours_skin_zero", kFluid, "skin: 0.3", "skin: 0", "neighbours.skin: must be positive"},
    {"neighbours_skin_huge", kFluid, "skin: 0.3", "skin: 50",
     "neighbours.skin: must lie in (0, 2] (a fraction of h), got 50"},
    {"neighbours_reorder_negative", kFluid, "reorder_every: 1", "reorder_every: -1",
     "neighbours.reorder_every: must be 0 (never) or more"},
    {"limits_max_particles", kFluid, "", "limits: {max_particles: 100}\n",
     "dp: 0.01 gives 571 particles, more than limits.max_particles (100)"},
    {"limits_max_memory", kFluid, "", "limits: {max_memory: 1000}\n",
     "dp: 0.01 gives 571 particles, which need about"},
    {"limits_unknown_key", kFluid, "", "limits: {max_particle: 100}\n",
     "limits.max_particle: unknown key"},
    {"limits_negative", kFluid, "", "limits: {max_memory: -1}\n",
     "limits.max_memory: must be positive"},
    {"size_guard_dp_tiny", kFluid, "dp: 0.01", "dp: 1e-12",
     "dp: 1e-12 gives about 5.7e+22 particles, which need about"},
    {"size_guard_dp_small", kFluid, "dp: 0.01", "dp: 1e-5",
     "dp: 1e-05 gives about 5.7e+08 particles"},
};

const SceneCase kVariables[] = {
    {"variables_a_list", kFluid, "variables: {speed: 0.1}", "variables: [speed]",
     "variables: expected a map of names to numbers"},
    {"variable_reserved", kFluid, "variables: {speed: 0.1}", "variables: {speed: 0.1, x: 1}",
     "variables.x: 'x' already has a meaning in expressions"},
    {"variable_bad_name", kFluid, "variables: {speed: 0.1}", "variables: {speed: 0.1, 2fast: 1}",
     "variables.2fast: a variable name is a letter or _"},
    {"variable_text", kFluid, "variables: {speed: 0.1}", "variables: {speed: fast}",
     "variables.speed: expected a number, got 'fast'"},
    {"variable_twice", kFluid, "variables: {speed: 0.1}", "variables: {speed: 0.1, speed: 2}",
     "variables.speed: given twice"},
    {"variable_unknown_in_expression", kFluid, "velocity: [\"speed\", \"0\"]",
     "velocity: [\"sped\", \"0\"]",
     "bodies[1] (water).initial.velocity[0]: invalid expression 'sped'"},
    // Number keys may be expressions of the variables (no x, y, z, t).
    {"number_expression_unknown_name", kFluid, "dp: 0.01", "dp: \"0.1*sped\"",
     "dp: expected a number, got '0.1*sped' (as an expression"},
    {"number_expression_with_x", kFluid, "end_time: 1.0e-5", "end_time: \"1e-5*(1+x)\"",
     "end_time: expected a number, got '1e-5*(1+x)'"},
    {"number_expression_unbalanced", kFluid, "max: [0.2, 0.15]", "max: [\"0.2*(1\", 0.15]",
     "bodies[1] (water).shape.box.max[0]: expected a number, got '0.2*(1'"},
    {"number_expression_not_finite", kFluid, "dp: 0.01", "dp: \"speed/0\"",
     "dp: expected a finite number, got 'speed/0'"},
};

const SceneCase kTimeStep[] = {
    {"cfl_tiny", kFluid, "cfl: 0.3", "cfl: 1e-300",
     "time_step.cfl: must lie in [0.001, 1], got 1e-300"},
    {"cfl_above_one", kFluid, "cfl: 0.3", "cfl: 2", "time_step.cfl: must lie in [0.001, 1], got 2"},
    {"force_factor_tiny", kFluid, "force_factor: 0.25", "force_factor: 1e-200",
     "time_step.force_factor: must lie in [0.001, 1], got 1e-200"},
    {"time_step_max_negative", kFluid, "force_factor: 0.25}", "force_factor: 0.25, max: -1}",
     "time_step.max: must not be negative"},
    {"collapse_ratio_one", kFluid, "force_factor: 0.25}", "force_factor: 0.25, collapse_ratio: 1}",
     "time_step.collapse_ratio: must lie in (0, 1), got 1"},
    {"newmark_gamma_two", kFluid, "force_factor: 0.25}", "force_factor: 0.25, newmark_gamma: 2}",
     "time_step.newmark_gamma: must lie in [0.5, 1]"},
    {"acoustic_cfl_tiny", kFluid, "force_factor: 0.25}",
     "force_factor: 0.25, dual_criteria: {acoustic_cfl: 1e-300}}",
     "time_step.dual_criteria.acoustic_cfl: must lie in [0.001, 1], got 1e-300"},
    {"advection_cfl_tiny", kFluid, "force_factor: 0.25}",
     "force_factor: 0.25, dual_criteria: {advection_cfl: 1e-300}}",
     "time_step.dual_criteria.advection_cfl: must be 0 (off) or lie in [0.001, 1], got 1e-300"},
    {"dual_criteria_kernel", kFluid, "force_factor: 0.25}",
     "force_factor: 0.25, dual_criteria: {kernel: warm}}",
     "time_step.dual_criteria.kernel: 'warm' is not allowed"},
    {"time_step_unknown_key", kFluid, "cfl: 0.3", "clf: 0.3", "time_step.clf: unknown key"},
    {"guards_mach_zero", kFluid, "max_mach: 0.5", "max_mach: 0",
     "guards.max_mach: must be positive"},
    {"guards_min_distance_one", kFluid, "min_distance: 0.1", "min_distance: 1",
     "guards.min_distance: must lie in [0, 1) (a fraction of dp), got 1"},
    {"guards_unknown_key", kFluid, "max_mach: 0.5", "max_mac: 0.5", "guards.max_mac: unknown key"},
    {"output_every_negative", kFluid, "every: 5.0e-6", "every: -1",
     "output.every: must not be negative"},
    {"output_checkpoint_text", kFluid, "checkpoint_every: 0", "checkpoint_every: often",
     "output.checkpoint_every: expected a number, got 'often'"},
    {"output_fields_a_map", kFluid, "checkpoint_every: 0}", "checkpoint_every: 0, fields: {a: 1}}",
     "output.fields: expected a list, got a map"},
    // Steps end on checkpoint times: 1e-12 s made a 0.01 s run take 1e10 steps (and print nothing).
    {"output_checkpoint_every_tiny", kFluid, "checkpoint_every: 0}", "checkpoint_every: 1.0e-12}",
     "output.checkpoint_every: 1e-12 s is shorter than the time step ("},
};

const SceneCase kMaterials[] = {
    {"materials_empty", kFluid, "materials:\n", "materials: {}\nunused:\n",
     "materials: expected a map of named materials"},
    {"material_a_number", kFluid,
     "  steel: {density: 7800, bulk_modulus: 1.6e11, shear_modulus: 8.0e10}", "  steel: 7800",
     "materials.steel: expected a map of keys, got '7800'"},
    {"material_no_density", kFluid, "{density: 7800, bulk_modulus", "{bulk_modulus",
     "materials.steel.density: missing (required)"},
    {"material_both_moduli", kFluid, "sound_speed: 10,", "sound_speed: 10, bulk_modulus: 1e5,",
     "materials.water: give either bulk_modulus or sound_speed, not both"},
    {"material_unknown_preset", kFluid, "{density: 7800,", "{preset: steel, density: 7800,",
     "materials.steel.preset: no shipped material 'steel'"},
    {"material_negative_shear", kFluid, "shear_modulus: 8.0e10", "shear_modulus: -8.0e10",
     "materials.steel.shear_modulus: must not be negative"},
    {"material_negative_viscosity", kFluid, "viscosity: 1.0e-3", "viscosity: -1",
     "materials.water.viscosity: must not be negative"},
    {"material_taylor_quinney", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, taylor_quinney: 2}",
     "materials.steel.taylor_quinney: must lie in [0, 1]"},
    {"material_heat_capacity_negative", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, heat_capacity: -1}",
     "materials.steel.heat_capacity: must not be negative"},
    {"material_elasticity_typo", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, elasticity: neohookean}",
     "materials.steel.elasticity: 'neohookean' is not allowed"},
    {"neo_hookean_eulerian", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, elasticity: neo_hookean}",
     "bodies[2] (plate).material: elasticity: neo_hookean needs formulation: total_lagrangian"},
    {"plasticity_without_A", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, plasticity: {B: 1e8}}", "materials.steel.plasticity.A: missing"},
    {"plasticity_melting_below_reference", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, plasticity: {A: 3e8, melting_temperature: 200}}",
     "materials.steel.plasticity.melting_temperature: must exceed reference_temperature"},
    {"plasticity_type", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, plasticity: {type: zerilli, A: 3e8}}",
     "materials.steel.plasticity.type: 'zerilli' is not allowed"},
    {"damage_without_D1", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, plasticity: {A: 3e8}, damage: {D2: 1, D3: 1}}",
     "materials.steel.damage.D1: missing"},
    {"damage_bad_word", kFluid, "shear_modulus: 8.0e10}", "shear_modulus: 8.0e10, damage: off}",
     "materials.steel.damage: expected a map {D1..D5} or 'none'"},
    {"damage_min_failure_strain", kFluid, "shear_modulus: 8.0e10}",
     "shear_modulus: 8.0e10, plasticity: {A: 3e8}, damage: {D1: 0.1, D2: 1, D3: -1, "
     "min_failure_strain: 0}}",
     "materials.steel.damage.min_failure_strain: must be positive"},
    // Non-local damage (issue 51): a length, more than one dp (kGrains: dp = 1 mm).
    {"damage_nonlocal_negative", kGrains, "al: {preset: Al6061-T6}",
     "al: {preset: Al6061-T6, damage: {nonlocal_length: -1e-3}}",
     "materials.al.damage.nonlocal_length: must not be negative"},
    {"damage_nonlocal_below_dp", kGrains, "al: {preset: Al6061-T6}",
     "al: {preset: Al6061-T6, damage: {nonlocal_length: 5e-4}}",
     "materials.al.damage.nonlocal_length: must exceed the particle spacing dp"},
    {"preset_plasticity_unknown_key", kGrains, "al: {preset: Al6061-T6}",
     "al: {preset: Al6061-T6, plasticity: {A: 3e8, Q: 1}}",
     "materials.al.plasticity.Q: unknown key"},
    {"sound_speed_zero", kFluid, "sound_speed: 10,", "sound_speed: 0,",
     "materials.water.sound_speed: must be positive"},
};

class CorpusKeys : public ::testing::TestWithParam<SceneCase> {};
TEST_P(CorpusKeys, ExitsWithCode2AndOneLineNamingTheKey) {
  run_scene_case(GetParam());
}
auto case_name = [](const auto& info) { return std::string(info.param.name); };
INSTANTIATE_TEST_SUITE_P(Yaml, CorpusKeys, ::testing::ValuesIn(kYaml), case_name);
INSTANTIATE_TEST_SUITE_P(TopLevel, CorpusKeys, ::testing::ValuesIn(kTopLevel), case_name);
INSTANTIATE_TEST_SUITE_P(Variables, CorpusKeys, ::testing::ValuesIn(kVariables), case_name);
INSTANTIATE_TEST_SUITE_P(TimeStep, CorpusKeys, ::testing::ValuesIn(kTimeStep), case_name);
INSTANTIATE_TEST_SUITE_P(Materials, CorpusKeys, ::testing::ValuesIn(kMaterials), case_name);

}  // namespace
