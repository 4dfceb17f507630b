#include "scene/scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/input_file.hpp"
#include "scene/expression.hpp"
#include "scene/scene_parts.hpp"
#include "scene/scene_probes.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_variables.hpp"

namespace monosph {

int Scene::material_index(const std::string& n) const {
  for (std::size_t k = 0; k < materials.size(); ++k)
    if (materials[k].name == n) return static_cast<int>(k);
  return -1;
}

namespace {

// Physics modules for scenes (switched on by the bodies and surfaces that need them).
const std::vector<std::string> kModules = {"solid",   "rigid",       "fluid",        "clusters",
                                           "contact", "lubrication", "solid_contact"};

void read_kernel(MapReader& r, Scene& s) {
  if (!r.has("kernel")) return void(r.optional("kernel"));
  auto kn = r.node("kernel");
  if (kn.IsScalar()) {
    s.kernel = kernel_from_name(as_text(kn, "kernel"));
    return;
  }
  MapReader k(kn, "kernel", r.constants());
  s.kernel = kernel_from_name(
      k.choice("type", {"cubic_spline", "wendland_c2", "quintic_spline"}, "cubic_spline"));
  s.h_factor = k.positive("h_factor", 1.3);
  if (s.h_factor < 1 || s.h_factor > 3)  // below: too few neighbours; above: every pair
    scene_error("kernel.h_factor",
                fmt::format("must lie in [1, 3] (h / dp), got {:g}", s.h_factor));
  k.finish();
}

void read_domain(MapReader& r, Scene& s) {
  const int dim = s.dimension;
  MapReader d(r.node("domain"), "domain", r.constants());
  s.domain_min = d.vector("min", dim);
  s.domain_max = d.vector("max", dim);
  for (int a = 0; a < dim; ++a)
    if (!(s.domain_max[a] > s.domain_min[a]))
      scene_error("domain.max", "must be greater than domain.min in every axis");
  s.periodic.assign(dim, false);
  if (d.has("periodic")) {
    for (const auto& ax : d.strings("periodic")) {
      int a = ax == "x" ? 0 : ax == "y" ? 1 : ax == "z" ? 2 : -1;
      if (a < 0 || a >= dim)
        scene_error("domain.periodic", "'" + ax + "' is not an axis of a " + std::to_string(dim) +
                                           "D scene (allowed: x, y" + (dim == 3 ? ", z)" : ")"));
      s.periodic[a] = true;
    }
  } else {
    d.optional("periodic");
  }
  // Symmetry planes at domain faces (mirror ghost particles, src/core/mirror.hpp).
  s.mirror_min.assign(dim, false);
  s.mirror_max.assign(dim, false);
  if (d.has("mirror")) {
    for (const auto& f : d.strings("mirror")) {
      const int a = f.size() == 5 && f[0] >= 'x' && f[0] <= 'z' ? f[0] - 'x' : -1;
      const std::string side = f.size() == 5 ? f.substr(1) : "";
      if (a < 0 || a >= dim || (side != "_min" && side != "_max"))
        scene_error("domain.mirror", "'" + f + "' is not a face of the " + std::to_string(dim) +
                                         "D domain (allowed: x_min, x_max, y_min, y_max" +
                                         (dim == 3 ? ", z_min, z_max)" : ")"));
      if (s.periodic[a]) scene_error("domain.mirror", "'" + f + "' lies on a periodic axis");
      (side == "_min" ? s.mirror_min : s.mirror_max)[a] = true;
    }
  } else {
    d.optional("mirror");
  }
  d.finish();
}

void read_neighbours(MapReader& r, Scene& s) {
  if (!r.has("neighbours")) return void(r.optional("neighbours"));
  MapReader nb(r.node("neighbours"), "neighbours", r.constants());
  s.skin_factor = nb.positive("skin", 0.3);
  if (s.skin_factor > 2)
    scene_error("neighbours.skin",
                fmt::format("must lie in (0, 2] (a fraction of h), got {:g}", s.skin_factor));
  s.reorder_every = nb.integer("reorder_every", 1);
  if (s.reorder_every < 0) scene_error("neighbours.reorder_every", "must be 0 (never) or more");
  nb.finish();
}

void read_materials(MapReader& r, Scene& s) {
  auto mats = r.node("materials");
  if (!mats.IsMap() || mats.size() == 0)
    scene_error("materials", "expected a map of named materials");
  for (auto it = mats.begin(); it != mats.end(); ++it) {
    std::string name = it->first.as<std::string>();
    s.materials.push_back(read_material(name, it->second, "materials." + name, r.constants()));
  }
}

void read_modules(MapReader& r, Scene& s) {
  s.modules.clear();
  if (!r.has("modules")) return void(r.optional("modules"));
  for (const auto& m : r.strings("modules")) {
    if (std::find(kModules.begin(), kModules.end(), m) == kModules.end())
      scene_error(
          "modules",
          "unknown module '" + m +
              "' (available: solid, rigid, fluid, clusters, contact, lubrication, solid_contact; "
              "they are "
              "switched on by the bodies and surfaces that need them)");
    s.modules.push_back(m);
  }
}

void read_probe_section(MapReader& r, Scene& s) {
  if (!r.has("probes")) return void(r.optional("probes"));
  MapReader pr(r.node("probes"), "probes", r.constants());
  read_probes(pr, s);  // scene_probes.cpp
  pr.finish();
}

}  // namespace

namespace {
Scene read_scene(const std::string& text, const std::vector<std::string>& overrides,
                 const std::string& origin) {
  YAML::Node root = parse_scene_yaml(text, origin);
  if (!root.IsMap()) throw InputError(origin + ": a scene must be a YAML map of keys");
  // The written end time, which the references are posed at (checked below as end_time).
  double written_end = -1;
  if (const YAML::Node e = static_cast<const YAML::Node&>(root)["end_time"]; e && e.IsScalar()) {
    try {
      written_end = e.as<double>();
    } catch (const YAML::Exception&) {  // malformed: reported below, unless --set replaces it
    }
  }
  check_yaml_tree(root, origin);  // keys plain and unique, text valid UTF-8
  for (const auto& o : overrides) {
    check_variable_override(root, o);  // scene_variables.cpp: a typo in a variable name fails
    apply_override(root, o);
  }
  if (!overrides.empty()) check_yaml_tree(root, origin);
  Scene s;
  {
    YAML::Emitter out;
    out << root;
    s.yaml = out.c_str();
  }
  MapReader r(root, "", nullptr);  // plain numbers until the variables are read
  s.name = r.text("name", "scene");
  check_name(s.name);
  s.description = r.text("description", "");
  s.dimension = r.integer("dimension", 2);
  if (s.dimension != 2 && s.dimension != 3)
    scene_error("dimension", "must be 2 or 3, got " + std::to_string(s.dimension));
  const int dim = s.dimension;
  s.variables = read_variables(r);  // before every expression that may use them
  r.set_constants(&s.variables);    // every number key below may be an expression of them
  s.dp = r.positive("dp");

  read_kernel(r, s);
  read_domain(r, s);
  read_neighbours(r, s);
  read_materials(r, s);
  read_modules(r, s);
  read_bodies(r, s);
  read_boundaries(r, s);
  read_surfaces(r, s, root, origin);
  for (const auto& m : registered_module_keys())  // the modules' sections (contact, ...)
    if (m.read_section)
      if (auto params = m.read_section(r, s)) s.params[m.module] = std::move(params);

  s.body_force = r.has("body_force") ? r.vector("body_force", dim)
                                     : (r.optional("body_force"), Point(dim, 0.0));
  s.end_time = r.positive("end_time");
  s.reference_end_time = written_end > 0 ? written_end : s.end_time;
  read_time_step(r, s);
  read_guards(r, s);
  read_output(r, s);
  read_probe_section(r, s);
  read_references(r, s);
  read_checks(r, s);
  read_limits(r, s);
  r.finish();
  check_scene_expressions(s);
  check_size(s);
  return s;
}
}  // namespace

Scene load_scene_text(const std::string& text, const std::vector<std::string>& overrides,
                      const std::string& origin) {
  try {
    return read_scene(text, overrides, origin);
  } catch (const YAML::Exception& e) {  // a YAML case no check above foresaw: still bad input
    throw InputError(origin + ": YAML error at line " + std::to_string(e.mark.line + 1) + ": " +
                     e.msg);
  }
}

Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_input_file(path, path + ": cannot read scene file", kMaxSceneBytes);
  return load_scene_text(text, overrides, path);
}

}  // namespace monosph
