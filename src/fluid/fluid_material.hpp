#pragma once
// The fluid module's keys of a material: the cavitation and background pressure of its equation
// of state (README.md, "materials").
#include <algorithm>
#include <limits>

#include "scene/module_keys.hpp"
#include "scene/scene.hpp"

namespace monosph {

struct FluidMaterial : ModuleParams {
  static constexpr const char* module = "fluid";
  // The pressure below which the liquid cavitates (gauge, Pa; Brennen 1995): the EOS pressure is
  // held at it, so that the fluid carries no larger tension.
  double cavitation_pressure = -std::numeric_limits<double>::infinity();
  // p_b added to the EOS pressure, p = K (rho/rho0 - 1) + p_b (Morris, Fox & Zhu 1997, Sect.
  // 2.2): keeps a confined flow's pressure positive against the tensile instability. Only for
  // flows without a free surface (the fluid module stops a run that has one).
  double background_pressure = 0;
  // The fluid EOS: MMB Eq. 13 held at the cavitation pressure, plus the background pressure.
  double pressure(const Material& m, double rho) const {
    return std::max(m.pressure(rho), cavitation_pressure) + background_pressure;
  }
  nlohmann::json dump() const override;
};

}  // namespace monosph
