// The scene section `surfaces` (rigid surfaces, MMB Sect. 3).
#include <cmath>

#include "core/input_file.hpp"
#include "scene/scene_parts.hpp"

namespace monosph {

namespace {

// A rigid surface (MMB Sect. 3; built by src/rigid): one geometry key, motion, contact parameters.
// `folder` resolves a relative STL path (the scene file's folder; empty: the working directory).
SurfaceSpec read_surface(YAML::Node node, const std::string& index_path, int dim,
                         const std::filesystem::path& folder, const Constants& vars) {
  MapReader r(node, index_path, &vars);
  SurfaceSpec s;
  s.name = r.text("name");
  const std::string p = index_path + " (" + s.name + ")";
  MapReader q(node, p, &vars);  // the same map, with the name in the paths of its keys
  q.text("name");
  s.friction = q.non_negative("friction", 0.0);
  s.damping = q.non_negative("damping", 0.0);
  s.friction_limit = q.non_negative("friction_limit", 0.0);  // tau_max, Pa; 0: Coulomb only
  if (q.has("friction_limit") && !(s.friction > 0))
    scene_error(q.at("friction_limit"), "needs a friction coefficient (key friction > 0)");
  // beta: the share of the friction work that heats the surface (lost to the scene); the rest
  // heats the particle. 1 (the default): friction heats nothing.
  s.heat_partition = q.non_negative("heat_partition", 1.0);
  if (s.heat_partition > 1) scene_error(q.at("heat_partition"), "must lie in [0, 1]");
  // A heat sink: q = h_c (T_surface - T) through each touching particle's area dp^(D-1).
  s.heat_transfer = q.non_negative("heat_transfer", 0.0);
  s.temperature = q.positive("temperature", 293.15);
  if (q.has("temperature") && !(s.heat_transfer > 0))
    scene_error(q.at("temperature"), "needs heat_transfer > 0 (W/(m^2 K))");
  s.stiffness = q.positive("stiffness", 0.0);
  s.poisson_ratio = q.non_negative("poisson_ratio", 0.3);
  if (s.poisson_ratio >= 0.5) scene_error(q.at("poisson_ratio"), "must be below 0.5");
  if (q.has("poisson_ratio") && !q.has("stiffness"))
    scene_error(q.at("poisson_ratio"), "needs a stiffness (a rigid surface has no Poisson ratio)");
  s.scale = q.positive("scale", 1.0);
  s.translate =
      q.has("translate") ? q.vector("translate", dim) : (q.optional("translate"), Point(dim, 0.0));
  if (q.has("velocity"))
    s.velocity_expr = expressions(q, "velocity", dim, vars, "t");
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
      s.points.push_back(as_vector(v[i], g + "[" + std::to_string(i) + "]", dim, &vars));
  };
  auto distinct = [&](std::size_t i, std::size_t j) {
    double d2 = 0;
    for (int a = 0; a < dim; ++a) d2 += std::pow(s.points[i][a] - s.points[j][a], 2);
    if (!(d2 > 0))
      scene_error(g, "points " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
  };
  if (s.kind == "box") {
    MapReader b(q.node("box"), g, &vars);
    s.points = {b.vector("min", dim), b.vector("max", dim)};
    b.finish();
    for (int a = 0; a < dim; ++a)
      if (!(s.points[1][a] > s.points[0][a]))
        scene_error(g + ".max", "must be greater than min in every axis");
  } else if (s.kind == "plane") {
    MapReader b(q.node("plane"), g, &vars);
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
        s.points.push_back(as_vector(v[i][c], ti + "[" + std::to_string(c) + "]", 3, &vars));
    }
  } else {  // stl
    std::filesystem::path f = q.text("stl");
    if (f.is_relative()) f = folder / f;
    std::error_code ec;
    f = std::filesystem::absolute(f, ec).lexically_normal();
    check_input_file(f.string(), g + ": cannot read STL file '" + f.string() + "'", kMaxStlBytes);
    s.file = f.string();
    node["stl"] = s.file;  // absolute in the stored scene text, so that a restart finds it
  }
  q.finish();
  return s;
}

}  // namespace

void read_surfaces(MapReader& r, Scene& s, YAML::Node& root, const std::string& origin) {
  if (!r.has("surfaces")) return void(r.optional("surfaces"));
  auto list = r.node("surfaces");
  if (!list.IsSequence() || list.size() == 0) scene_error("surfaces", "expected a list");
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::is_regular_file(origin, ec)
                                           ? std::filesystem::path(origin).parent_path()
                                           : std::filesystem::path();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = "surfaces[" + std::to_string(i) + "]";
    s.surfaces.push_back(read_surface(list[i], p, s.dimension, folder, s.variables));
    for (std::size_t j = 0; j < i; ++j)
      if (s.surfaces[j].name == s.surfaces[i].name)
        scene_error(p + " (" + s.surfaces[i].name + ").name", "duplicate surface name");
  }
  YAML::Emitter out;  // STL paths were made absolute
  out << root;
  s.yaml = out.c_str();
  if (std::find(s.modules.begin(), s.modules.end(), "rigid") == s.modules.end())
    s.modules.push_back("rigid");
}

}  // namespace monosph
