#include "solid/solid_keys.hpp"

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"
#include "solid/solid_material.hpp"

namespace monosph {

namespace {

// Hourglass control (MMB Eq. 32-34).
void read_hourglass(MapReader& b, const BodySpec& body, const std::string& p, SolidBodyKeys& k) {
  if (!b.has("hourglass")) return void(b.optional("hourglass"));
  if (body.phase != "solid")
    scene_error(p + ".hourglass", "hourglass control applies to solid bodies only");
  MapReader hg(b.node("hourglass"), p + ".hourglass", b.constants());
  // Ganzenmueller's alpha (Eq. 31-32) is MMB's xi (Eq. 32): one coefficient, two names.
  if (hg.has("alpha") && hg.has("xi")) scene_error(hg.path(), "give either xi or alpha");
  if (hg.has("alpha")) {
    k.hg_xi = hg.non_negative("alpha", 0.0);
    hg.optional("xi");
  } else {
    k.hg_xi = hg.non_negative("xi", 0.0);
    hg.optional("alpha");
  }
  k.hg_zeta = hg.non_negative("zeta", 0.0);
  k.hg_chi = hg.non_negative("chi", 0.0);
  // Only the stiffness form (G15 Eq. 32) for total-Lagrangian bodies: zeta, chi must be 0.
  if (body.total_lagrangian)
    for (const char* key : {"zeta", "chi"})
      if (hg.has(key) && hg.number(key) != 0)
        scene_error(hg.at(key), "must be 0 with formulation: total_lagrangian");
  if (k.hg_chi > 1) scene_error(p + ".hourglass.chi", "must be between 0 and 1");
  const std::string ref =
      hg.choice("reference", {"initial", "intermediate", "least_squares"}, "initial");
  k.hg_reference = ref == "initial" ? 0 : ref == "intermediate" ? 1 : 2;
  // Ganzenmueller 2015 (Sect. 3): E of Eq. 32 replaced by the yield stress once plastic.
  k.hg_plastic_switch = hg.boolean("plastic_switch", false);
  hg.finish();
}

void read_self_contact(MapReader& b, const BodySpec& body, const std::string& p, SolidBodyKeys& k) {
  if (!b.has("self_contact")) return void(b.optional("self_contact"));
  if (body.phase != "solid") scene_error(p + ".self_contact", "applies to solid bodies only");
  MapReader sc(b.node("self_contact"), p + ".self_contact", b.constants());
  k.self_contact = sc.positive("distance");
  if (k.self_contact >= 1)
    scene_error(p + ".self_contact.distance", "must be below 1 (a fraction of dp)");
  sc.finish();
}

// The non-hourglass Laplacian's coefficient and erosion of failed particles.
void read_laplacian_and_erosion(MapReader& b, const BodySpec& body, const std::string& p,
                                const Scene& s, SolidBodyKeys& k) {
  if (b.has("laplacian_zeta")) {
    if (body.formulation != 2)
      scene_error(p + ".laplacian_zeta", "applies with formulation: non_hourglass only");
    k.laplacian_zeta = b.positive("laplacian_zeta");
  } else {
    b.optional("laplacian_zeta");
    k.laplacian_zeta = 0.7 * s.dimension + 2.1;  // Zhang et al. 2024, Sect. 6 (h = 1.3 dp)
  }
  if (!b.has("erosion")) return void(b.optional("erosion"));
  if (body.total_lagrangian)
    scene_error(p + ".erosion", "not available with formulation: total_lagrangian");
  if (body.phase != "solid") scene_error(p + ".erosion", "applies to solid bodies only");
  const std::string e = b.choice("erosion", {"none", "failed", "failed_surface"});
  k.erosion = e == "none" ? 0 : e == "failed" ? 1 : 2;
}

// What a body's formulation asks of its material.
void check_material(const BodySpec& body, const std::string& p, const Scene& s) {
  const Material& m = s.materials[body.material];
  const SolidMaterial& sm = module_params<SolidMaterial>(m.params);
  if (body.formulation == 2 && sm.plasticity.on)
    scene_error(p + ".formulation",
                "non_hourglass (Zhang et al. 2024) is for elastic materials; material '" + m.name +
                    "' has plasticity");
  if (body.phase == "solid" && !body.total_lagrangian && sm.neo_hookean)
    scene_error(p + ".material", "elasticity: neo_hookean needs formulation: total_lagrangian");
}

}  // namespace

nlohmann::json SolidBodyKeys::dump() const {
  return {{"hourglass",
           {{"xi", hg_xi},
            {"zeta", hg_zeta},
            {"chi", hg_chi},
            {"reference", hg_reference},
            {"plastic_switch", hg_plastic_switch}}},
          {"self_contact", self_contact},
          {"laplacian_zeta", laplacian_zeta},
          {"erosion", erosion}};
}

ModuleKeys solid_keys() {
  return {.module = SolidBodyKeys::module,
          .read_body = [](MapReader& b, const BodySpec& body, const std::string& p,
                          const Scene& s) -> std::shared_ptr<const ModuleParams> {
            check_material(body, p, s);
            auto k = std::make_shared<SolidBodyKeys>();
            read_hourglass(b, body, p, *k);
            read_self_contact(b, body, p, *k);
            read_laplacian_and_erosion(b, body, p, s, *k);
            return k;
          },
          .read_material = read_solid_material};
}

}  // namespace monosph
