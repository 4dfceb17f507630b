// The solid module's material keys: `plasticity`, `damage`, `taylor_quinney`, `elasticity`.
#include "solid/solid_material.hpp"

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

std::optional<SolidMaterial> solid_preset(const std::string& name) {
  // MMB 2020 Table 1 (Al 6061-T6 after [38]; PMMA). Temperatures in K.
  SolidMaterial m;
  if (name == "Al6061-T6") {
    m.plasticity = {true, 164e6, 211e6, 0.465, 0.002, 1.0, 1.419, 292, 925};
    m.damage = {true, -0.77, 1.45, -0.47, 0.0, 1.6};
    return m;
  }
  if (name == "PMMA") {
    m.plasticity = {true, 212e6, 580e6, 3.5, 0.081, 0.001, 0.749, 213, 398};
    m.damage = {true, -1.751, 2.32, -0.773, -0.0491, 0.38};
    return m;
  }
  return std::nullopt;
}

nlohmann::json SolidMaterial::dump() const {
  const auto& p = plasticity;
  const auto& d = damage;
  return {{"plasticity",
           {{"on", p.on},
            {"A", p.A},
            {"B", p.B},
            {"n", p.n},
            {"C", p.C},
            {"rate0", p.rate0},
            {"m", p.m},
            {"T_ref", p.T_ref},
            {"T_melt", p.T_melt}}},
          {"damage",
           {{"on", d.on},
            {"d1", d.d1},
            {"d2", d.d2},
            {"d3", d.d3},
            {"d4", d.d4},
            {"d5", d.d5},
            {"min_failure_strain", d.min_failure_strain},
            {"nonlocal_length", d.nonlocal_length}}},
          {"taylor_quinney", taylor_quinney},
          {"neo_hookean", neo_hookean}};
}

namespace {

// True for `key: none` (the model off); any other scalar is an error naming the map expected.
bool is_none(MapReader& r, const char* key, const char* map) {
  if (!r.has(key) || !r.node(key).IsScalar()) return false;
  if (r.node(key).Scalar() != "none")
    scene_error(r.at(key), std::string("expected a map ") + map + " or 'none'");
  return true;
}

// `plasticity: none` (elastic) or {A, B, n, ...}: MMB Eq. 23 (Johnson & Cook 1983); perfect
// plasticity is B = 0.
void read_plasticity(MapReader& r, JohnsonCook& jc) {
  if (is_none(r, "plasticity", "{A, B, n, ...}")) return void(jc.on = false);
  if (!r.has("plasticity")) return void(r.optional("plasticity"));
  MapReader q(r.node("plasticity"), r.at("plasticity"), r.constants());
  q.choice("type", {"johnson_cook"}, "johnson_cook");
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
}

// `damage: none` (turns a preset's off) or {D1..D5}: MMB Eq. 25-26.
void read_damage(MapReader& r, JohnsonCookDamage& d) {
  if (is_none(r, "damage", "{D1..D5}")) return void(d.on = false);
  if (!r.has("damage")) return void(r.optional("damage"));
  MapReader q(r.node("damage"), r.at("damage"), r.constants());
  q.choice("type", {"johnson_cook"}, "johnson_cook");
  const bool preset = d.on;  // D1-D3 have no neutral value: required unless a preset gave them
  d.on = true;
  d.d1 = preset ? q.number("D1", d.d1) : q.number("D1");
  d.d2 = preset ? q.number("D2", d.d2) : q.number("D2");
  d.d3 = preset ? q.number("D3", d.d3) : q.number("D3");
  d.d4 = q.number("D4", d.d4);
  d.d5 = q.number("D5", d.d5);
  d.min_failure_strain = q.positive("min_failure_strain", d.min_failure_strain);
  // Opt-in regularisation with a physical length (docs/theory.md, "Non-local damage").
  d.nonlocal_length = q.non_negative("nonlocal_length", d.nonlocal_length);  // 0: local
  q.finish();
}

}  // namespace

std::shared_ptr<const ModuleParams> read_solid_material(MapReader& r, Material& m,
                                                        const std::string& preset) {
  auto s = std::make_shared<SolidMaterial>(solid_preset(preset).value_or(SolidMaterial{}));
  s->taylor_quinney = r.non_negative("taylor_quinney", s->taylor_quinney);
  if (s->taylor_quinney > 1) scene_error(r.at("taylor_quinney"), "must lie in [0, 1]");
  // Stress from F for total-Lagrangian bodies (Ganzenmueller 2015 Eq. 44); default hypoelastic.
  s->neo_hookean =
      r.choice("elasticity", {"hypoelastic", "neo_hookean"}, "hypoelastic") == "neo_hookean";
  if (s->neo_hookean && m.shear_modulus <= 0)
    scene_error(r.at("elasticity"), "neo_hookean needs a positive shear_modulus");
  read_plasticity(r, s->plasticity);
  read_damage(r, s->damage);
  if (s->damage.on && !s->plasticity.on)
    scene_error(r.at("damage"),
                "Johnson-Cook damage grows with plastic strain: give `plasticity` too, or "
                "`damage: none`");
  if (s->plasticity.on && s->neo_hookean)
    scene_error(r.at("elasticity"), "neo_hookean is elastic: remove `plasticity` or the key");
  if (s->plasticity.on && m.shear_modulus <= 0)
    scene_error(r.at("plasticity"), "needs a positive shear_modulus");
  if (s->plasticity.on) m.reference_temperature = s->plasticity.T_ref;
  return s;
}

}  // namespace monosph
