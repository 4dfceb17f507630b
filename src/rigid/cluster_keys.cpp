#include "rigid/cluster_keys.hpp"

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

nlohmann::json ClusterBodyKeys::dump() const {
  return {{"cluster_per_part", per_part}};
}

ModuleKeys cluster_keys() {
  return {ClusterBodyKeys::module,
          [](MapReader& b, const BodySpec& body, const std::string& p, const Scene&) {
            auto k = std::make_shared<ClusterBodyKeys>();
            if (!b.has("clusters")) {
              b.optional("clusters");
            } else {
              if (body.phase != "rigid")
                scene_error(p + ".clusters", "applies to rigid bodies only");
              k->per_part = b.choice("clusters", {"one", "per_part"}) == "per_part";
              if (k->per_part && body.shape.kind != Shape::Kind::Union)
                scene_error(p + ".clusters", "per_part needs a shape that is a union of parts");
            }
            return std::shared_ptr<const ModuleParams>(std::move(k));
          }};
}

}  // namespace monosph
