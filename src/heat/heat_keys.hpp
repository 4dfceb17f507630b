#pragma once
// The heat module's key on a body: `heat_conduction: {conductivity: k}` (README.md).
#include "scene/module_keys.hpp"

namespace monosph {

struct HeatBodyKeys : ModuleParams {
  static constexpr const char* module = "heat";
  double conductivity = 0;  // thermal conductivity k, W/(m K); 0: no conduction
  // Nothing for a body without conduction (the configuration of scenes without the key is as
  // before the module existed).
  nlohmann::json dump() const override;
};

ModuleKeys heat_keys();

}  // namespace monosph
