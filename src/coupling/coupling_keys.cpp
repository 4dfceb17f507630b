#include "coupling/coupling_keys.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

namespace {

// The top-level section `key` as a map, or none (the key then declared known and absent).
std::optional<MapReader> section(MapReader& r, const char* key) {
  if (!r.has(key)) {
    r.optional(key);
    return std::nullopt;
  }
  return MapReader(r.node(key), key, r.constants());
}

void switch_on(Scene& s, const std::string& module) {
  if (std::find(s.modules.begin(), s.modules.end(), module) == s.modules.end())
    s.modules.push_back(module);
}

// Rigid-cluster contact (equations.md Sect. 6).
std::shared_ptr<const ModuleParams> read_contact(MapReader& r, Scene&) {
  auto k = std::make_shared<ContactSpec>();
  auto sec = section(r, "contact");
  if (!sec) return k;
  MapReader& c = *sec;
  k->law = c.choice("law", {"hertz", "lennard_jones"}, "hertz");
  k->distance = c.positive("distance", 1.0);
  k->damping = c.non_negative("damping", 0.0);
  k->friction = c.non_negative("friction", 0.0);
  if (k->law == "lennard_jones") {
    k->strength = c.positive("strength");
    k->p1 = c.positive("p1", 12.0);
    k->p2 = c.positive("p2", 4.0);
    if (!(k->p1 > k->p2)) scene_error("contact.p1", "must exceed contact.p2");
  } else {
    for (const char* key : {"strength", "p1", "p2"})
      if (c.has(key))
        scene_error(std::string("contact.") + key, "applies to law lennard_jones only");
  }
  c.finish();
  return k;
}

// Needs a rigid body; the film viscosity defaults to the first fluid's.
std::shared_ptr<const ModuleParams> read_lubrication(MapReader& r, Scene& s) {
  auto l = std::make_shared<LubricationSpec>();
  auto sec = section(r, "lubrication");
  if (!sec) return l;
  MapReader& c = *sec;
  l->on = true;
  l->cutoff = c.positive("cutoff", 1.5);
  l->min_gap = c.positive("min_gap", 0.05);
  if (!(l->min_gap < l->cutoff))
    scene_error("lubrication.min_gap", "must be below lubrication.cutoff");
  const BodySpec* fluid = nullptr;
  bool rigid = false;
  for (const auto& b : s.bodies) {
    if (b.phase == "fluid" && !fluid) fluid = &b;
    rigid = rigid || b.phase == "rigid";
  }
  if (!rigid)
    scene_error("lubrication",
                "needs a rigid body (the film lies between a cluster and a surface)");
  if (c.has("viscosity")) {
    l->viscosity = c.positive("viscosity");
  } else {
    if (!fluid) scene_error("lubrication.viscosity", "is required without a fluid body");
    l->viscosity = s.materials[fluid->material].viscosity;
    if (!(l->viscosity > 0))
      scene_error("lubrication.viscosity", "the fluid's material has no viscosity: give one");
  }
  c.finish();
  switch_on(s, LubricationSpec::module);
  return l;
}

// Needs two solid bodies that are not one continuum; the contact diameter lies within the kernel
// support (h >= dp, support >= 2h).
std::shared_ptr<const ModuleParams> read_solid_contact(MapReader& r, Scene& s) {
  auto sc = std::make_shared<SolidContactSpec>();
  auto sec = section(r, "solid_contact");
  if (!sec) return sc;
  MapReader& c = *sec;
  sc->on = true;
  sc->distance = c.positive("distance", 1.0);
  if (sc->distance > 2)
    scene_error("solid_contact.distance",
                "must lie in (0, 2] (the contact diameter in dp, within the kernel support)");
  sc->damping = c.non_negative("damping", 0.0);
  sc->friction = c.non_negative("friction", 0.0);
  c.finish();
  std::vector<std::string> continua;
  for (const auto& b : s.bodies)
    if (b.phase == "solid" &&
        std::find(continua.begin(), continua.end(), b.continuum) == continua.end())
      continua.push_back(b.continuum);
  if (continua.size() < 2)
    scene_error("solid_contact",
                "needs two solid bodies of different continua (bodies of one continuum meet "
                "through the SPH equations)");
  switch_on(s, SolidContactSpec::module);
  return sc;
}

}  // namespace

nlohmann::json ContactSpec::dump() const {
  return {{"contact",
           {{"law", law},
            {"distance", distance},
            {"damping", damping},
            {"friction", friction},
            {"strength", strength},
            {"p1", p1},
            {"p2", p2}}}};
}

nlohmann::json LubricationSpec::dump() const {
  return {{"lubrication",
           {{"on", on}, {"cutoff", cutoff}, {"min_gap", min_gap}, {"viscosity", viscosity}}}};
}

nlohmann::json SolidContactSpec::dump() const {
  return {{"solid_contact",
           {{"on", on}, {"distance", distance}, {"damping", damping}, {"friction", friction}}}};
}

ModuleKeys contact_keys() {
  return {.module = ContactSpec::module, .read_section = read_contact};
}
ModuleKeys lubrication_keys() {
  return {.module = LubricationSpec::module, .read_section = read_lubrication};
}
ModuleKeys solid_contact_keys() {
  return {.module = SolidContactSpec::module, .read_section = read_solid_contact};
}

}  // namespace monosph
