#include "fluid/fluid_keys.hpp"

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

namespace {

// delta-plus (Sun et al. 2017, speed U) or transport-velocity (Adami et al. 2013, pressure P)
// shifting, with or without the Sun et al. 2019 ALE terms.
void read_shifting(MapReader& b, const BodySpec& body, const std::string& p, FluidBodyKeys& k) {
  if (!b.has("shifting")) return void(b.optional("shifting"));
  if (body.phase != "fluid") scene_error(p + ".shifting", "applies to fluid bodies only");
  MapReader sh(b.node("shifting"), p + ".shifting");
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

}  // namespace

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
  return {FluidBodyKeys::module,
          [](MapReader& b, const BodySpec& body, const std::string& p, const Scene&) {
            auto k = std::make_shared<FluidBodyKeys>();
            read_shifting(b, body, p, *k);
            read_walls(b, body, p, *k);
            return std::shared_ptr<const BodyParams>(std::move(k));
          }};
}

}  // namespace monosph
