// The scene section `materials`: shipped presets (MMB Table 1) and one material's keys.
#include <cmath>

#include "scene/scene_parts.hpp"

namespace monosph {

double Material::sound_speed() const {
  return std::sqrt(bulk_modulus / density);
}
std::optional<Material> library_material(const std::string& name) {
  // MMB 2020 Table 1 (Al 6061-T6 after [38]; PMMA). Temperatures in K.
  Material m;
  m.name = name;
  if (name == "Al6061-T6") {
    m.density = 2800, m.bulk_modulus = 69e9, m.shear_modulus = 26.5e9, m.heat_capacity = 885;
    m.plasticity = {true, 164e6, 211e6, 0.465, 0.002, 1.0, 1.419, 292, 925};
    m.damage = {true, -0.77, 1.45, -0.47, 0.0, 1.6};
    return m;
  }
  if (name == "PMMA") {
    m.density = 1186, m.bulk_modulus = 5.85e9, m.shear_modulus = 2.2e9, m.heat_capacity = 1470;
    m.plasticity = {true, 212e6, 580e6, 3.5, 0.081, 0.001, 0.749, 213, 398};
    m.damage = {true, -1.751, 2.32, -0.773, -0.0491, 0.38};
    return m;
  }
  if (name == "iron") {  // pure iron (handbook): E = 211 GPa, nu = 0.29 -> K, mu; abrasive grains
    const double e = 211e9, nu = 0.29;
    m.density = 7870, m.bulk_modulus = e / (3 * (1 - 2 * nu)), m.shear_modulus = e / (2 * (1 + nu));
    return m;
  }
  return std::nullopt;
}

std::vector<std::string> library_material_names() {
  return {"Al6061-T6", "PMMA", "iron"};
}

double Material::wave_speed() const {
  return std::sqrt((bulk_modulus + 4.0 * shear_modulus / 3.0) / density);
}

Material read_material(const std::string& name, const YAML::Node& n, const std::string& path) {
  MapReader r(n, path);
  Material m;
  if (r.has("preset")) {
    const std::string preset = r.text("preset");
    auto lib = library_material(preset);
    if (!lib) {
      std::string names;
      for (const auto& k : library_material_names()) names += (names.empty() ? "" : ", ") + k;
      scene_error(r.at("preset"),
                  "no shipped material '" + preset + "' (available: " + names + ")");
    }
    m = *lib;
  }
  m.name = name;
  m.density = m.density > 0 ? r.positive("density", m.density) : r.positive("density");
  if (r.has("bulk_modulus") && r.has("sound_speed"))
    scene_error(path, "give either bulk_modulus or sound_speed, not both");
  if (r.has("sound_speed")) {
    double c = r.positive("sound_speed");
    m.bulk_modulus = m.density * c * c;
    r.optional("bulk_modulus");
  } else {
    m.bulk_modulus = m.bulk_modulus > 0 ? r.positive("bulk_modulus", m.bulk_modulus)
                                        : r.positive("bulk_modulus");
    r.optional("sound_speed");
  }
  m.shear_modulus = r.non_negative("shear_modulus", m.shear_modulus);
  m.heat_capacity = r.non_negative("heat_capacity", m.heat_capacity);
  m.taylor_quinney = r.non_negative("taylor_quinney", m.taylor_quinney);
  m.viscosity = r.non_negative("viscosity", m.viscosity);
  // Fluids: the pressure below which the liquid cavitates (gauge, Pa; Brennen 1995): the EOS
  // pressure is held at it, so that the fluid carries no larger tension.
  if (r.has("cavitation_pressure")) {
    m.cavitation_pressure = r.number("cavitation_pressure");
    if (!(m.cavitation_pressure <= 0))
      scene_error(r.at("cavitation_pressure"),
                  "must be <= 0 (a gauge pressure: the tension the liquid bears)");
  } else {
    r.optional("cavitation_pressure");
  }
  // Fluids without a free surface: a constant added to the EOS pressure (Morris et al. 1997).
  m.background_pressure = r.non_negative("background_pressure", 0.0);
  // Stress from F for total-Lagrangian bodies (Ganzenmueller 2015 Eq. 44); default hypoelastic.
  m.neo_hookean =
      r.choice("elasticity", {"hypoelastic", "neo_hookean"}, "hypoelastic") == "neo_hookean";
  if (m.neo_hookean && m.shear_modulus <= 0)
    scene_error(r.at("elasticity"), "neo_hookean needs a positive shear_modulus");
  if (m.taylor_quinney > 1) scene_error(r.at("taylor_quinney"), "must lie in [0, 1]");
  if (r.has("plasticity") && r.node("plasticity").IsScalar()) {  // `plasticity: none`: elastic
    if (r.node("plasticity").Scalar() != "none")
      scene_error(r.at("plasticity"), "expected a map {A, B, n, ...} or 'none'");
    m.plasticity.on = false;
  } else if (r.has("plasticity")) {
    // MMB Eq. 23 (Johnson & Cook 1983); perfect plasticity is B = 0.
    MapReader q(r.node("plasticity"), r.at("plasticity"));
    q.choice("type", {"johnson_cook"}, "johnson_cook");
    JohnsonCook& jc = m.plasticity;
    jc.on = true;
    jc.A = jc.A > 0 ? q.positive("A", jc.A) : q.positive("A");
    jc.B = q.non_negative("B", jc.B);
    jc.n = q.positive("n", jc.n);
    jc.C = q.non_negative("C", jc.C);
    jc.rate0 = q.positive("reference_strain_rate", jc.rate0);
    jc.m = q.positive("m", jc.m);
    jc.T_ref = q.positive("reference_temperature", jc.T_ref);
    jc.T_melt = q.non_negative("melting_temperature", jc.T_melt);
    if (jc.T_melt > 0 && jc.T_melt <= jc.T_ref)
      scene_error(q.at("melting_temperature"),
                  "must exceed reference_temperature (or be 0: no thermal softening)");
    q.finish();
  } else {
    r.optional("plasticity");
  }
  if (r.has("damage") && r.node("damage").IsScalar()) {  // `damage: none` turns a preset's off
    if (r.node("damage").Scalar() != "none")
      scene_error(r.at("damage"), "expected a map {D1..D5} or 'none'");
    m.damage.on = false;
  } else if (r.has("damage")) {
    MapReader q(r.node("damage"), r.at("damage"));
    q.choice("type", {"johnson_cook"}, "johnson_cook");
    JohnsonCookDamage& d = m.damage;
    const bool preset = d.on;  // D1-D3 have no neutral value: required unless a preset gave them
    d.on = true;
    d.d1 = preset ? q.number("D1", d.d1) : q.number("D1");
    d.d2 = preset ? q.number("D2", d.d2) : q.number("D2");
    d.d3 = preset ? q.number("D3", d.d3) : q.number("D3");
    d.d4 = q.number("D4", d.d4);
    d.d5 = q.number("D5", d.d5);
    d.min_failure_strain = q.positive("min_failure_strain", d.min_failure_strain);
    q.finish();
  } else {
    r.optional("damage");
  }
  if (m.damage.on && !m.plasticity.on)
    scene_error(r.at("damage"),
                "Johnson-Cook damage grows with plastic strain: give `plasticity` too, or "
                "`damage: none`");
  if (m.plasticity.on && m.neo_hookean)
    scene_error(r.at("elasticity"), "neo_hookean is elastic: remove `plasticity` or the key");
  if (m.plasticity.on && m.shear_modulus <= 0)
    scene_error(r.at("plasticity"), "needs a positive shear_modulus");
  r.finish();
  return m;
}

}  // namespace monosph
