#pragma once
// The cluster module's key on a body: `clusters: one/per_part` (README.md, "bodies").
#include "scene/module_keys.hpp"

namespace monosph {

struct ClusterBodyKeys : ModuleParams {
  static constexpr const char* module = "clusters";
  bool per_part = false;  // one rigid cluster per part of a union shape (else one per body)
  nlohmann::json dump() const override;
};

ModuleKeys cluster_keys();

}  // namespace monosph
