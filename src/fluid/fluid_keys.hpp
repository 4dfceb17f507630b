#pragma once
// The fluid module's keys on a body: particle shifting and the viscous form of fluid bodies;
// slip and wall pressure of the wall-like bodies the fluid meets (README.md, "bodies").
#include <string>

#include "scene/module_keys.hpp"

namespace monosph {

struct FluidBodyKeys : ModuleParams {
  static constexpr const char* module = "fluid";
  // delta-plus particle shifting (Sun et al. 2017): reference speed U (0: off), the
  // anti-clustering term R (W_ij / W(dp))^n.
  double shift_speed = 0, shift_R = 0.2, shift_n = 4;
  // `shifting: {form: transport_velocity, pressure: P}`: Adami, Hu & Adams 2013 shift velocity
  // from a constant background pressure P (> 0; 0: the delta-plus form above).
  double shift_pb = 0;
  bool shift_consistent = false;  // the ALE terms of Sun et al. 2019 in continuity and momentum
  // morris (Morris et al. 1997), central (Sun et al. 2017, conserves angular momentum), auto
  // (central when the scene has rigid clusters, else morris)
  std::string viscous_form = "auto";
  bool no_slip = true;                      // a wall-like body seen by the fluid
  bool non_negative_wall_pressure = false;  // Adami p_w clipped at 0 (no suction)
  nlohmann::json dump() const override;
};

ModuleKeys fluid_keys();

}  // namespace monosph
