#include "heat/heat_keys.hpp"

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

nlohmann::json HeatBodyKeys::dump() const {
  if (!(conductivity > 0)) return nlohmann::json::object();
  return {{"heat_conduction", {{"conductivity", conductivity}}}};
}

ModuleKeys heat_keys() {
  return {HeatBodyKeys::module,
          [](MapReader& b, const BodySpec& body, const std::string& p, const Scene& s) {
            auto k = std::make_shared<HeatBodyKeys>();
            if (!b.has("heat_conduction")) {
              b.optional("heat_conduction");
              return std::shared_ptr<const ModuleParams>(std::move(k));
            }
            if (body.phase != "solid" && body.phase != "fluid")
              scene_error(p + ".heat_conduction", "applies to solid and fluid bodies");
            MapReader hc(b.node("heat_conduction"), p + ".heat_conduction", b.constants());
            k->conductivity = hc.positive("conductivity");
            hc.finish();
            const Material& m = s.materials[body.material];
            if (!(m.heat_capacity > 0))
              scene_error(p + ".heat_conduction",
                          "needs the heat_capacity of material '" + m.name + "' (J/(kg K), > 0)");
            return std::shared_ptr<const ModuleParams>(std::move(k));
          }};
}

}  // namespace monosph
