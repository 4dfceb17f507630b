#pragma once
// The solid module's keys of a material: Johnson-Cook plasticity and damage, the Taylor-Quinney
// coefficient, the elasticity of total-Lagrangian bodies (README.md, "materials").
#include <optional>
#include <string>

#include "scene/module_keys.hpp"

namespace monosph {

// Johnson-Cook yield stress (MMB Eq. 23): [A + B eps^n][1 + C ln(rate/rate0)][1 - T*^m].
struct JohnsonCook {
  bool on = false;
  double A = 0, B = 0, n = 1, C = 0, rate0 = 1, m = 1, T_ref = 293.15, T_melt = 0;
};

// Johnson-Cook failure strain (MMB Eq. 26), damage rate = plastic strain rate / eps_f (Eq. 25).
struct JohnsonCookDamage {
  bool on = false;
  double d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;
  double min_failure_strain = 1e-6;  // floor of eps_f (as LS-DYNA's EFMIN): D1 < 0 fits give
                                     // eps_f <= 0 at high triaxiality
  // Non-local damage (solid/nonlocal_damage.hpp): the length l [m] over which damage increments
  // are averaged; 0 (default) = local (MMB).
  double nonlocal_length = 0;
};

struct SolidMaterial : ModuleParams {
  static constexpr const char* module = "solid";
  JohnsonCook plasticity;       // J2 plasticity (MMB Eq. 22-23) when `on`
  JohnsonCookDamage damage;     // Johnson-Cook damage (MMB Eq. 25-26) when `on`
  double taylor_quinney = 0.9;  // eta of MMB Eq. 24
  // `elasticity: neo_hookean`: compressible neo-Hookean PK2 stress from F (Ganzenmueller 2015
  // Eq. 44), total-Lagrangian bodies only; otherwise hypoelastic (Jaumann S + EOS pressure).
  bool neo_hookean = false;
  nlohmann::json dump() const override;
};

// The plasticity and damage of a shipped material (MMB 2020 Table 1), if it has them.
std::optional<SolidMaterial> solid_preset(const std::string& name);

// The solid module's keys of one material (ModuleKeys::read_material).
std::shared_ptr<const ModuleParams> read_solid_material(MapReader& r, Material& m,
                                                        const std::string& preset);

}  // namespace monosph
