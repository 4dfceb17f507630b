#include "scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "expression.hpp"
#include "scene_probes.hpp"
#include "scene_reader.hpp"
#include "scene_variables.hpp"

namespace monosph {

double Material::sound_speed() const {
  return std::sqrt(bulk_modulus / density);
}
std::optional<Material> library_material(const std::string& name) {
  // MMB 2020 Table 1 (Al 6061-T6 after [38]; PMMA). Temperatures in K.
  Material m;
  m.name = name;
  if (name == "Al6061-T6") {
    m.density = 2800, m.bulk_modulus = 69e9, m.shear_modulus = 26.5e9, m.heat_capacity = 885;
    m.plasticity = {true, 164e6, 211e6, 0.465, 0.002, 1.0, 1.419, 292, 925};
    m.damage = {true, -0.77, 1.45, -0.47, 0.0, 1.6};
    return m;
  }
  if (name == "PMMA") {
    m.density = 1186, m.bulk_modulus = 5.85e9, m.shear_modulus = 2.2e9, m.heat_capacity = 1470;
    m.plasticity = {true, 212e6, 580e6, 3.5, 0.081, 0.001, 0.749, 213, 398};
    m.damage = {true, -1.751, 2.32, -0.773, -0.0491, 0.38};
    return m;
  }
  if (name == "iron") {  // pure iron (handbook): E = 211 GPa, nu = 0.29 -> K, mu; abrasive grains
    const double e = 211e9, nu = 0.29;
    m.density = 7870, m.bulk_modulus = e / (3 * (1 - 2 * nu)), m.shear_modulus = e / (2 * (1 + nu));
    return m;
  }
  return std::nullopt;
}

std::vector<std::string> library_material_names() {
  return {"Al6061-T6", "PMMA", "iron"};
}

double Material::wave_speed() const {
  return std::sqrt((bulk_modulus + 4.0 * shear_modulus / 3.0) / density);
}

int Scene::material_index(const std::string& n) const {
  for (std::size_t k = 0; k < materials.size(); ++k)
    if (materials[k].name == n) return static_cast<int>(k);
  return -1;
}

namespace {

// Physics modules for scenes (switched on by the bodies and surfaces that need them).
const std::vector<std::string> kModules = {"solid",    "rigid",   "fluid",
                                           "clusters", "contact", "lubrication"};

void check_expression(const std::string& text, const std::string& path, const Constants& vars) {
  Expression e(text, path, vars);
}

std::vector<std::string> expressions(MapReader& r, const std::string& key, int dim,
                                     const Constants& vars) {
  auto n = r.node(key);
  if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
    scene_error(r.at(key), "expected a list of " + std::to_string(dim) + " expressions");
  std::vector<std::string> out;
  for (int a = 0; a < dim; ++a) {
    std::string p = r.at(key) + "[" + std::to_string(a) + "]";
    out.push_back(as_text(n[a], p));
    check_expression(out.back(), p, vars);
  }
  return out;
}

// Built-in initial velocity profiles, written out as expressions.
std::vector<std::string> velocity_profile(MapReader& in, int dim) {
  MapReader pr(in.node("velocity_profile"), in.at("velocity_profile"));
  pr.choice("type", {"cantilever_mode"});
  // Fundamental bending mode of a clamped plate (MMB Eq. 35-36): v(x) = v_l f(x)/f(l),
  // f(x) = (cos kl + cosh kl)(cosh kx - cos kx) + (sin kl - sinh kl)(sinh kx - sin kx).
  const double vl = pr.number("amplitude");
  const double x0 = pr.number("clamp");
  const double len = pr.positive("length");
  const double kl = pr.positive("kl", 1.875);
  const std::string axis = pr.choice("direction", {"x", "y", "z"}, "y");
  const std::string along = pr.choice("along", {"x", "y", "z"}, "x");
  pr.finish();
  const int a = axis[0] - 'x';
  if (a >= dim || along[0] - 'x' >= dim) scene_error(pr.path(), "axis not in this dimension");
  const double k = kl / len;
  auto f = [&](double x) {
    return (std::cos(kl) + std::cosh(kl)) * (std::cosh(k * x) - std::cos(k * x)) +
           (std::sin(kl) - std::sinh(kl)) * (std::sinh(k * x) - std::sin(k * x));
  };
  const std::string sx = fmt::format("({}-({:.17g}))", along, x0);
  const std::string ks = fmt::format("{:.17g}", k);
  std::string e = fmt::format(
      "{0}>0 ? "
      "{1:.17g}*(({2:.17g})*(cosh({3}*{0})-cos({3}*{0}))+({4:.17g})*(sinh({3}*{0})-sin({3}*{0}))) "
      ": 0",
      sx, vl / f(len), std::cos(kl) + std::cosh(kl), ks, std::sin(kl) - std::sinh(kl));
  std::vector<std::string> out(dim, "0");
  out[a] = e;
  return out;
}

Shape read_shape(const YAML::Node& node, const std::string& path, int dim) {
  static const std::vector<std::string> kinds = {"box",     "circle",        "sphere",
                                                 "ring",    "hollow_sphere", "cylinder",
                                                 "polygon", "union",         "difference"};
  if (!node.IsMap() || node.size() != 1)
    scene_error(path,
                "expected a map with exactly one shape key (box, circle, sphere, ring, "
                "hollow_sphere, cylinder, polygon, union, difference)");
  std::string kind = node.begin()->first.as<std::string>();
  YAML::Node body = node.begin()->second;
  std::string p = path + "." + kind;
  Shape s;
  auto list_of_shapes = [&](Shape::Kind k) {
    if (!body.IsSequence() || body.size() < 1) scene_error(p, "expected a list of shapes");
    s.kind = k;
    for (std::size_t i = 0; i < body.size(); ++i)
      s.parts.push_back(read_shape(body[i], p + "[" + std::to_string(i) + "]", dim));
    if (k == Shape::Kind::Difference && s.parts.size() < 2)
      scene_error(p, "expected a base shape followed by at least one shape to subtract");
  };
  if (kind == "box") {
    MapReader r(body, p);
    s.kind = Shape::Kind::Box;
    s.a = r.vector("min", dim);
    s.b = r.vector("max", dim);
    r.finish();
    for (int k = 0; k < dim; ++k)
      if (!(s.b[k] > s.a[k])) scene_error(p + ".max", "must be greater than min in every axis");
  } else if ((kind == "circle" && dim == 2) || (kind == "sphere" && dim == 3)) {
    MapReader r(body, p);
    s.kind = Shape::Kind::Sphere;
    s.center = r.vector("center", dim);
    s.r0 = r.positive("radius");
    r.finish();
  } else if ((kind == "ring" && dim == 2) || (kind == "hollow_sphere" && dim == 3)) {
    MapReader r(body, p);
    s.kind = Shape::Kind::Ring;
    s.center = r.vector("center", dim);
    s.r0 = r.positive("inner");
    s.r1 = r.positive("outer");
    r.finish();
    if (!(s.r1 > s.r0)) scene_error(p + ".outer", "must be greater than inner");
  } else if (kind == "cylinder" && dim == 3) {
    MapReader r(body, p);
    s.kind = Shape::Kind::Cylinder;
    s.a = r.vector("start", 3);
    s.b = r.vector("end", 3);
    s.r0 = r.positive("radius");
    r.finish();
  } else if (kind == "polygon" && dim == 2) {
    MapReader r(body, p);
    s.kind = Shape::Kind::Polygon;
    auto v = r.node("vertices");
    if (!v.IsSequence() || v.size() < 3) scene_error(p + ".vertices", "expected at least 3 points");
    for (std::size_t i = 0; i < v.size(); ++i)
      s.vertices.push_back(as_vector(v[i], p + ".vertices[" + std::to_string(i) + "]", 2));
    r.finish();
  } else if (kind == "union") {
    list_of_shapes(Shape::Kind::Union);
  } else if (kind == "difference") {
    list_of_shapes(Shape::Kind::Difference);
  } else {
    std::string hint = closest_word(kind, kinds);
    scene_error(p, "unknown shape in " + std::to_string(dim) +
                       "D (allowed: box, union, difference, " +
                       (dim == 2 ? "circle, ring, polygon)" : "sphere, hollow_sphere, cylinder)") +
                       (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
  return s;
}

// A rigid surface (MMB Sect. 3; built by src/rigid): one geometry key, motion, contact parameters.
// `folder` resolves a relative STL path (the scene file's folder; empty: the working directory).
SurfaceSpec read_surface(YAML::Node node, const std::string& index_path, int dim,
                         const std::filesystem::path& folder, const Constants& vars) {
  MapReader r(node, index_path);
  SurfaceSpec s;
  s.name = r.text("name");
  const std::string p = index_path + " (" + s.name + ")";
  MapReader q(node, p);  // the same map, with the name in the paths of its keys
  q.text("name");
  s.friction = q.non_negative("friction", 0.0);
  s.damping = q.non_negative("damping", 0.0);
  s.stiffness = q.positive("stiffness", 0.0);
  s.poisson_ratio = q.non_negative("poisson_ratio", 0.3);
  if (s.poisson_ratio >= 0.5) scene_error(q.at("poisson_ratio"), "must be below 0.5");
  if (q.has("poisson_ratio") && !q.has("stiffness"))
    scene_error(q.at("poisson_ratio"), "needs a stiffness (a rigid surface has no Poisson ratio)");
  s.scale = q.positive("scale", 1.0);
  s.translate =
      q.has("translate") ? q.vector("translate", dim) : (q.optional("translate"), Point(dim, 0.0));
  if (q.has("velocity"))
    s.velocity_expr = expressions(q, "velocity", dim, vars);
  else
    s.velocity_expr.assign(dim, "0"), q.optional("velocity");
  const std::vector<std::string> kinds2 = {"box", "plane", "segment", "polyline", "polygon"};
  const std::vector<std::string> kinds3 = {"box", "plane", "rectangle", "triangles", "stl"};
  const auto& kinds = dim == 2 ? kinds2 : kinds3;
  std::vector<std::string> given;
  for (const auto& k : kinds)
    if (q.has(k)) given.push_back(k);
  const std::string allowed =
      dim == 2 ? "box, plane, segment, polyline, polygon" : "box, plane, rectangle, triangles, stl";
  if (given.size() != 1) {
    if (given.empty()) q.finish();  // a misspelt geometry key is named there
    scene_error(p, "give exactly one geometry key (" + std::to_string(dim) + "D: " + allowed + ")");
  }
  s.kind = given[0];
  const std::string g = q.at(s.kind);
  auto points = [&](std::size_t min_count) {
    auto v = q.node(s.kind);
    if (!v.IsSequence() || v.size() < min_count)
      scene_error(g, "expected a list of at least " + std::to_string(min_count) + " points");
    for (std::size_t i = 0; i < v.size(); ++i)
      s.points.push_back(as_vector(v[i], g + "[" + std::to_string(i) + "]", dim));
  };
  auto distinct = [&](std::size_t i, std::size_t j) {
    double d2 = 0;
    for (int a = 0; a < dim; ++a) d2 += std::pow(s.points[i][a] - s.points[j][a], 2);
    if (!(d2 > 0))
      scene_error(g, "points " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
  };
  if (s.kind == "box") {
    MapReader b(q.node("box"), g);
    s.points = {b.vector("min", dim), b.vector("max", dim)};
    b.finish();
    for (int a = 0; a < dim; ++a)
      if (!(s.points[1][a] > s.points[0][a]))
        scene_error(g + ".max", "must be greater than min in every axis");
  } else if (s.kind == "plane") {
    MapReader b(q.node("plane"), g);
    s.points = {b.vector("point", dim), b.vector("normal", dim)};
    double nn = 0;
    for (double c : s.points[1]) nn += c * c;
    if (!(nn > 0)) scene_error(g + ".normal", "must not be zero");
    if (dim == 2) {
      s.size[0] = b.positive("size");
    } else {
      auto sz = b.vector("size", 2);
      if (!(sz[0] > 0 && sz[1] > 0)) scene_error(g + ".size", "side lengths must be positive");
      s.size[0] = sz[0], s.size[1] = sz[1];
    }
    b.finish();
  } else if (s.kind == "segment") {
    points(2);
    if (s.points.size() != 2) scene_error(g, "expected two points [[x0, y0], [x1, y1]]");
    distinct(0, 1);
  } else if (s.kind == "polyline" || s.kind == "polygon") {
    points(s.kind == "polyline" ? 2 : 3);
    for (std::size_t i = 0; i + 1 < s.points.size(); ++i) distinct(i, i + 1);
    if (s.kind == "polygon") distinct(s.points.size() - 1, 0);
  } else if (s.kind == "rectangle") {
    points(4);
    if (s.points.size() != 4) scene_error(g, "expected four corners in order");
    for (std::size_t i = 0; i < 4; ++i) distinct(i, (i + 1) % 4);
  } else if (s.kind == "triangles") {
    auto v = q.node("triangles");
    if (!v.IsSequence() || v.size() < 1) scene_error(g, "expected a list of triangles");
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string ti = g + "[" + std::to_string(i) + "]";
      if (!v[i].IsSequence() || v[i].size() != 3)
        scene_error(ti, "expected three corners [[x, y, z], [x, y, z], [x, y, z]]");
      for (std::size_t c = 0; c < 3; ++c)
        s.points.push_back(as_vector(v[i][c], ti + "[" + std::to_string(c) + "]", 3));
    }
  } else {  // stl
    std::filesystem::path f = q.text("stl");
    if (f.is_relative()) f = folder / f;
    std::error_code ec;
    f = std::filesystem::absolute(f, ec).lexically_normal();
    std::ifstream in(f, std::ios::binary);
    if (!in || std::filesystem::is_directory(f, ec))
      scene_error(g, "cannot read STL file '" + f.string() + "'");
    s.file = f.string();
    node["stl"] = s.file;  // absolute in the stored scene text, so that a restart finds it
  }
  q.finish();
  return s;
}

YAML::Node parse_yaml(const std::string& text, const std::string& origin) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(origin + ": invalid YAML at line " + std::to_string(e.mark.line + 1) +
                     ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

void apply_override(YAML::Node& root, const std::string& item) {
  auto eq = item.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + item + ": expected key=value, e.g. --set end_time=0.1");
  std::string key = item.substr(0, eq), value = item.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  YAML::Node value_node;
  try {
    value_node = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + item + ": invalid value: " + e.msg);
  }
  // Walk with explicit node copies (yaml-cpp nodes are handles).
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node cur = chain.back();
    const std::string& k = parts[i];
    if (cur.IsSequence()) {
      std::size_t idx;
      try {
        idx = std::stoul(k);
      } catch (...) {
        throw InputError("--set " + key + ": '" + k + "' must be a list index");
      }
      if (idx >= cur.size()) throw InputError("--set " + key + ": index " + k + " out of range");
      chain.push_back(cur[idx]);
    } else {
      if (!cur[k].IsDefined() || cur[k].IsNull()) cur[k] = YAML::Node(YAML::NodeType::Map);
      chain.push_back(cur[k]);
    }
  }
  YAML::Node last = chain.back();
  const std::string& k = parts.back();
  if (last.IsSequence()) {
    std::size_t idx = std::stoul(k);
    if (idx >= last.size()) throw InputError("--set " + key + ": index " + k + " out of range");
    last[idx] = value_node;
  } else {
    last[k] = value_node;
  }
}

Material read_material(const std::string& name, const YAML::Node& n, const std::string& path) {
  MapReader r(n, path);
  Material m;
  if (r.has("preset")) {
    const std::string preset = r.text("preset");
    auto lib = library_material(preset);
    if (!lib) {
      std::string names;
      for (const auto& k : library_material_names()) names += (names.empty() ? "" : ", ") + k;
      scene_error(r.at("preset"),
                  "no shipped material '" + preset + "' (available: " + names + ")");
    }
    m = *lib;
  }
  m.name = name;
  m.density = m.density > 0 ? r.positive("density", m.density) : r.positive("density");
  if (r.has("bulk_modulus") && r.has("sound_speed"))
    scene_error(path, "give either bulk_modulus or sound_speed, not both");
  if (r.has("sound_speed")) {
    double c = r.positive("sound_speed");
    m.bulk_modulus = m.density * c * c;
    r.optional("bulk_modulus");
  } else {
    m.bulk_modulus = m.bulk_modulus > 0 ? r.positive("bulk_modulus", m.bulk_modulus)
                                        : r.positive("bulk_modulus");
    r.optional("sound_speed");
  }
  m.shear_modulus = r.non_negative("shear_modulus", m.shear_modulus);
  m.heat_capacity = r.non_negative("heat_capacity", m.heat_capacity);
  m.taylor_quinney = r.non_negative("taylor_quinney", m.taylor_quinney);
  m.viscosity = r.non_negative("viscosity", m.viscosity);
  // Fluids: the pressure below which the liquid cavitates (gauge, Pa; Brennen 1995): the EOS
  // pressure is held at it, so that the fluid carries no larger tension.
  if (r.has("cavitation_pressure")) {
    m.cavitation_pressure = r.number("cavitation_pressure");
    if (!(m.cavitation_pressure <= 0))
      scene_error(r.at("cavitation_pressure"),
                  "must be <= 0 (a gauge pressure: the tension the liquid bears)");
  } else {
    r.optional("cavitation_pressure");
  }
  // Stress from F for total-Lagrangian bodies (Ganzenmueller 2015 Eq. 44); default hypoelastic.
  m.neo_hookean =
      r.choice("elasticity", {"hypoelastic", "neo_hookean"}, "hypoelastic") == "neo_hookean";
  if (m.neo_hookean && m.shear_modulus <= 0)
    scene_error(r.at("elasticity"), "neo_hookean needs a positive shear_modulus");
  if (m.taylor_quinney > 1) scene_error(r.at("taylor_quinney"), "must lie in [0, 1]");
  if (r.has("plasticity") && r.node("plasticity").IsScalar()) {  // `plasticity: none`: elastic
    if (r.node("plasticity").Scalar() != "none")
      scene_error(r.at("plasticity"), "expected a map {A, B, n, ...} or 'none'");
    m.plasticity.on = false;
  } else if (r.has("plasticity")) {
    // MMB Eq. 23 (Johnson & Cook 1983); perfect plasticity is B = 0.
    MapReader q(r.node("plasticity"), r.at("plasticity"));
    q.choice("type", {"johnson_cook"}, "johnson_cook");
    JohnsonCook& jc = m.plasticity;
    jc.on = true;
    jc.A = jc.A > 0 ? q.positive("A", jc.A) : q.positive("A");
    jc.B = q.non_negative("B", jc.B);
    jc.n = q.positive("n", jc.n);
    jc.C = q.non_negative("C", jc.C);
    jc.rate0 = q.positive("reference_strain_rate", jc.rate0);
    jc.m = q.positive("m", jc.m);
    jc.T_ref = q.positive("reference_temperature", jc.T_ref);
    jc.T_melt = q.non_negative("melting_temperature", jc.T_melt);
    if (jc.T_melt > 0 && jc.T_melt <= jc.T_ref)
      scene_error(q.at("melting_temperature"),
                  "must exceed reference_temperature (or be 0: no thermal softening)");
    q.finish();
  } else {
    r.optional("plasticity");
  }
  if (r.has("damage") && r.node("damage").IsScalar()) {  // `damage: none` turns a preset's off
    if (r.node("damage").Scalar() != "none")
      scene_error(r.at("damage"), "expected a map {D1..D5} or 'none'");
    m.damage.on = false;
  } else if (r.has("damage")) {
    MapReader q(r.node("damage"), r.at("damage"));
    q.choice("type", {"johnson_cook"}, "johnson_cook");
    JohnsonCookDamage& d = m.damage;
    const bool preset = d.on;  // D1-D3 have no neutral value: required unless a preset gave them
    d.on = true;
    d.d1 = preset ? q.number("D1", d.d1) : q.number("D1");
    d.d2 = preset ? q.number("D2", d.d2) : q.number("D2");
    d.d3 = preset ? q.number("D3", d.d3) : q.number("D3");
    d.d4 = q.number("D4", d.d4);
    d.d5 = q.number("D5", d.d5);
    d.min_failure_strain = q.positive("min_failure_strain", d.min_failure_strain);
    q.finish();
  } else {
    r.optional("damage");
  }
  if (m.damage.on && !m.plasticity.on)
    scene_error(r.at("damage"),
                "Johnson-Cook damage grows with plastic strain: give `plasticity` too, or "
                "`damage: none`");
  if (m.plasticity.on && m.neo_hookean)
    scene_error(r.at("elasticity"), "neo_hookean is elastic: remove `plasticity` or the key");
  if (m.plasticity.on && m.shear_modulus <= 0)
    scene_error(r.at("plasticity"), "needs a positive shear_modulus");
  r.finish();
  return m;
}

}  // namespace

// Section `lubrication` (src/coupling/lubrication_module.hpp): needs a rigid and a fluid body;
// the film viscosity defaults to the fluid's.
static void read_lubrication(MapReader& r, Scene& s) {
  if (!r.has("lubrication")) {
    r.optional("lubrication");
    return;
  }
  MapReader c(r.node("lubrication"), "lubrication");
  auto& l = s.lubrication;
  l.on = true;
  l.cutoff = c.positive("cutoff", 1.5);
  l.min_gap = c.positive("min_gap", 0.05);
  if (!(l.min_gap < l.cutoff))
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
    l.viscosity = c.positive("viscosity");
  } else {
    if (!fluid) scene_error("lubrication.viscosity", "is required without a fluid body");
    l.viscosity = s.materials[fluid->material].viscosity;
    if (!(l.viscosity > 0))
      scene_error("lubrication.viscosity", "the fluid's material has no viscosity: give one");
  }
  c.finish();
  if (std::find(s.modules.begin(), s.modules.end(), "lubrication") == s.modules.end())
    s.modules.push_back("lubrication");
}

Scene load_scene_text(const std::string& text, const std::vector<std::string>& overrides,
                      const std::string& origin) {
  YAML::Node root = parse_yaml(text, origin);
  if (!root.IsMap()) throw InputError(origin + ": a scene must be a YAML map of keys");
  // The written end time, which the references are posed at (checked below as end_time).
  double written_end = -1;
  if (const YAML::Node e = static_cast<const YAML::Node&>(root)["end_time"]; e && e.IsScalar()) {
    try {
      written_end = e.as<double>();
    } catch (const YAML::Exception&) {  // malformed: reported below, unless --set replaces it
    }
  }
  for (const auto& o : overrides) {
    check_variable_override(root, o);  // scene_variables.cpp: a typo in a variable name fails
    apply_override(root, o);
  }
  Scene s;
  {
    YAML::Emitter out;
    out << root;
    s.yaml = out.c_str();
  }
  MapReader r(root, "");
  s.name = r.text("name", "scene");
  s.description = r.text("description", "");
  s.dimension = r.integer("dimension", 2);
  if (s.dimension != 2 && s.dimension != 3)
    scene_error("dimension", "must be 2 or 3, got " + std::to_string(s.dimension));
  const int dim = s.dimension;
  s.variables = read_variables(r);  // before every expression that may use them
  s.dp = r.positive("dp");

  if (r.has("kernel")) {
    auto kn = r.node("kernel");
    if (kn.IsScalar()) {
      s.kernel = kernel_from_name(as_text(kn, "kernel"));
    } else {
      MapReader k(kn, "kernel");
      s.kernel = kernel_from_name(
          k.choice("type", {"cubic_spline", "wendland_c2", "quintic_spline"}, "cubic_spline"));
      s.h_factor = k.positive("h_factor", 1.3);
      k.finish();
    }
  }

  {
    MapReader d(r.node("domain"), "domain");
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
    d.finish();
  }

  if (r.has("neighbours")) {
    MapReader nb(r.node("neighbours"), "neighbours");
    s.skin_factor = nb.positive("skin", 0.3);
    s.reorder_every = nb.integer("reorder_every", 1);
    if (s.reorder_every < 0) scene_error("neighbours.reorder_every", "must be 0 (never) or more");
    nb.finish();
  } else {
    r.optional("neighbours");
  }

  {
    auto mats = r.node("materials");
    if (!mats.IsMap() || mats.size() == 0)
      scene_error("materials", "expected a map of named materials");
    for (auto it = mats.begin(); it != mats.end(); ++it) {
      std::string name = it->first.as<std::string>();
      s.materials.push_back(read_material(name, it->second, "materials." + name));
    }
  }

  s.modules.clear();
  if (r.has("modules")) {
    for (const auto& m : r.strings("modules")) {
      if (std::find(kModules.begin(), kModules.end(), m) == kModules.end())
        scene_error(
            "modules",
            "unknown module '" + m +
                "' (available: solid, rigid, fluid, clusters, contact, lubrication; they are "
                "switched on by the bodies and surfaces that need them)");
      s.modules.push_back(m);
    }
  } else {
    r.optional("modules");
  }

  {
    auto bodies = r.node("bodies");
    if (!bodies.IsSequence() || bodies.size() == 0)
      scene_error("bodies", "expected a list of bodies");
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      std::string p = "bodies[" + std::to_string(i) + "]";
      MapReader b(bodies[i], p);
      BodySpec body;
      body.name = b.text("name");
      p = "bodies[" + std::to_string(i) + "] (" + body.name + ")";
      for (const auto& other : s.bodies)
        if (other.name == body.name) scene_error(p + ".name", "duplicate body name");
      body.phase = b.choice("phase", {"fluid", "solid", "wall", "rigid"});
      body.continuum = b.text("continuum", body.name);
      // MMB Eulerian (default), Ganzenmueller 2015 total-Lagrangian SPH, or Zhang et al. 2024's
      // essentially non-hourglass updated Lagrangian formulation.
      if (b.has("formulation")) {
        if (body.phase != "solid") scene_error(p + ".formulation", "applies to solid bodies only");
        const std::string f =
            b.choice("formulation", {"eulerian", "total_lagrangian", "non_hourglass"});
        body.total_lagrangian = f == "total_lagrangian";
        body.formulation = f == "total_lagrangian" ? 1 : f == "non_hourglass" ? 2 : 0;
      } else {
        b.optional("formulation");
      }
      // Keys of the Eulerian scheme that a total-Lagrangian body does not have.
      if (body.total_lagrangian)
        for (const char* k : {"artificial_viscosity", "artificial_stress", "density_diffusion",
                              "stress_divergence", "erosion"})
          if (b.has(k))
            scene_error(p + "." + k, "not available with formulation: total_lagrangian");
      std::string mat = b.text("material");
      body.material = s.material_index(mat);
      if (body.material < 0) {
        std::vector<std::string> names;
        for (const auto& m : s.materials) names.push_back(m.name);
        std::string hint = closest_word(mat, names);
        scene_error(p + ".material", "no material named '" + mat + "' in materials" +
                                         (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
      }
      body.shape = read_shape(b.node("shape"), p + ".shape", dim);
      body.jitter = b.non_negative("jitter", 0.0);
      if (body.jitter >= 0.5) scene_error(p + ".jitter", "must be below 0.5 (fraction of dp)");
      body.seed = static_cast<unsigned>(b.integer("seed", 1));
      if (b.has("initial")) {
        MapReader in(b.node("initial"), p + ".initial");
        body.density_expr = in.text("density", "");
        body.temperature = in.positive("temperature", 0.0 + body.temperature);
        if (!body.density_expr.empty())
          check_expression(body.density_expr, in.at("density"), s.variables);
        if (in.has("velocity") && in.has("velocity_profile"))
          scene_error(in.path(), "give either velocity or velocity_profile, not both");
        if (in.has("velocity"))
          body.velocity_expr = expressions(in, "velocity", dim, s.variables);
        else
          in.optional("velocity");
        if (in.has("velocity_profile"))
          body.velocity_expr = velocity_profile(in, dim);
        else
          in.optional("velocity_profile");
        if (in.has("angular_velocity")) {  // rigid clusters: about each cluster's centre of mass
          if (body.phase != "rigid")
            scene_error(in.at("angular_velocity"), "applies to rigid bodies only");
          body.angular_velocity =
              dim == 2 ? Point{in.number("angular_velocity")} : in.vector("angular_velocity", 3);
        } else {
          in.optional("angular_velocity");
        }
        in.finish();
      } else {
        b.optional("initial");
      }
      if (b.has("artificial_viscosity")) {
        MapReader av(b.node("artificial_viscosity"), p + ".artificial_viscosity");
        body.av_alpha = av.non_negative("alpha", 0.0);
        body.av_beta = av.non_negative("beta", 0.0);
        av.finish();
      } else {
        b.optional("artificial_viscosity");
      }
      if (b.has("artificial_stress")) {
        MapReader as(b.node("artificial_stress"), p + ".artificial_stress");
        body.as_epsilon = as.non_negative("epsilon", 0.3);
        body.as_n = as.positive("n", 4.0);
        as.finish();
      } else {
        b.optional("artificial_stress");
      }
      if (b.has("density_diffusion")) {
        MapReader dd(b.node("density_diffusion"), p + ".density_diffusion");
        body.delta = dd.non_negative("delta", 0.1);
        dd.finish();
      } else {
        b.optional("density_diffusion");
      }
      if (b.has("stress_divergence")) {
        if (body.phase != "solid")
          scene_error(p + ".stress_divergence", "applies to solid bodies only");
        body.corrected_divergence =
            b.choice("stress_divergence", {"normalised", "corrected"}) == "corrected";
      } else {
        b.optional("stress_divergence");
      }
      if (body.formulation == 2 && s.materials[body.material].plasticity.on)
        scene_error(p + ".formulation",
                    "non_hourglass (Zhang et al. 2024) is for elastic materials; material '" +
                        s.materials[body.material].name + "' has plasticity");
      if (b.has("laplacian_zeta")) {
        if (body.formulation != 2)
          scene_error(p + ".laplacian_zeta", "applies with formulation: non_hourglass only");
        body.laplacian_zeta = b.positive("laplacian_zeta");
      } else {
        b.optional("laplacian_zeta");
        body.laplacian_zeta = 0.7 * dim + 2.1;  // Zhang et al. 2024, Sect. 6 (Wendland, h = 1.3 dp)
      }
      if (b.has("hourglass")) {
        if (body.phase != "solid")
          scene_error(p + ".hourglass", "hourglass control applies to solid bodies only");
        MapReader hg(b.node("hourglass"), p + ".hourglass");
        // Ganzenmueller's alpha (Eq. 31-32) is MMB's xi (Eq. 32): one coefficient, two names.
        if (hg.has("alpha") && hg.has("xi")) scene_error(hg.path(), "give either xi or alpha");
        if (hg.has("alpha")) {
          body.hg_xi = hg.non_negative("alpha", 0.0);
          hg.optional("xi");
        } else {
          body.hg_xi = hg.non_negative("xi", 0.0);
          hg.optional("alpha");
        }
        body.hg_zeta = hg.non_negative("zeta", 0.0);
        body.hg_chi = hg.non_negative("chi", 0.0);
        // Only the stiffness form (G15 Eq. 32) for total-Lagrangian bodies: zeta, chi must be 0.
        if (body.total_lagrangian)
          for (const char* k : {"zeta", "chi"})
            if (hg.has(k) && hg.number(k) != 0)
              scene_error(hg.at(k), "must be 0 with formulation: total_lagrangian");
        if (body.hg_chi > 1) scene_error(p + ".hourglass.chi", "must be between 0 and 1");
        const std::string ref =
            hg.choice("reference", {"initial", "intermediate", "least_squares"}, "initial");
        body.hg_reference = ref == "initial" ? 0 : ref == "intermediate" ? 1 : 2;
        // Ganzenmueller 2015 (Sect. 3): E of Eq. 32 replaced by the yield stress once plastic.
        body.hg_plastic_switch = hg.boolean("plastic_switch", false);
        hg.finish();
      } else {
        b.optional("hourglass");
      }
      if (b.has("self_contact")) {
        if (body.phase != "solid") scene_error(p + ".self_contact", "applies to solid bodies only");
        MapReader sc(b.node("self_contact"), p + ".self_contact");
        body.self_contact = sc.positive("distance");
        if (body.self_contact >= 1)
          scene_error(p + ".self_contact.distance", "must be below 1 (a fraction of dp)");
        sc.finish();
      } else {
        b.optional("self_contact");
      }
      if (b.has("shifting")) {  // delta-plus particle shifting (Sun et al. 2017)
        if (body.phase != "fluid") scene_error(p + ".shifting", "applies to fluid bodies only");
        MapReader sh(b.node("shifting"), p + ".shifting");
        body.shift_speed = sh.positive("speed");
        body.shift_R = sh.non_negative("R", 0.2);
        body.shift_n = sh.positive("n", 4.0);
        sh.finish();
      } else {
        b.optional("shifting");
      }
      if (b.has("viscous_form")) {
        if (body.phase != "fluid") scene_error(p + ".viscous_form", "applies to fluid bodies only");
        body.viscous_form = b.choice("viscous_form", {"auto", "morris", "central"});
      } else {
        b.optional("viscous_form");
      }
      if (b.has("slip")) {
        if (body.phase == "fluid")
          scene_error(p + ".slip", "applies to wall-like (non-fluid) bodies");
        body.no_slip = b.choice("slip", {"no_slip", "free_slip"}) == "no_slip";
      } else {
        b.optional("slip");
      }
      if (b.has("wall_pressure")) {
        if (body.phase == "fluid")
          scene_error(p + ".wall_pressure", "applies to wall-like (non-fluid) bodies");
        body.non_negative_wall_pressure =
            b.choice("wall_pressure", {"extrapolated", "non_negative"}) == "non_negative";
      } else {
        b.optional("wall_pressure");
      }
      if (b.has("damping")) {  // dynamic relaxation to a static state (quasi-static loading)
        if (body.phase != "solid" && body.phase != "fluid")
          scene_error(p + ".damping", "applies to solid and fluid bodies");
        body.damping = b.non_negative("damping", 0.0);
      } else {
        b.optional("damping");
      }
      if (b.has("body_force"))  // replaces the scene's body_force for this body
        body.body_force = b.vector("body_force", dim);
      else
        b.optional("body_force");
      body.fill_rest = b.choice("fill", {"all", "rest"}, "all") == "rest";
      if (b.has("clusters")) {
        if (body.phase != "rigid") scene_error(p + ".clusters", "applies to rigid bodies only");
        body.cluster_per_part = b.choice("clusters", {"one", "per_part"}) == "per_part";
        if (body.cluster_per_part && body.shape.kind != Shape::Kind::Union)
          scene_error(p + ".clusters", "per_part needs a shape that is a union of parts");
      } else {
        b.optional("clusters");
      }
      if (b.has("erosion")) {
        if (body.phase != "solid") scene_error(p + ".erosion", "applies to solid bodies only");
        const std::string e = b.choice("erosion", {"none", "failed", "failed_surface"});
        body.erosion = e == "none" ? 0 : e == "failed" ? 1 : 2;
      } else {
        b.optional("erosion");
      }
      b.finish();
      // The body must lie inside the domain.
      Point lo, hi;
      body.shape.bounds(lo, hi);
      for (int a = 0; a < dim; ++a)
        if (lo[a] < s.domain_min[a] - 1e-12 || hi[a] > s.domain_max[a] + 1e-12)
          scene_error(p + ".shape", "extends outside the domain along " + std::string(1, "xyz"[a]) +
                                        " ([" + std::to_string(lo[a]) + ", " +
                                        std::to_string(hi[a]) + "] is not within [" +
                                        std::to_string(s.domain_min[a]) + ", " +
                                        std::to_string(s.domain_max[a]) + "])");
      s.bodies.push_back(std::move(body));
    }
    // Bodies of one continuum share one stress divergence (their pairs use both particles' terms).
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (s.bodies[i].phase == "solid" && s.bodies[j].phase == "solid" &&
            s.bodies[i].continuum == s.bodies[j].continuum &&
            s.bodies[i].corrected_divergence != s.bodies[j].corrected_divergence)
          scene_error(
              "bodies[" + std::to_string(i) + "] (" + s.bodies[i].name + ").stress_divergence",
              "differs from body '" + s.bodies[j].name + "' of the same continuum '" +
                  s.bodies[i].continuum + "'");
    // Total-Lagrangian bodies: own continuum, no periodic axes; neo-Hookean materials only there.
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
      const auto& bi = s.bodies[i];
      const std::string pi = "bodies[" + std::to_string(i) + "] (" + bi.name + ")";
      if (bi.phase == "solid" && !bi.total_lagrangian && s.materials[bi.material].neo_hookean)
        scene_error(pi + ".material",
                    "elasticity: neo_hookean needs formulation: total_lagrangian");
      if (!bi.total_lagrangian) continue;
      for (std::size_t a = 0; a < s.periodic.size(); ++a)
        if (s.periodic[a])
          scene_error(pi + ".formulation", "total_lagrangian does not support periodic axes");
      for (std::size_t j = 0; j < s.bodies.size(); ++j)
        if (j != i && s.bodies[j].phase == "solid" && s.bodies[j].continuum == bi.continuum)
          scene_error(pi + ".continuum", "a total_lagrangian body cannot share its continuum ('" +
                                             bi.continuum + "')");
    }
    // A fluid or wall body needs the fluid module.
    for (const auto& body : s.bodies)
      if ((body.phase == "fluid" || body.phase == "wall") &&
          std::find(s.modules.begin(), s.modules.end(), "fluid") == s.modules.end())
        s.modules.push_back("fluid");
    // Rigid bodies are clusters, in contact with the other bodies (Cleary-type contact).
    for (const char* m : {"clusters", "contact"})
      for (const auto& body : s.bodies)
        if (body.phase == "rigid" &&
            std::find(s.modules.begin(), s.modules.end(), m) == s.modules.end())
          s.modules.push_back(m);
    // A solid body needs the solid module: switch it on.
    for (const auto& body : s.bodies)
      if (body.phase == "solid" &&
          std::find(s.modules.begin(), s.modules.end(), "solid") == s.modules.end())
        s.modules.push_back("solid");
  }

  if (r.has("boundary_conditions")) {
    auto bcs = r.node("boundary_conditions");
    if (!bcs.IsSequence()) scene_error("boundary_conditions", "expected a list");
    for (std::size_t i = 0; i < bcs.size(); ++i) {
      std::string p = "boundary_conditions[" + std::to_string(i) + "]";
      MapReader b(bcs[i], p);
      BoundarySpec bc;
      bc.type = b.choice("type", {"fixed", "velocity"});
      bc.name = b.text("name", "bc" + std::to_string(i));
      if (int(b.has("body")) + int(b.has("region")) + int(b.has("point")) != 1)
        scene_error(p, "give exactly one of 'body', 'region' or 'point'");
      if (b.has("point")) {
        bc.point = b.vector("point", dim);
        b.optional("body");
        b.optional("region");
      } else if (b.has("body")) {
        bc.body = b.text("body");
        bool found = false;
        for (const auto& body : s.bodies) found = found || body.name == bc.body;
        if (!found) scene_error(p + ".body", "no body named '" + bc.body + "'");
        b.optional("region");
        b.optional("point");
      } else {
        bc.region = read_shape(b.node("region"), p + ".region", dim);
        b.optional("body");
        b.optional("point");
      }
      if (bc.type == "velocity") {  // "free": that component is not prescribed
        auto n = b.node("velocity");
        if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
          scene_error(b.at("velocity"),
                      "expected a list of " + std::to_string(dim) + " expressions or 'free'");
        for (int a = 0; a < dim; ++a) {
          std::string q = b.at("velocity") + "[" + std::to_string(a) + "]";
          bc.velocity_expr.push_back(as_text(n[a], q));
          if (bc.velocity_expr.back() != "free")
            check_expression(bc.velocity_expr.back(), q, s.variables);
        }
        if (std::all_of(bc.velocity_expr.begin(), bc.velocity_expr.end(),
                        [](const std::string& e) { return e == "free"; }))
          scene_error(b.at("velocity"), "prescribes no component (use at least one expression)");
      }
      b.finish();
      s.boundaries.push_back(std::move(bc));
    }
  } else {
    r.optional("boundary_conditions");
  }

  if (r.has("surfaces")) {  // rigid surfaces: switch the rigid module on
    auto list = r.node("surfaces");
    if (!list.IsSequence() || list.size() == 0) scene_error("surfaces", "expected a list");
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::is_regular_file(origin, ec)
                                             ? std::filesystem::path(origin).parent_path()
                                             : std::filesystem::path();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string p = "surfaces[" + std::to_string(i) + "]";
      s.surfaces.push_back(read_surface(list[i], p, dim, folder, s.variables));
      for (std::size_t j = 0; j < i; ++j)
        if (s.surfaces[j].name == s.surfaces[i].name)
          scene_error(p + " (" + s.surfaces[i].name + ").name", "duplicate surface name");
    }
    YAML::Emitter out;  // STL paths were made absolute
    out << root;
    s.yaml = out.c_str();
    if (std::find(s.modules.begin(), s.modules.end(), "rigid") == s.modules.end())
      s.modules.push_back("rigid");
  } else {
    r.optional("surfaces");
  }

