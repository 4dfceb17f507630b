#pragma once
// The coupling modules' top-level sections: `contact`, `lubrication`, `solid_contact`
// (README.md).
#include <string>

#include "scene/module_keys.hpp"

namespace monosph {

// Contact between rigid-cluster particles and other bodies' particles (substitute for the law of
// Cleary et al. 2012; ../shared/reference/equations.md Sect. 6): spheres of diameter
// `distance` dp, Hertz (default) or Lennard-Jones-type (Monaghan 1994).
struct ContactSpec : ModuleParams {
  static constexpr const char* module = "contact";
  std::string law = "hertz";  // hertz | lennard_jones
  double distance = 1.0;      // contact diameter, fraction of dp
  double damping = 0;         // hertz: normal dashpot, ratio of critical
  double friction = 0;        // Coulomb coefficient of the pair's sliding
  double strength = 0;        // lennard_jones: D (m^2/s^2)
  double p1 = 12, p2 = 4;     // lennard_jones exponents
  nlohmann::json dump() const override;
};

// Contact between solid bodies of different continua (section `solid_contact`): Hertz spheres
// of diameter distance * dp, repulsive only, with Coulomb friction.
struct SolidContactSpec : ModuleParams {
  static constexpr const char* module = "solid_contact";
  bool on = false;
  double distance = 1.0;  // contact diameter d_c, fraction of dp
  double damping = 0;     // normal dashpot, ratio of critical
  double friction = 0;    // Coulomb coefficient of the pair's sliding
  nlohmann::json dump() const override;
};

// Sub-grid lubrication between rigid clusters and surfaces (section `lubrication`).
struct LubricationSpec : ModuleParams {
  static constexpr const char* module = "lubrication";
  bool on = false;
  double cutoff = 1.5;    // resolved gap h_c, in dp: the film force is added below it
  double min_gap = 0.05;  // smallest gap (surface roughness), in dp
  double viscosity = 0;   // dynamic viscosity of the film (default: the fluid's)
  nlohmann::json dump() const override;
};

ModuleKeys contact_keys();
ModuleKeys lubrication_keys();
ModuleKeys solid_contact_keys();

}  // namespace monosph
