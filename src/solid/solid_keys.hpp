#pragma once
// The solid module's keys on a body: hourglass control, self-contact, the non-hourglass
// Laplacian, erosion (README.md, "bodies").
#include "scene/module_keys.hpp"

namespace monosph {

struct SolidBodyKeys : ModuleParams {
  static constexpr const char* module = "solid";
  double hg_xi = 0, hg_zeta = 0, hg_chi = 0;  // hourglass control (MMB Eq. 32-34)
  int hg_reference = 0;  // error vector against: 0 initial (MMB), 1 intermediate, 2 least squares
  bool hg_plastic_switch = false;  // Ganzenmueller: E -> yield stress in Eq. 32 when plastic
  // Hertz spheres of diameter self_contact dp between the body's own particles (0: off): a
  // floor under the pair distance, where the kernel gradient vanishes.
  double self_contact = 0;
  double laplacian_zeta = 0;  // Zhang et al. 2024 Eq. 19-20 (formulation: non_hourglass)
  int erosion = 0;            // remove particles with D >= 1: 0 never, 1 all, 2 surface only
  nlohmann::json dump() const override;
};

ModuleKeys solid_keys();

}  // namespace monosph