  if (r.has("contact")) {  // rigid-cluster contact (equations.md Sect. 6)
    MapReader c(r.node("contact"), "contact");
    s.contact.law = c.choice("law", {"hertz", "lennard_jones"}, "hertz");
    s.contact.distance = c.positive("distance", 1.0);
    s.contact.damping = c.non_negative("damping", 0.0);
    s.contact.friction = c.non_negative("friction", 0.0);
    if (s.contact.law == "lennard_jones") {
      s.contact.strength = c.positive("strength");
      s.contact.p1 = c.positive("p1", 12.0);
      s.contact.p2 = c.positive("p2", 4.0);
      if (!(s.contact.p1 > s.contact.p2)) scene_error("contact.p1", "must exceed contact.p2");
    } else {
      for (const char* k : {"strength", "p1", "p2"})
        if (c.has(k)) scene_error(std::string("contact.") + k, "applies to law lennard_jones only");
    }
    c.finish();
  } else {
    r.optional("contact");
  }
  read_lubrication(r, s);

  s.body_force = r.has("body_force") ? r.vector("body_force", dim)
                                     : (r.optional("body_force"), Point(dim, 0.0));
  s.end_time = r.positive("end_time");
  s.reference_end_time = written_end > 0 ? written_end : s.end_time;

  if (r.has("time_step")) {
    MapReader t(r.node("time_step"), "time_step");
    s.cfl = t.positive("cfl", 0.3);
    if (s.cfl > 1.0) scene_error("time_step.cfl", "must not exceed 1");
    s.force_factor = t.positive("force_factor", 0.25);
    s.max_dt = t.non_negative("max", 0.0);
    s.dt_collapse = t.positive("collapse_ratio", 1e-4);
    s.newmark_gamma = t.number("newmark_gamma", 0.5);
    if (t.has("dual_criteria")) {
      MapReader dc(t.node("dual_criteria"), "time_step.dual_criteria");
      // Zhang et al. 2024, Eq. 21; 0 switches dual-criteria stepping off (a study can vary it).
      s.advection_cfl = dc.non_negative("advection_cfl", 0.2);
      s.acoustic_cfl = dc.positive("acoustic_cfl", 0.4);  // Eq. 22
      s.frozen_kernel = dc.choice("kernel", {"refreshed", "frozen"}, "refreshed") == "frozen";
      if (s.advection_cfl > 1.0) scene_error(dc.at("advection_cfl"), "must not exceed 1");
      if (s.acoustic_cfl > 1.0) scene_error(dc.at("acoustic_cfl"), "must not exceed 1");
      dc.finish();
    } else {
      t.optional("dual_criteria");
    }
    if (s.newmark_gamma < 0.5 || s.newmark_gamma > 1.0)
      scene_error("time_step.newmark_gamma", "must lie in [0.5, 1] (0.5: velocity Verlet)");
    t.finish();
  } else {
    r.optional("time_step");
  }

