// The scene sections `bodies` (shape, material, initial state, per-body schemes) and
// `boundary_conditions`.
#include <fmt/format.h>

#include <cmath>

#include "scene/scene_parts.hpp"

namespace monosph {

namespace {

void check_expression(const std::string& text, const std::string& path, const Constants& vars,
                      const std::string& variables = "xyzt") {
  Expression e(text, path, vars, variables);
}

// Built-in initial velocity profiles, written out as expressions.
// cantilever_mode: fundamental bending mode of a clamped-free beam (MMB Eq. 35-36),
//   v = v_l f(x)/f(l), f(x) = (cos kl + cosh kl)(cosh kx - cos kx) + (sin kl - sinh kl)(sinh kx -
//   sin kx), zero for x < clamp.
// clamped_clamped_mode: first mode of a beam clamped at both ends (Blevins, Formulas for Natural
//   Frequency and Mode Shape, 1979, Table 8-1: cos kl cosh kl = 1, kl = 4.7300, s = 0.982502),
//   v = v_l f(x)/f(l/2),
//   f(x) = (cosh kx - cos kx) - s (sinh kx - sin kx), s = (cosh kl - cos kl)/(sinh kl - sin kl),
//   zero outside [clamp, clamp + length].
std::vector<std::string> velocity_profile(MapReader& in, int dim) {
  MapReader pr(in.node("velocity_profile"), in.at("velocity_profile"), in.constants());
  const std::string type = pr.choice("type", {"cantilever_mode", "clamped_clamped_mode"});
  const bool cc = type == "clamped_clamped_mode";
  const double vl = pr.number("amplitude");
  const double x0 = pr.number("clamp");
  const double len = pr.positive("length");
  const double kl = pr.positive("kl", cc ? 4.730040745 : 1.875);
  const std::string axis = pr.choice("direction", {"x", "y", "z"}, "y");
  const std::string along = pr.choice("along", {"x", "y", "z"}, "x");
  pr.finish();
  const int a = axis[0] - 'x';
  if (a >= dim || along[0] - 'x' >= dim) scene_error(pr.path(), "axis not in this dimension");
  const double k = kl / len;
  // f(x) = A (cosh kx - cos kx) + B (sinh kx - sin kx)
  const double A = cc ? 1.0 : std::cos(kl) + std::cosh(kl);
  const double B = cc ? -(std::cosh(kl) - std::cos(kl)) / (std::sinh(kl) - std::sin(kl))
                      : std::sin(kl) - std::sinh(kl);
  auto f = [&](double x) {
    return A * (std::cosh(k * x) - std::cos(k * x)) + B * (std::sinh(k * x) - std::sin(k * x));
  };
  const double fref = f(cc ? 0.5 * len : len);
  const std::string sx = fmt::format("({}-({:.17g}))", along, x0);
  const std::string ks = fmt::format("{:.17g}", k);
  const std::string inside =
      cc ? fmt::format("{0}>0 && {0}<{1:.17g}", sx, len) : fmt::format("{0}>0", sx);
  std::string e = fmt::format(
      "{5} ? "
      "{1:.17g}*(({2:.17g})*(cosh({3}*{0})-cos({3}*{0}))+({4:.17g})*(sinh({3}*{0})-sin({3}*{0}))) "
      ": 0",
      sx, vl / fref, A, ks, B, inside);
  std::vector<std::string> out(dim, "0");
  out[a] = e;
  return out;
}

// name, phase, continuum, formulation, material.
void read_body_head(MapReader& b, BodySpec& body, const std::string& p, const Scene& s) {
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
    for (const char* k :
         {"artificial_viscosity", "artificial_stress", "density_diffusion", "stress_divergence"})
      if (b.has(k)) scene_error(p + "." + k, "not available with formulation: total_lagrangian");
  std::string mat = b.text("material");
  body.material = s.material_index(mat);
  if (body.material < 0) {
    std::vector<std::string> names;
    for (const auto& m : s.materials) names.push_back(m.name);
    std::string hint = closest_word(mat, names);
    scene_error(p + ".material", "no material named '" + mat + "' in materials" +
                                     (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
}

// `initial`: density and velocity expressions (or a velocity profile), temperature, spin.
void read_initial(MapReader& b, BodySpec& body, const std::string& p, const Scene& s) {
  const int dim = s.dimension;
  if (!b.has("initial")) return void(b.optional("initial"));
  MapReader in(b.node("initial"), p + ".initial", b.constants());
  body.density_expr = in.text("density", "");
  body.temperature = in.positive("temperature", 0.0 + body.temperature);
  if (!body.density_expr.empty())
    check_expression(body.density_expr, in.at("density"), s.variables, "xyz");
  if (in.has("velocity") && in.has("velocity_profile"))
    scene_error(in.path(), "give either velocity or velocity_profile, not both");
  if (in.has("velocity"))
    body.velocity_expr = expressions(in, "velocity", dim, s.variables, "xyz");
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
}

// Stabilisation of the Eulerian scheme: artificial viscosity and stress, density diffusion,
// stress divergence.
void read_stabilisation(MapReader& b, BodySpec& body, const std::string& p, const Scene& s) {
  if (b.has("artificial_viscosity")) {
    MapReader av(b.node("artificial_viscosity"), p + ".artificial_viscosity", b.constants());
    body.av_alpha = av.non_negative("alpha", 0.0);
    body.av_beta = av.non_negative("beta", 0.0);
    av.finish();
  } else {
    b.optional("artificial_viscosity");
  }
  if (b.has("artificial_stress")) {
    MapReader as(b.node("artificial_stress"), p + ".artificial_stress", b.constants());
    body.as_epsilon = as.non_negative("epsilon", 0.3);
    body.as_n = as.positive("n", 4.0);
    as.finish();
  } else {
    b.optional("artificial_stress");
  }
  if (b.has("density_diffusion")) {
    MapReader dd(b.node("density_diffusion"), p + ".density_diffusion", b.constants());
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
}

// Damping, body force, fill.
void read_other_keys(MapReader& b, BodySpec& body, const std::string& p, int dim) {
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
  const std::string fill = b.choice("fill", {"all", "rest", "shells"}, "all");
  body.fill_rest = fill == "rest";
  body.fill_shells = fill == "shells";
  if (body.fill_shells && body.shape.kind != Shape::Kind::Sphere &&
      body.shape.kind != Shape::Kind::Ring)
    scene_error(p + ".fill", "shells needs a sphere (circle in 2D) or ring shape");
}

// `rotate: {degrees, about, axis}`: the particles turned after the fill; `about` defaults to the
// centre of the shape's bounding box, `axis` (3D only) to z.
void read_rotate(MapReader& b, BodySpec& body, int dim) {
  if (!b.has("rotate")) return void(b.optional("rotate"));
  MapReader r(b.node("rotate"), b.at("rotate"), b.constants());
  BodyRotation rot;
  rot.degrees = r.number("degrees");
  if (r.has("about")) {
    rot.about = r.vector("about", dim);
  } else {
    r.optional("about");
    Point lo, hi;
    body.shape.bounds(lo, hi);
    for (int a = 0; a < dim; ++a) rot.about.push_back(0.5 * (lo[a] + hi[a]));
  }
  if (dim == 2 && r.has("axis"))
    scene_error(r.at("axis"), "applies to 3D scenes only (a 2D body turns about the point)");
  if (dim == 3 && r.has("axis")) {
    rot.axis = r.vector("axis", 3);
    const double a2 =
        rot.axis[0] * rot.axis[0] + rot.axis[1] * rot.axis[1] + rot.axis[2] * rot.axis[2];
    if (!(a2 > 0) || !std::isfinite(a2))
      scene_error(r.at("axis"), "must be a finite non-zero vector");
    for (double& c : rot.axis) c /= std::sqrt(a2);
  } else {
    r.optional("axis");
  }
  r.finish();
  body.rotate = rot;
}

BodySpec read_body(const YAML::Node& node, std::size_t i, const Scene& s) {
  const int dim = s.dimension;
  BodySpec body;
  body.name = MapReader(node, "bodies[" + std::to_string(i) + "]", nullptr).text("name");
  const std::string p = "bodies[" + std::to_string(i) + "] (" + body.name + ")";
  MapReader b(node, p, &s.variables);  // the name in the paths of the body's keys
  b.text("name");
  for (const auto& other : s.bodies)
    if (other.name == body.name) scene_error(p + ".name", "duplicate body name");
  read_body_head(b, body, p, s);
  body.shape = read_shape(b.node("shape"), p + ".shape", dim, b.constants());
  body.jitter = b.non_negative("jitter", 0.0);
  if (body.jitter >= 0.5) scene_error(p + ".jitter", "must be below 0.5 (fraction of dp)");
  const int seed = b.integer("seed", 1);
  if (seed < 0) scene_error(p + ".seed", "must not be negative, got " + std::to_string(seed));
  body.seed = static_cast<unsigned>(seed);
  read_initial(b, body, p, s);
  read_stabilisation(b, body, p, s);
  read_other_keys(b, body, p, dim);
  read_rotate(b, body, dim);
  for (const auto& m : registered_module_keys())
    if (m.read_body)
      if (auto params = m.read_body(b, body, p, s)) body.params[m.module] = std::move(params);
  b.finish();
  // The body must lie inside the domain.
  Point lo, hi;
  body.shape.bounds(lo, hi);
  for (int a = 0; a < dim; ++a)
    if (lo[a] < s.domain_min[a] - 1e-12 || hi[a] > s.domain_max[a] + 1e-12)
      scene_error(p + ".shape", "extends outside the domain along " + std::string(1, "xyz"[a]) +
                                    " ([" + std::to_string(lo[a]) + ", " + std::to_string(hi[a]) +
                                    "] is not within [" + std::to_string(s.domain_min[a]) + ", " +
                                    std::to_string(s.domain_max[a]) + "])");
  return body;
}

// Bodies of one continuum share one stress divergence (their pairs use both particles' terms);
// total-Lagrangian bodies have their own continuum and no periodic axes.
void check_continua(const Scene& s) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (s.bodies[i].phase == "solid" && s.bodies[j].phase == "solid" &&
          s.bodies[i].continuum == s.bodies[j].continuum &&
          s.bodies[i].corrected_divergence != s.bodies[j].corrected_divergence)
        scene_error(
            "bodies[" + std::to_string(i) + "] (" + s.bodies[i].name + ").stress_divergence",
            "differs from body '" + s.bodies[j].name + "' of the same continuum '" +
                s.bodies[i].continuum + "'");
  // Total-Lagrangian bodies: own continuum, no periodic axes.
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const auto& bi = s.bodies[i];
    const std::string pi = "bodies[" + std::to_string(i) + "] (" + bi.name + ")";
    if (s.has_mirror() && bi.phase == "rigid")
      scene_error(pi + ".phase", "rigid bodies do not support domain.mirror");
    if (bi.total_lagrangian)
      for (std::size_t a = 0; a < s.mirror_min.size(); ++a)
        if (s.mirror_min[a] && s.mirror_max[a])
          scene_error("domain.mirror", "total_lagrangian bodies take one plane per axis");
    if (!bi.total_lagrangian) continue;
    for (std::size_t a = 0; a < s.periodic.size(); ++a)
      if (s.periodic[a])
        scene_error(pi + ".formulation", "total_lagrangian does not support periodic axes");
    for (std::size_t j = 0; j < s.bodies.size(); ++j)
      if (j != i && s.bodies[j].phase == "solid" && s.bodies[j].continuum == bi.continuum)
        scene_error(pi + ".continuum",
                    "a total_lagrangian body cannot share its continuum ('" + bi.continuum + "')");
  }
  // A fluid or wall body needs the fluid module.
}

// The modules the bodies need: fluid (fluid, wall), clusters and contact (rigid), solid.
void switch_modules_on(Scene& s) {
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

}  // namespace

std::vector<std::string> expressions(MapReader& r, const std::string& key, int dim,
                                     const Constants& vars, const std::string& variables) {
  auto n = r.node(key);
  if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
    scene_error(r.at(key), "expected a list of " + std::to_string(dim) + " expressions");
  std::vector<std::string> out;
  for (int a = 0; a < dim; ++a) {
    std::string p = r.at(key) + "[" + std::to_string(a) + "]";
    out.push_back(as_text(n[a], p));
    check_expression(out.back(), p, vars, variables);
  }
  return out;
}

void read_bodies(MapReader& r, Scene& s) {
  auto bodies = r.node("bodies");
  if (!bodies.IsSequence() || bodies.size() == 0)
    scene_error("bodies", "expected a list of bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) s.bodies.push_back(read_body(bodies[i], i, s));
  check_continua(s);
  switch_modules_on(s);
}

void read_boundaries(MapReader& r, Scene& s) {
  const int dim = s.dimension;
  if (!r.has("boundary_conditions")) return void(r.optional("boundary_conditions"));
  auto bcs = r.node("boundary_conditions");
  if (!bcs.IsSequence()) scene_error("boundary_conditions", "expected a list");
  for (std::size_t i = 0; i < bcs.size(); ++i) {
    std::string p = "boundary_conditions[" + std::to_string(i) + "]";
    MapReader b(bcs[i], p, r.constants());
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
      bc.region = read_shape(b.node("region"), p + ".region", dim, b.constants());
      b.optional("body");
      b.optional("point");
    }
    if (bc.type == "velocity") {  // "free": that component is
                                  // not prescribed
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
        scene_error(b.at("velocity"),
                    "prescribes no component (use at least "
                    "one expression)");
    }
    b.finish();
    s.boundaries.push_back(std::move(bc));
  }
}

}  // namespace monosph
