#include "scene/scene_probes.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/expression.hpp"
#include "scene/scene_parts.hpp"

namespace monosph {

namespace {

const std::vector<std::string> kTypes = {"kinetic_energy",
                                         "elastic_energy",
                                         "disorder",
                                         "total_mass",
                                         "momentum",
                                         "abs_momentum",
                                         "max_speed",
                                         "min_distance",
                                         "integral",
                                         "mean",
                                         "value_at",
                                         "tracked",
                                         "reaction_force",
                                         "surface_force",
                                         "surface_contacts",
                                         "removed_mass",
                                         "field_max",
                                         "field_min",
                                         "extent",
                                         "surface_displacement",
                                         "fluid_force",
                                         "penetration",
                                         "grain_impacts",
                                         "contact_pairs",
                                         "total_energy",
                                         "failure_energy",
                                         "plastic_work",
                                         "pieces",
                                         "diameter",
                                         "rigid_centre",
                                         "rigid_velocity",
                                         "rigid_angular_velocity",
                                         "profile",
                                         "contact_energy",
                                         "lubrication_force",
                                         "lubrication_gap",
                                         "solid_contact_pairs",
                                         "solid_contact_force",
                                         "solid_contact_neighbours",
                                         "wall_pressure",
                                         "chip_ratio",
                                         "kinetic_share"};

bool is_one_of(const std::string& type, std::initializer_list<const char*> types) {
  return std::any_of(types.begin(), types.end(), [&](const char* t) { return type == t; });
}

bool is_rigid_type(const std::string& type) {
  return is_one_of(type, {"rigid_centre", "rigid_velocity", "rigid_angular_velocity"});
}

// Columns the probe writes to probes.csv: name, or name_x, name_y (, name_z); none for a profile.
int column_count(const std::string& type, int dim) {
  if (type == "profile") return 0;
  if (type == "rigid_angular_velocity") return dim == 3 ? 3 : 1;
  if (is_one_of(type,
                {"momentum", "reaction_force", "surface_force", "surface_displacement",
                 "rigid_centre", "rigid_velocity", "lubrication_force", "solid_contact_force"}))
    return dim;
  return 1;
}

// `field: name` or `field: name.x` (a component).
void read_field(MapReader& q, const std::string& p, ProbeSpec& ps, int dim) {
  ps.field = q.text("field");
  auto dot = ps.field.find('.');
  if (dot == std::string::npos) return;
  std::string c = ps.field.substr(dot + 1);
  ps.component = c == "x" ? 0 : c == "y" ? 1 : c == "z" ? 2 : -2;
  if (ps.component < 0 || ps.component >= dim)
    scene_error(p + ".field", "component '" + c + "' is not an axis");
  ps.field = ps.field.substr(0, dot);
}

// `axis: x` (y, z) or a vector of dim components; returned as a unit vector.
Point read_axis(MapReader& q, int dim) {
  const std::string at = q.at("axis");
  auto n = q.node("axis");
  Point axis(dim, 0.0);
  if (n.IsScalar()) {
    const std::string a = n.Scalar();
    const int k = a == "x" ? 0 : a == "y" ? 1 : a == "z" ? 2 : -1;
    if (k < 0 || k >= dim)
      scene_error(at,
                  "'" + a + "' is not an axis (x, y" + (dim == 3 ? ", z" : "") + " or a vector)");
    axis[k] = 1;
    return axis;
  }
  axis = as_vector(n, at, dim, q.constants());
  double a2 = 0;
  for (double c : axis) a2 += c * c;
  if (!(a2 > 0)) scene_error(at, "must not be the zero vector");
  for (double& c : axis) c /= std::sqrt(a2);
  return axis;
}

// profile: axis, bins and the optional range [lo, hi].
void read_profile(MapReader& q, ProbeSpec& ps, int dim) {
  ps.axis = read_axis(q, dim);
  if (!q.has("bins")) scene_error(q.at("bins"), "missing (the number of bins, at least 1)");
  ps.bins = q.integer("bins", 0);
  if (ps.bins < 1) scene_error(q.at("bins"), "must be at least 1, got " + std::to_string(ps.bins));
  if (q.has("range")) {
    ps.range = q.vector("range", 2);
    if (!(ps.range[0] < ps.range[1])) scene_error(q.at("range"), "must be [lo, hi] with lo < hi");
  } else {
    q.optional("range");
  }
}

// wall_pressure: `center` (a point on the wall face), `normal` (an axis or a vector, from the wall
// into the fluid; stored as a unit vector in ps.axis) and `size` (sensor length in 2D, diameter
// in 3D). The other types reject these keys as unknown.
void read_sensor(MapReader& q, ProbeSpec& ps, int dim) {
  ps.point = q.vector("center", dim);
  const std::string at = q.at("normal");
  auto n = q.node("normal");
  Point normal(dim, 0.0);
  if (n.IsScalar()) {
    const std::string a = n.Scalar();
    const int sign = !a.empty() && a[0] == '-' ? -1 : 1;
    const std::string ax = sign < 0 || (!a.empty() && a[0] == '+') ? a.substr(1) : a;
    const int k = ax == "x" ? 0 : ax == "y" ? 1 : ax == "z" ? 2 : -1;
    if (k < 0 || k >= dim)
      scene_error(at, "'" + a + "' is not an axis (x, -x, y, -y" + (dim == 3 ? ", z, -z" : "") +
                          " or a vector)");
    normal[k] = sign;
  } else {
    normal = as_vector(n, at, dim, q.constants());
  }
  double n2 = 0;
  for (double c : normal) n2 += c * c;
  if (!(n2 > 0) || !std::isfinite(n2)) scene_error(at, "must be a finite non-zero vector");
  for (double& c : normal) c /= std::sqrt(n2);
  ps.axis = normal;
  ps.size = q.positive("size");
}

// chip_ratio: the chip's thickness over the uncut chip thickness `size`. The chip is the particles
// of `body` whose distance along `axis` (up the rake face) from `point` (on the rake face, the
// surface's frame at t = 0) lies in `range` [s1, s2] and whose distance d along `normal` (the rake
// face's, into the chip) lies in [-dp, 5 size]; the layer from the nearest of them out to the
// first gap wider than 1.5 dp: thickness = max d - min d + dp over it. `method: section` takes
// the widest such run instead and corrects it by the direction e of its mean flow relative to
// the surface: the thickness normal to the flow of a chip crossing the window. `method: flow`
// takes the chip's speed relative to the surface, |v_i - v_s| averaged over the window: by mass
// conservation of the steady chip, thickness / h = |v_s| / chip speed (a curled chip too).
void read_chip(MapReader& q, const std::string& p, ProbeSpec& ps, const Scene& s, int dim) {
  ps.point = q.vector("point", dim);
  ps.axis = read_axis(q, dim);
  Point n = q.vector("normal", dim);
  double n2 = 0, dot = 0;
  for (int a = 0; a < dim; ++a) n2 += n[a] * n[a], dot += n[a] * ps.axis[a];
  if (!(n2 > 0) || !std::isfinite(n2))
    scene_error(q.at("normal"), "must be a finite non-zero vector");
  if (std::abs(dot) > 1e-6 * std::sqrt(n2))
    scene_error(q.at("normal"), "must be perpendicular to axis (the rake face's normal)");
  for (double& c : n) c /= std::sqrt(n2);
  ps.normal = n;
  ps.range = q.vector("range", 2);
  if (!(ps.range[0] >= 0 && ps.range[0] < ps.range[1]))
    scene_error(q.at("range"), "must be [s1, s2] with 0 <= s1 < s2 (along the rake face)");
  ps.size = q.positive("size");
  ps.method = q.choice("method", {"layer", "section", "flow"}, "layer");
  ps.target = q.text("body");
  auto it = std::find_if(s.bodies.begin(), s.bodies.end(),
                         [&](const BodySpec& b) { return b.name == ps.target; });
  if (it == s.bodies.end()) scene_error(p + ".body", "no body named '" + ps.target + "'");
}

// `weight` multiplies the integrand of integral, mean and kinetic_energy; others reject it.
void read_weight(MapReader& q, ProbeSpec& ps, const Scene& s) {
  if (!q.has("weight")) return void(q.optional("weight"));
  if (!is_one_of(ps.type, {"integral", "mean", "kinetic_energy"}))
    scene_error(q.at("weight"), "only integral, mean and kinetic_energy probes take a weight ('" +
                                    ps.type + "' would ignore it)");
  ps.weight_expr = q.text("weight");
  Expression check(ps.weight_expr, q.at("weight"), s.variables);
}

void check_surface(const std::string& p, const ProbeSpec& ps, const Scene& s) {
  bool found = false;
  std::vector<std::string> names;
  for (const auto& sf : s.surfaces) found = found || sf.name == ps.body, names.push_back(sf.name);
  if (ps.body.empty()) scene_error(p + ".surface", "missing (the name of a surface)");
  if (found) return;
  std::string hint = closest_word(ps.body, names);
  scene_error(p + ".surface", "no surface named '" + ps.body + "' in surfaces" +
                                  (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
}

// `body` names a body of the scene (a rigid one for the rigid_* types), a boundary condition
// (reaction_force) or nothing (contact_energy).
void check_body(const std::string& p, const ProbeSpec& ps, const Scene& s) {
  if (ps.type == "reaction_force") {
    bool found = false;
    for (const auto& bc : s.boundaries) found = found || bc.name == ps.body;
    if (!found) scene_error(p + ".body", "reaction_force needs the name of a boundary condition");
    return;
  }
  if (ps.type == "contact_energy" && !ps.body.empty())
    scene_error(p + ".body", "contact_energy is the energy of all contacts; it takes no body");
  const bool rigid = is_rigid_type(ps.type);
  if (rigid && ps.body.empty()) scene_error(p + ".body", "missing (the name of a rigid body)");
  if (ps.type == "wall_pressure" && ps.body.empty())
    scene_error(p + ".body", "missing (the name of the wall the sensor sits on)");
  if (ps.type == "solid_contact_force" && ps.body.empty())
    scene_error(p + ".body", "missing (the name of a solid body: the contact force on it)");
  if (ps.body.empty()) return;
  auto it = std::find_if(s.bodies.begin(), s.bodies.end(),
                         [&](const BodySpec& b) { return b.name == ps.body; });
  if (it == s.bodies.end()) scene_error(p + ".body", "no body named '" + ps.body + "'");
  if (ps.type == "wall_pressure" && it->phase == "fluid")
    scene_error(p + ".body",
                "'" + ps.body + "' is a fluid; wall_pressure needs the wall the sensor sits on");
  if (rigid && it->phase != "rigid")
    scene_error(p + ".body", "'" + ps.body + "' is not a rigid body (phase " + it->phase + "); " +
                                 ps.type + " needs a body with phase: rigid");
}

// A probe's name is a CSV column (and a profile's file name): plain text.
void check_probe_name(const std::string& name, const std::string& path) {
  if (name.empty()) scene_error(path, "must not be empty (it names a column of probes.csv)");
  if (has_controls(name) || name.find_first_of(",\"/\\") != std::string::npos)
    scene_error(path, "'" + printable(name) +
                          "' is not a column name (no commas, quotes, slashes or control "
                          "characters, bidirectional ones included)");
}

// The columns a probe writes: its name, or name_x, name_y (, name_z); a profile its file.
std::vector<std::string> column_names(const ProbeSpec& ps) {
  if (ps.columns <= 1) return {ps.type == "profile" ? "profile_" + ps.name : ps.name};
  std::vector<std::string> out{ps.name};  // a bare momentum name stands for its x column
  for (int a = 0; a < ps.columns; ++a) out.push_back(ps.name + "_" + "xyz"[a]);
  return out;
}

ProbeSpec read_probe(const YAML::Node& node, const std::string& p, const Scene& s) {
  const int dim = s.dimension;
  MapReader q(node, p, &s.variables);
  ProbeSpec ps;
  ps.name = q.text("name");
  check_probe_name(ps.name, q.at("name"));
  ps.type = q.choice("type", kTypes);
  if (is_one_of(ps.type, {"integral", "mean", "value_at", "tracked", "field_max", "field_min",
                          "extent", "profile"}))
    read_field(q, p, ps, dim);
  else
    q.optional("field");
  read_weight(q, ps, s);
  const bool on_surface = is_one_of(
      ps.type, {"surface_force", "surface_contacts", "surface_displacement", "chip_ratio"});
  if (ps.type == "chip_ratio") {
    ps.body = q.text("surface");
    read_chip(q, p, ps, s, dim);
  } else if (on_surface && q.has("surface")) {  // the surface's name (`body` is accepted too)
    if (q.has("body")) scene_error(p, "give either surface or body, not both");
    ps.body = q.text("surface");
  }
  if (ps.body.empty()) ps.body = q.text("body", "");
  if (ps.type == "chip_ratio") {
  } else if (ps.type == "penetration") {
    ps.target = q.text("target", "");
    bool found = ps.target.empty();
    for (const auto& body : s.bodies) found = found || body.name == ps.target;
    if (!found) scene_error(p + ".target", "no body named '" + ps.target + "'");
  } else {
    q.optional("target");
  }
  if (is_one_of(ps.type, {"value_at", "tracked", "diameter"}))
    ps.point = q.vector("point", dim);
  else if (ps.type != "chip_ratio")
    q.optional("point");
  if (ps.type == "wall_pressure") read_sensor(q, ps, dim);
  if (ps.type == "diameter") {
    ps.axis = as_vector(q.node("axis"), q.at("axis"), dim, q.constants());
    double a2 = 0;
    for (double c : ps.axis) a2 += c * c;
    if (!(a2 > 0)) scene_error(p + ".axis", "must not be the zero vector");
    for (double& c : ps.axis) c /= std::sqrt(a2);
  } else if (ps.type == "profile") {
    read_profile(q, ps, dim);
  } else if (ps.type != "chip_ratio") {
    q.optional("axis");
  }
  if (ps.type == "pieces") {
    ps.min_particles = q.integer("min_particles", ps.min_particles);
    if (ps.min_particles < 1) scene_error(q.at("min_particles"), "must be at least 1");
  } else {
    q.optional("min_particles");
  }
  if (on_surface)
    check_surface(p, ps, s);
  else
    check_body(p, ps, s);
  q.finish();
  return ps;
}

}  // namespace

void read_probes(MapReader& pr, Scene& s) {
  s.probe_every = pr.non_negative("every", 0.0);
  auto list = pr.node("list");
  if (!list.IsSequence()) scene_error("probes.list", "expected a list of probes");
  std::set<std::string> columns = {"time", "step"};  // of probes.csv (and profile files)
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = "probes.list[" + std::to_string(i) + "]";
    ProbeSpec ps = read_probe(list[i], p, s);
    ps.columns = column_count(ps.type, s.dimension);
    for (const auto& c : column_names(ps))
      if (!columns.insert(c).second)
        scene_error(p + " (" + ps.name + ").name", "duplicate probe column '" + c + "'");
    s.probes.push_back(std::move(ps));
  }
}

bool names_probe_column(const std::vector<ProbeSpec>& probes, const std::string& name) {
  for (const auto& ps : probes) {
    // A bare momentum or reaction_force name stands for its x component (as before).
    if (ps.name == name && (ps.columns == 1 || is_one_of(ps.type, {"momentum", "reaction_force"})))
      return true;
    for (int a = 0; a < ps.columns && ps.columns > 1; ++a)
      if (ps.name + "_" + "xyz"[a] == name) return true;
  }
  return false;
}

}  // namespace monosph
