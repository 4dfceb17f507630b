// Bad-input corpus, part 3: rigid surfaces, contact, lubrication, probes (every type family),
// references and checks.
#include "corpus.hpp"

using namespace monosph::test;

namespace {

const char* const kFloor = "{name: floor, segment: [[0, 0.005], [0.05, 0.005]], friction: 0.1}";
const char* const kProbes = "    - {name: hits, type: grain_impacts}";  // kGrains' last probe
const char* const kFluidProbes = "    - {name: ke, type: kinetic_energy}";

const SceneCase kSurfaceCases[] = {
    {"surface_without_geometry", kGrains, kFloor, "{name: floor, friction: 0.1}",
     "surfaces[0] (floor): give exactly one geometry key"},
    {"surface_two_geometries", kGrains, kFloor,
     "{name: floor, segment: [[0, 0.005], [0.05, 0.005]], polyline: [[0, 0], [1, 1]]}",
     "surfaces[0] (floor): give exactly one geometry key (2D: box, plane, segment, polyline, "
     "polygon)"},
    {"segment_coincident", kGrains, "segment: [[0, 0.005], [0.05, 0.005]]",
     "segment: [[0, 0.005], [0, 0.005]]", "surfaces[0] (floor).segment: points 0 and 1 coincide"},
    {"segment_three_points", kGrains, "segment: [[0, 0.005], [0.05, 0.005]]",
     "segment: [[0, 0.005], [0.05, 0.005], [0.05, 0.01]]",
     "surfaces[0] (floor).segment: expected two points"},
    {"rectangle_in_2d", kGrains, "segment: [[0, 0.005], [0.05, 0.005]]",
     "rectangle: [[0, 0], [1, 0], [1, 1], [0, 1]]", "surfaces[0] (floor).rectangle: unknown key"},
    {"plane_zero_normal", kSolid3d, "normal: [0, 1, 0]", "normal: [0, 0, 0]",
     "surfaces[0] (anvil).plane.normal: must not be zero"},
    {"plane_size_negative", kSolid3d, "size: [0.2, 0.2]", "size: [0.2, -0.2]",
     "surfaces[0] (anvil).plane.size: side lengths must be positive"},
    {"triangle_two_corners", kSolid3d,
     "[[[0.15, 0.001, 0.15], [0.19, 0.001, 0.15], [0.15, 0.001, 0.19]]]",
     "[[[0.15, 0.001, 0.15], [0.19, 0.001, 0.15]]]",
     "surfaces[1] (wedge).triangles[0]: expected three corners"},
    {"stl_is_a_folder", kSolid3d,
     "triangles: [[[0.15, 0.001, 0.15], [0.19, 0.001, 0.15], [0.15, "
     "0.001, 0.19]]]",
     "stl: /tmp", "surfaces[1] (wedge).stl: cannot read STL file '/tmp' (it is a folder)"},
    // A device never ends: it ran out of memory after 11 s (exit 4, std::bad_alloc).
    {"stl_is_dev_zero", kSolid3d,
     "triangles: [[[0.15, 0.001, 0.15], [0.19, 0.001, 0.15], [0.15, "
     "0.001, 0.19]]]",
     "stl: /dev/zero",
     "surfaces[1] (wedge).stl: cannot read STL file '/dev/zero' (it is a character device, not "
     "a regular file)"},
    {"surface_friction_negative", kGrains, "friction: 0.1}", "friction: -0.1}",
     "surfaces[0] (floor).friction: must not be negative"},
    {"poisson_without_stiffness", kGrains, "friction: 0.1}", "friction: 0.1, poisson_ratio: 0.3}",
     "surfaces[0] (floor).poisson_ratio: needs a stiffness"},
    {"poisson_above_half", kGrains, "friction: 0.1}",
     "friction: 0.1, stiffness: 1e9, poisson_ratio: 0.6}",
     "surfaces[0] (floor).poisson_ratio: must be below 0.5"},
    {"surface_name_twice", kGrains, kFloor,
     "{name: floor, segment: [[0, 0.005], [0.05, 0.005]]}\n  - {name: floor, segment: [[0, 0.045], "
     "[0.05, 0.045]]}",
     "surfaces[1] (floor).name: duplicate surface name"},
    {"surface_velocity_infinite", kGrains, "friction: 0.1}",
     "friction: 0.1, velocity: [\"1/0\", 0]}",
     "surfaces[0] (floor).velocity[0]: '1/0' is inf at t = 0"},
    {"surface_velocity_x", kGrains, "friction: 0.1}", "friction: 0.1, velocity: [\"x\", 0]}",
     "surfaces[0] (floor).velocity[0]: invalid expression 'x'"},
    {"surface_scale_zero", kGrains, "friction: 0.1}", "friction: 0.1, scale: 0}",
     "surfaces[0] (floor).scale: must be positive"},
    {"contact_law_without_strength", kGrains, "law: hertz,", "law: lennard_jones,",
     "contact.strength: missing (required)"},
    {"contact_p1_below_p2", kGrains, "law: hertz,",
     "law: lennard_jones, strength: 1, p1: 2, p2: 4,", "contact.p1: must exceed contact.p2"},
    {"contact_strength_with_hertz", kGrains, "law: hertz,", "law: hertz, strength: 1,",
     "contact.strength: applies to law lennard_jones only"},
    {"contact_distance_zero", kGrains, "distance: 1.0,", "distance: 0,",
     "contact.distance: must be positive"},
    {"lubrication_unknown_key", kGrains, "min_gap: 0.05}", "min_gap: 0.05, viscosty: 1}",
     "lubrication.viscosty: unknown key"},
    {"lubrication_without_fluid", kGrains, "    phase: fluid\n", "    phase: wall\n",
     "lubrication.viscosity: is required without a fluid body"},
};

const SceneCase kProbeCases[] = {
    {"probes_list_missing", kFluid, "  every: 0\n  list:\n", "  every: 0\n  lst:\n",
     "probes.lst: unknown key; did you mean 'list'?"},
    {"probes_every_negative", kFluid, "  every: 0\n", "  every: -1\n",
     "probes.every: must not be negative"},
    {"probe_type_typo", kFluid, "type: kinetic_energy}", "type: kinetic}",
     "probes.list[0].type: 'kinetic' is not allowed"},
    {"probe_name_twice", kFluid, "{name: tip, type: tracked", "{name: ke, type: tracked",
     "probes.list[3] (ke).name: duplicate probe column 'ke'"},
    {"probe_column_clash", kGrains, kProbes,
     "    - {name: hits, type: grain_impacts}\n    - {name: centre_x, type: max_speed}",
     "probes.list[4] (centre_x).name: duplicate probe column 'centre_x'"},
    {"probe_name_comma", kFluid, "{name: ke,", "{name: \"k,e\",",
     "probes.list[0].name: 'k,e' is not a column name"},
    {"probe_name_empty", kFluid, "{name: ke,", "{name: \"\",",
     "probes.list[0].name: must not be empty"},
    {"probe_weight_infinite", kFluid, "weight: \"cos(x)\"", "weight: \"1/0\"",
     "probes.list[2] (mode).weight: '1/0' is inf at"},
    {"probe_weight_on_max_speed", kFluid, kFluidProbes,
     "    - {name: ke, type: max_speed, weight: \"x\"}",
     "probes.list[0].weight: only integral, mean and kinetic_energy probes take a weight"},
    {"probe_field_component_w", kFluid, "field: position.y", "field: position.w",
     "probes.list[3].field: component 'w' is not an axis"},
    {"probe_field_z_in_2d", kFluid, "field: position.y", "field: position.z",
     "probes.list[3].field: component 'z' is not an axis"},
    {"probe_unknown_body", kFluid, "body: water}", "body: watr}",
     "probes.list[1].body: no body named 'watr'"},
    {"rigid_probe_without_body", kGrains, "type: rigid_centre, body: grains}",
     "type: rigid_centre}", "probes.list[0].body: missing (the name of a rigid body)"},
    {"surface_probe_unknown_surface", kGrains, "surface: floor}", "surface: flor}",
     "probes.list[1].surface: no surface named 'flor' in surfaces; did you mean 'floor'?"},
    {"surface_probe_surface_and_body", kGrains, "surface: floor}", "surface: floor, body: oil}",
     "probes.list[1]: give either surface or body, not both"},
    {"penetration_unknown_target", kGrains, kProbes,
     "    - {name: hits, type: penetration, body: grains, target: targt}",
     "probes.list[3].target: no body named 'targt'"},
    {"value_at_without_point", kFluid, kFluidProbes,
     "    - {name: ke, type: value_at, field: pressure}",
     "probes.list[0].point: missing (required)"},
    {"diameter_zero_axis", kFluid, kFluidProbes,
     "    - {name: ke, type: diameter, body: plate, point: [0.27, 0.1], axis: [0, 0]}",
     "probes.list[0].axis: must not be the zero vector"},
    {"profile_range_inverted", kGrains, "axis: y, bins: 10}", "axis: y, bins: 10, range: [1, 0]}",
     "probes.list[2].range: must be [lo, hi] with lo < hi"},
    {"profile_axis_w", kGrains, "axis: y, bins: 10}", "axis: w, bins: 10}",
     "probes.list[2].axis: 'w' is not an axis"},
    {"profile_without_bins", kGrains, "axis: y, bins: 10}", "axis: y}",
     "probes.list[2].bins: missing"},
    {"pieces_min_particles_zero", kGrains, kProbes,
     "    - {name: hits, type: pieces, body: target, min_particles: 0}",
     "probes.list[3].min_particles: must be at least 1"},
    {"reaction_force_not_a_bc", kFluid, kFluidProbes,
     "    - {name: ke, type: reaction_force, body: plate}",
     "probes.list[0].body: reaction_force needs the name of a boundary condition"},
    {"contact_energy_with_body", kGrains, kProbes,
     "    - {name: hits, type: contact_energy, body: grains}",
     "probes.list[3].body: contact_energy is the energy of all contacts; it takes no body"},
    {"wall_pressure_size_zero", kFluid, kFluidProbes,
     "    - {name: ke, type: wall_pressure, body: tank, center: [0.03, 0.1], normal: x, size: 0}",
     "probes.list[0].size: must be positive"},
    {"wall_pressure_normal_zero", kFluid, kFluidProbes,
     "    - {name: ke, type: wall_pressure, body: tank, center: [0.03, 0.1], normal: [0, 0], size: "
     "0.01}",
     "probes.list[0].normal: must be a finite non-zero vector"},
    {"wall_pressure_on_a_fluid", kFluid, kFluidProbes,
     "    - {name: ke, type: wall_pressure, body: water, center: [0.03, 0.1], normal: x, size: "
     "0.01}",
     "probes.list[0].body: 'water' is a fluid"},
    {"wall_pressure_off_the_face", kFluid, kFluidProbes,
     "    - {name: ke, type: wall_pressure, body: tank, center: [0.1, 0.1], normal: x, size: 0.01}",
     "probes.list[0].center: not on the face of 'tank'"},
    {"wall_pressure_normal_into_the_wall", kFluid, kFluidProbes,
     "    - {name: ke, type: wall_pressure, body: tank, center: [0.03, 0.1], normal: -x, size: "
     "0.01}",
     "probes.list[0].normal: points into 'tank'"},
    {"probe_unknown_key", kFluid, "{name: ke, type: kinetic_energy}",
     "{name: ke, type: kinetic_energy, colour: red}", "probes.list[0].colour: unknown key"},
    {"reference_unknown_probe", kFluid, "probe: mass, measure: final}",
     "probe: mas, measure: final}", "reference[0].probe: no probe named 'mas'"},
    {"reference_measure_typo", kFluid, "measure: final}", "measure: last}",
     "reference[0].measure: 'last' is not allowed"},
    {"reference_not_a_list", kFluid, "reference:\n", "reference: {a: 1}\nunused:\n",
     "reference: expected a list"},
    {"reference_name_twice", kFluid,
     "  - {name: final_mass, value: 1, probe: mass, measure: final}",
     "  - {name: final_mass, value: 1, probe: mass, measure: final}\n  - {name: final_mass, probe: "
     "ke, measure: max}",
     "reference[1] (final_mass).name: duplicate reference name"},
    {"check_without_bounds", kFluid, "measure: drift, max: 0.01}", "measure: drift}",
     "checks[0]: give min, max or both"},
    {"check_min_above_max", kFluid, "measure: drift, max: 0.01}",
     "measure: drift, min: 1, max: 0.01}", "checks[0].min: must not exceed max"},
    {"check_measure_typo", kFluid, "measure: drift,", "measure: drfit,",
     "checks[0].measure: 'drfit' is not allowed"},
    {"check_unknown_probe", kFluid, "{name: mass_kept, probe: mass,",
     "{name: mass_kept, probe: mss,", "checks[0].probe: no probe named 'mss'"},
    {"check_name_twice", kFluid, "  - {name: mass_kept, probe: mass, measure: drift, max: 0.01}",
     "  - {name: mass_kept, probe: mass, measure: drift, max: 0.01}\n  - {name: mass_kept, probe: "
     "ke, measure: max, max: 1}",
     "checks[1] (mass_kept).name: duplicate check name"},
};

// Contact between solid bodies (`solid_contact`): kSolid3d has three solid bodies of three
// continua, kFluid one solid body.
const SceneCase kSolidContactCases[] = {
    {"solid_contact_key_typo", kSolid3d, "", "solid_contact: {distance: 1.0, frction: 0.3}\n",
     "solid_contact.frction: unknown key"},
    {"solid_contact_distance_zero", kSolid3d, "", "solid_contact: {distance: 0}\n",
     "solid_contact.distance: must be positive"},
    {"solid_contact_distance_beyond_support", kSolid3d, "", "solid_contact: {distance: 3}\n",
     "solid_contact.distance: must lie in (0, 2]"},
    {"solid_contact_friction_negative", kSolid3d, "", "solid_contact: {friction: -0.2}\n",
     "solid_contact.friction: must not be negative"},
    {"solid_contact_damping_text", kSolid3d, "", "solid_contact: {damping: high}\n",
     "solid_contact.damping: expected a number"},
    {"solid_contact_one_continuum", kFluid, "", "solid_contact: {distance: 1.0}\n",
     "solid_contact: needs two solid bodies of different continua"},
    {"solid_contact_force_without_body", kSolid3d, "",
     "solid_contact: {}\nprobes:\n  list:\n    - {name: f, type: solid_contact_force}\n",
     "probes.list[0].body: missing (the name of a solid body"},
    {"solid_contact_probe_without_section", kFluid, kFluidProbes,
     "    - {name: ke, type: kinetic_energy}\n    - {name: sc, type: solid_contact_pairs}",
     "probes.list[1].type: 'solid_contact_pairs' needs a solid_contact section"},
};

class CorpusCoupling : public ::testing::TestWithParam<SceneCase> {};
TEST_P(CorpusCoupling, ExitsWithCode2AndOneLineNamingTheKey) {
  run_scene_case(GetParam());
}
auto case_name = [](const auto& info) { return std::string(info.param.name); };
INSTANTIATE_TEST_SUITE_P(Surfaces, CorpusCoupling, ::testing::ValuesIn(kSurfaceCases), case_name);
INSTANTIATE_TEST_SUITE_P(Probes, CorpusCoupling, ::testing::ValuesIn(kProbeCases), case_name);
INSTANTIATE_TEST_SUITE_P(SolidContact, CorpusCoupling, ::testing::ValuesIn(kSolidContactCases),
                         case_name);

}  // namespace
