#include "fluid/fluid_keys.hpp"

#include <nlohmann/json.hpp>

#include "fluid/fluid_material.hpp"
#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

namespace {

// delta-plus (Sun et al. 2017, speed U) or transport-velocity (Adami et al. 2013, pressure P)
// shifting, with or without the Sun et al. 2019 ALE terms.
void read_shifting(MapReader& b, const BodySpec& body, const std::string& p, FluidBodyKeys& k) {
  if (!b.has("shifting")) return void(b.optional("shifting"));
  if (body.phase != "fluid") scene_error(p + ".shifting", "applies to fluid bodies only");
  MapReader sh(b.node("shifting"), p + ".shifting", b.constants());
  if (sh.choice("form", {"delta_plus", "transport_velocity"}, "delta_plus") == "delta_plus") {
    k.shift_speed = sh.positive("speed");
    k.shift_R = sh.non_negative("R", 0.2);
    k.shift_n = sh.positive("n", 4.0);
  } else {
    k.shift_pb = sh.positive("pressure");
  }
  k.shift_consistent = sh.boolean("consistent", false);
  sh.finish();
}

// viscous_form (fluids); slip and wall_pressure (wall-like bodies).
void read_walls(MapReader& b, const BodySpec& body, const std::string& p, FluidBodyKeys& k) {
  if (b.has("viscous_form")) {
    if (body.phase != "fluid") scene_error(p + ".viscous_form", "applies to fluid bodies only");
    k.viscous_form = b.choice("viscous_form", {"auto", "morris", "central"});
  } else {
    b.optional("viscous_form");
  }
  if (b.has("slip")) {
    if (body.phase == "fluid") scene_error(p + ".slip", "applies to wall-like (non-fluid) bodies");
    k.no_slip = b.choice("slip", {"no_slip", "free_slip"}) == "no_slip";
  } else {
    b.optional("slip");
  }
  if (b.has("wall_pressure")) {
    if (body.phase == "fluid")
      scene_error(p + ".wall_pressure", "applies to wall-like (non-fluid) bodies");
    k.non_negative_wall_pressure =
        b.choice("wall_pressure", {"extrapolated", "non_negative"}) == "non_negative";
  } else {
    b.optional("wall_pressure");
  }
}

// The material keys of the fluid EOS: cavitation_pressure, background_pressure.
std::shared_ptr<const ModuleParams> read_fluid_material(MapReader& r) {
  auto f = std::make_shared<FluidMaterial>();
  if (r.has("cavitation_pressure")) {
    f->cavitation_pressure = r.number("cavitation_pressure");
    if (!(f->cavitation_pressure <= 0))
      scene_error(r.at("cavitation_pressure"),
                  "must be <= 0 (a gauge pressure: the tension the liquid bears)");
  } else {
    r.optional("cavitation_pressure");
  }
  // Fluids without a free surface (Morris et al. 1997).
  f->background_pressure = r.non_negative("background_pressure", 0.0);
  return f;
}

}  // namespace

nlohmann::json FluidMaterial::dump() const {
  return {{"cavitation_pressure", cavitation_pressure},
          {"background_pressure", background_pressure}};
}

nlohmann::json FluidBodyKeys::dump() const {
  return {{"shifting",
           {{"speed", shift_speed},
            {"R", shift_R},
            {"n", shift_n},
            {"pressure", shift_pb},
            {"consistent", shift_consistent}}},
          {"no_slip", no_slip},
          {"non_negative_wall_pressure", non_negative_wall_pressure},
          {"viscous_form", viscous_form}};
}

ModuleKeys fluid_keys() {
  return {.module = FluidBodyKeys::module,
          .read_body = [](MapReader& b, const BodySpec& body, const std::string& p,
                          const Scene& s) -> std::shared_ptr<const ModuleParams> {
            auto k = std::make_shared<FluidBodyKeys>();
            read_shifting(b, body, p, *k);
            read_walls(b, body, p, *k);
            const Material& m = s.materials[body.material];
            if ((body.phase == "solid" || body.phase == "rigid") &&
                module_params<FluidMaterial>(m.params).background_pressure > 0)
              scene_error(
                  "materials." + m.name + ".background_pressure",
                  "applies to fluids only (body '" + body.name + "' is " + body.phase + ")");
            return k;
          },
          .read_material = [](MapReader& r, Material&,
                              const std::string&) { return read_fluid_material(r); }};
}

}  // namespace monosph
