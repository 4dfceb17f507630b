// The parsed configuration of a scene as JSON (`monosph info SCENE --config`): every value the
// run uses, defaults included, so that two versions of the scene reader can be compared.
#include "scene/scene_dump.hpp"

namespace monosph {

namespace {

using nlohmann::json;

json shape_json(const Shape& s) {
  json j = {{"kind", static_cast<int>(s.kind)},
            {"a", s.a},
            {"b", s.b},
            {"center", s.center},
            {"r0", s.r0},
            {"r1", s.r1},
            {"vertices", s.vertices}};
  for (const auto& part : s.parts) j["parts"].push_back(shape_json(part));
  return j;
}

// Each module's parameters merged into j (one object, keys sorted).
void add_params(json& j, const ParamMap& params) {
  for (const auto& [module, p] : params) j.update(p->dump());
}

// The generic keys, then each module's.
json material_json(const Material& m) {
  json j = {{"name", m.name},
            {"density", m.density / m.mass_scaling},  // the keys as given: read back, the same
            {"bulk_modulus", m.bulk_modulus},
            {"shear_modulus", m.shear_modulus},
            {"heat_capacity", m.heat_capacity * m.mass_scaling},
            {"viscosity", m.viscosity},
            {"mass_scaling", m.mass_scaling}};
  add_params(j, m.params);
  return j;
}

// The generic keys, then each module's.
json body_json(const BodySpec& b) {
  json j = {{"name", b.name},
            {"phase", b.phase},
            {"continuum", b.continuum},
            {"material", b.material},
            {"shape", shape_json(b.shape)},
            {"jitter", b.jitter},
            {"seed", b.seed},
            {"density", b.density_expr},
            {"velocity", b.velocity_expr},
            {"artificial_viscosity", {{"alpha", b.av_alpha}, {"beta", b.av_beta}}},
            {"artificial_stress", {{"epsilon", b.as_epsilon}, {"n", b.as_n}}},
            {"density_diffusion", {{"delta", b.delta}}},
            {"stress_divergence_corrected", b.corrected_divergence},
            {"formulation", b.formulation},
            {"total_lagrangian", b.total_lagrangian},
            {"temperature", b.temperature},
            {"body_force", b.body_force},
            {"damping", b.damping},
            {"fill_rest", b.fill_rest},
            {"fill_shells", b.fill_shells},
            {"angular_velocity", b.angular_velocity}};
  if (b.rotate)
    j["rotate"] = {
        {"degrees", b.rotate->degrees}, {"about", b.rotate->about}, {"axis", b.rotate->axis}};
  add_params(j, b.params);
  return j;
}

json boundary_json(const BoundarySpec& bc) {
  json j = {
      {"type", bc.type}, {"body", bc.body}, {"velocity", bc.velocity_expr}, {"name", bc.name}};
  if (bc.region) j["region"] = shape_json(*bc.region);
  if (bc.point) j["point"] = *bc.point;
  return j;
}

json surface_json(const SurfaceSpec& s) {
  return {{"name", s.name},
          {"kind", s.kind},
          {"points", s.points},
          {"size", {s.size[0], s.size[1]}},
          {"file", s.file},
          {"scale", s.scale},
          {"translate", s.translate},
          {"velocity", s.velocity_expr},
          {"friction", s.friction},
          {"damping", s.damping},
          {"friction_limit", s.friction_limit},
          {"heat_partition", s.heat_partition},
          {"heat_transfer", s.heat_transfer}, {"temperature", s.temperature},
          {"stiffness", s.stiffness},
          {"poisson_ratio", s.poisson_ratio}};
}

json probe_json(const ProbeSpec& p) {
  return {{"name", p.name},           {"type", p.type},
          {"field", p.field},         {"weight", p.weight_expr},
          {"body", p.body},           {"target", p.target},
          {"component", p.component}, {"point", p.point},
          {"axis", p.axis},           {"min_particles", p.min_particles},
          {"bins", p.bins},           {"range", p.range},
          {"columns", p.columns},     {"size", p.size}};
}

json time_json(const Scene& s) {
  return {{"end_time", s.end_time},
          {"reference_end_time", s.reference_end_time},
          {"cfl", s.cfl},
          {"force_factor", s.force_factor},
          {"max_dt", s.max_dt},
          {"dt_collapse", s.dt_collapse},
          {"newmark_gamma", s.newmark_gamma},
          {"multi_rate", s.multi_rate},
          {"max_substeps", s.max_substeps},
          {"advection_cfl", s.advection_cfl},
          {"acoustic_cfl", s.acoustic_cfl},
          {"frozen_kernel", s.frozen_kernel},
          {"max_mach", s.max_mach},
          {"min_distance", s.min_distance}};
}

}  // namespace

nlohmann::json scene_config(const Scene& s) {
  json j = {{"name", s.name},
            {"description", s.description},
            {"dimension", s.dimension},
            {"dp", s.dp},
            {"kernel", static_cast<int>(s.kernel)},
            {"h_factor", s.h_factor},
            {"skin", s.skin_factor},
            {"domain",
             {{"min", s.domain_min},
              {"max", s.domain_max},
              {"periodic", s.periodic},
              {"mirror_min", s.mirror_min},
              {"mirror_max", s.mirror_max}}},
            {"modules", s.modules},
            {"body_force", s.body_force},
            {"time", time_json(s)},
            {"output",
             {{"every", s.output_every},
              {"checkpoint_every", s.checkpoint_every},
              {"probe_every", s.probe_every},
              {"fields", s.output_fields}}},
            {"variables", s.variables},
            {"reorder_every", s.reorder_every},
            {"limits", {{"max_particles", s.max_particles}, {"max_memory", s.max_memory}}}};
  add_params(j, s.params);  // the modules' sections
  for (const auto& m : s.materials) j["materials"].push_back(material_json(m));
  for (const auto& b : s.bodies) j["bodies"].push_back(body_json(b));
  for (const auto& bc : s.boundaries) j["boundary_conditions"].push_back(boundary_json(bc));
  for (const auto& sf : s.surfaces) j["surfaces"].push_back(surface_json(sf));
  for (const auto& p : s.probes) j["probes"].push_back(probe_json(p));
  for (const auto& r : s.references)
    j["reference"].push_back({{"name", r.name},
                              {"probe", r.probe},
                              {"measure", r.measure},
                              {"value", r.value},
                              {"start", r.start},
                              {"needs", r.needs}});
  for (const auto& c : s.checks)
    j["checks"].push_back({{"name", c.name},
                           {"probe", c.probe},
                           {"measure", c.measure},
                           {"min", c.min},
                           {"max", c.max},
                           {"start", c.start}});
  return j;
}

}  // namespace monosph