  if (r.has("guards")) {
    MapReader g(r.node("guards"), "guards");
    s.max_mach = g.positive("max_mach", 0.5);
    s.min_distance = g.non_negative("min_distance", 0.1);
    g.finish();
  } else {
    r.optional("guards");
  }

  if (r.has("output")) {
    MapReader o(r.node("output"), "output");
    s.output_every = o.non_negative("every", 0.0);
    s.checkpoint_every = o.non_negative("checkpoint_every", 0.0);
    if (o.has("fields"))
      s.output_fields = o.strings("fields");
    else
      o.optional("fields");
    o.finish();
  } else {
    r.optional("output");
  }

  if (r.has("probes")) {
    MapReader pr(r.node("probes"), "probes");
    read_probes(pr, s);  // scene_probes.cpp
    pr.finish();
  } else {
    r.optional("probes");
  }

  if (r.has("reference")) {
    auto refs = r.node("reference");
    if (!refs.IsSequence()) scene_error("reference", "expected a list");
    for (std::size_t i = 0; i < refs.size(); ++i) {
      std::string p = "reference[" + std::to_string(i) + "]";
      MapReader q(refs[i], p);
      ReferenceSpec rs;
      rs.name = q.text("name");
      // No value: a measured figure without reference (a study's value, e.g. removed mass).
      rs.value = q.number("value", std::numeric_limits<double>::quiet_NaN());
      rs.probe = q.text("probe");
      rs.measure = q.choice("measure", {"frequency", "angular_frequency", "period", "final", "max",
                                        "min", "mean", "peak_ratio"});
      rs.start = q.non_negative("start", 0.0);
      if (q.has("needs_time")) rs.needs = q.non_negative("needs_time", 0.0);
      if (!names_probe_column(s.probes, rs.probe))
        scene_error(p + ".probe", "no probe named '" + rs.probe + "'");
      q.finish();
      s.references.push_back(std::move(rs));
    }
  } else {
    r.optional("reference");
  }
  if (r.has("checks")) {
    auto list = r.node("checks");
    if (!list.IsSequence()) scene_error("checks", "expected a list");
    for (std::size_t i = 0; i < list.size(); ++i) {
      std::string p = "checks[" + std::to_string(i) + "]";
      MapReader q(list[i], p);
      CheckSpec c;
      c.name = q.text("name");
      c.probe = q.text("probe");
      c.measure = q.choice("measure", {"final", "max", "min", "mean", "drift", "growth", "trend",
                                       "period", "frequency", "angular_frequency", "peak_ratio"});
      if (q.has("min")) c.min = q.number("min");
      if (q.has("max")) c.max = q.number("max");
      if (!q.has("min") && !q.has("max")) scene_error(p, "give min, max or both");
      c.start = q.non_negative("start", 0.0);
      if (!names_probe_column(s.probes, c.probe))
        scene_error(p + ".probe", "no probe named '" + c.probe + "'");
      q.finish();
      s.checks.push_back(std::move(c));
    }
  } else {
    r.optional("checks");
  }
  r.finish();
  return s;
}

Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  return load_scene_text(ss.str(), overrides, path);
}

}  // namespace monosph
