#pragma once
// The parsed configuration of a scene as JSON: every value a run uses, defaults included.
#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace monosph {

nlohmann::json scene_config(const Scene& s);

}  // namespace monosph
