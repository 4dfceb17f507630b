// The scene sections `time_step`, `guards`, `output`, `reference`, `checks` and `limits`.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "scene/scene_parts.hpp"
#include "scene/scene_probes.hpp"

namespace monosph {

namespace {
// A value in [lo, hi]: smaller CFL numbers give steps so small the run never ends.
void check_range(double v, double lo, double hi, const std::string& path,
                 const std::string& what = "") {
  if (!(v >= lo && v <= hi))
    scene_error(path, fmt::format("must lie in [{:g}, {:g}]{}, got {:g}", lo, hi, what, v));
}
}  // namespace

void read_time_step(MapReader& r, Scene& s) {
  if (!r.has("time_step")) return void(r.optional("time_step"));
  MapReader t(r.node("time_step"), "time_step", r.constants());
  s.cfl = t.positive("cfl", 0.3);
  check_range(s.cfl, 1e-3, 1, "time_step.cfl");
  s.force_factor = t.positive("force_factor", 0.25);
  check_range(s.force_factor, 1e-3, 1, "time_step.force_factor");
  s.max_dt = t.non_negative("max", 0.0);
  s.dt_collapse = t.positive("collapse_ratio", 1e-4);
  if (s.dt_collapse >= 1)
    scene_error("time_step.collapse_ratio",
                fmt::format("must lie in (0, 1), got {:g}", s.dt_collapse));
  s.newmark_gamma = t.number("newmark_gamma", 0.5);
  s.multi_rate = t.boolean("multi_rate", false);
  const double ms = t.positive("max_substeps", 32);
  if (ms != std::floor(ms) || ms > 1000)
    scene_error("time_step.max_substeps",
                fmt::format("must be a whole number in [1, 1000], got {:g}", ms));
  s.max_substeps = static_cast<int>(ms);
  if (t.has("dual_criteria")) {
    MapReader dc(t.node("dual_criteria"), "time_step.dual_criteria", t.constants());
    // Zhang et al. 2024, Eq. 21; 0 switches dual-criteria stepping off (a study can vary it).
    s.advection_cfl = dc.non_negative("advection_cfl", 0.2);
    s.acoustic_cfl = dc.positive("acoustic_cfl", 0.4);  // Eq. 22
    s.frozen_kernel = dc.choice("kernel", {"refreshed", "frozen"}, "refreshed") == "frozen";
    if (s.advection_cfl != 0 && !(s.advection_cfl >= 1e-3 && s.advection_cfl <= 1))
      scene_error(dc.at("advection_cfl"),
                  fmt::format("must be 0 (off) or lie in [0.001, 1], got {:g}", s.advection_cfl));
    check_range(s.acoustic_cfl, 1e-3, 1, dc.at("acoustic_cfl"));
    dc.finish();
  } else {
    t.optional("dual_criteria");
  }
  if (s.newmark_gamma < 0.5 || s.newmark_gamma > 1.0)
    scene_error("time_step.newmark_gamma", "must lie in [0.5, 1] (0.5: velocity Verlet)");
  if (s.multi_rate && s.newmark_gamma != 0.5)
    scene_error("time_step.multi_rate", "works with newmark_gamma 0.5 (velocity Verlet) only");
  if (s.multi_rate && s.advection_cfl > 0)
    scene_error("time_step.multi_rate", "cannot be combined with dual_criteria");
  t.finish();
}

void read_guards(MapReader& r, Scene& s) {
  if (!r.has("guards")) return void(r.optional("guards"));
  MapReader g(r.node("guards"), "guards", r.constants());
  s.max_mach = g.positive("max_mach", 0.5);
  s.min_distance = g.non_negative("min_distance", 0.1);
  if (s.min_distance >= 1)
    scene_error("guards.min_distance",
                fmt::format("must lie in [0, 1) (a fraction of dp), got {:g}", s.min_distance));
  g.finish();
}

void read_output(MapReader& r, Scene& s) {
  if (!r.has("output")) return void(r.optional("output"));
  MapReader o(r.node("output"), "output", r.constants());
  s.output_every = o.non_negative("every", 0.0);
  s.checkpoint_every = o.non_negative("checkpoint_every", 0.0);
  if (o.has("fields"))
    s.output_fields = o.strings("fields");
  else
    o.optional("fields");
  o.finish();
}

void read_references(MapReader& r, Scene& s) {
  if (!r.has("reference")) return void(r.optional("reference"));
  auto refs = r.node("reference");
  if (!refs.IsSequence()) scene_error("reference", "expected a list");
  for (std::size_t i = 0; i < refs.size(); ++i) {
    std::string p = "reference[" + std::to_string(i) + "]";
    MapReader q(refs[i], p, r.constants());
    ReferenceSpec rs;
    rs.name = q.text("name");
    for (const auto& other : s.references)
      if (other.name == rs.name)
        scene_error(p + " (" + rs.name + ").name", "duplicate reference name");
    // No value: a measured figure without reference (a study's value, e.g. removed mass).
    rs.value = q.number("value", std::numeric_limits<double>::quiet_NaN());
    rs.probe = q.text("probe");
    rs.measure = q.choice("measure", {"frequency", "angular_frequency", "period", "final", "max",
                                      "min", "mean", "harmonic_mean", "std", "peak_ratio"});
    rs.start = q.non_negative("start", 0.0);
    if (q.has("needs_time")) rs.needs = q.non_negative("needs_time", 0.0);
    if (!names_probe_column(s.probes, rs.probe))
      scene_error(p + ".probe", "no probe named '" + rs.probe + "'");
    q.finish();
    s.references.push_back(std::move(rs));
  }
}

void read_checks(MapReader& r, Scene& s) {
  if (!r.has("checks")) return void(r.optional("checks"));
  auto list = r.node("checks");
  if (!list.IsSequence()) scene_error("checks", "expected a list");
  for (std::size_t i = 0; i < list.size(); ++i) {
    std::string p = "checks[" + std::to_string(i) + "]";
    MapReader q(list[i], p, r.constants());
    CheckSpec c;
    c.name = q.text("name");
    for (const auto& other : s.checks)
      if (other.name == c.name) scene_error(p + " (" + c.name + ").name", "duplicate check name");
    c.probe = q.text("probe");
    c.measure = q.choice("measure",
                         {"final", "max", "min", "mean", "harmonic_mean", "std", "drift", "growth",
                          "trend", "period", "frequency", "angular_frequency", "peak_ratio"});
    if (q.has("min")) c.min = q.number("min");
    if (q.has("max")) c.max = q.number("max");
    if (!q.has("min") && !q.has("max")) scene_error(p, "give min, max or both");
    if (c.min > c.max) scene_error(p + ".min", "must not exceed max");
    c.start = q.non_negative("start", 0.0);
    if (!names_probe_column(s.probes, c.probe))
      scene_error(p + ".probe", "no probe named '" + c.probe + "'");
    q.finish();
    s.checks.push_back(std::move(c));
  }
}

// The size guard's limits (scene_checks.cpp): particles and bytes.
void read_limits(MapReader& r, Scene& s) {
  if (!r.has("limits")) return void(r.optional("limits"));
  MapReader l(r.node("limits"), "limits", r.constants());
  s.max_particles = l.positive("max_particles", 0.0);
  s.max_memory = l.positive("max_memory", 0.0);
  l.finish();
}

}  // namespace monosph
