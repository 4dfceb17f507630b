// The scene section `materials`: shipped presets (MMB Table 1) and one material's generic keys;
// the modules read theirs (plasticity, damage, the fluid EOS: scene/module_keys.hpp).
#include <cmath>

#include "scene/scene_parts.hpp"

namespace monosph {

double Material::sound_speed() const {
  return std::sqrt(bulk_modulus / density);
}
std::optional<Material> library_material(const std::string& name) {
  // MMB 2020 Table 1 (Al 6061-T6 after [38]; PMMA); their plasticity: solid_preset.
  Material m;
  m.name = name;
  if (name == "Al6061-T6") {
    m.density = 2800, m.bulk_modulus = 69e9, m.shear_modulus = 26.5e9, m.heat_capacity = 885;
    return m;
  }
  if (name == "PMMA") {
    m.density = 1186, m.bulk_modulus = 5.85e9, m.shear_modulus = 2.2e9, m.heat_capacity = 1470;
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

Material read_material(const std::string& name, const YAML::Node& n, const std::string& path,
                       const Constants* constants) {
  MapReader r(n, path, constants);
  Material m;
  std::string preset;
  if (r.has("preset")) {
    preset = r.text("preset");
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
  m.viscosity = r.non_negative("viscosity", m.viscosity);
  m.mass_scaling = r.positive("mass_scaling", 1.0);
  if (m.mass_scaling < 1) scene_error(r.at("mass_scaling"), "must be at least 1 (1: none)");
  m.density *= m.mass_scaling;  // after bulk_modulus: sound_speed is the material's own
  m.heat_capacity /= m.mass_scaling;
  for (const auto& k : registered_module_keys())
    if (k.read_material)
      if (auto params = k.read_material(r, m, preset)) m.params[k.module] = std::move(params);
  r.finish();
  return m;
}

}  // namespace monosph
