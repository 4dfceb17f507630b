#include "study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/types.hpp"
#include "parallel/threads.hpp"
#include "processes.hpp"
#include "scene/scene.hpp"
#include "solid/solid_keys.hpp"
#include "study_stats.hpp"

namespace monosph {
namespace fs = std::filesystem;

namespace {

struct Axis {
  std::string key;
  std::vector<std::string> values;
};

Axis parse_vary(const std::string& s) {
  const auto eq = s.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
    throw InputError("--vary " + s + ": expected key=v1,v2,... e.g. --vary dp=0.01,0.005");
  Axis a{s.substr(0, eq), {}};
  std::stringstream ss(s.substr(eq + 1));
  for (std::string v; std::getline(ss, v, ',');) {
    if (v.empty()) throw InputError("--vary " + s + ": empty value");
    a.values.push_back(v);
  }
  if (a.key == "stabilisation")
    for (const auto& v : a.values)
      if (v != "none" && v != "artificial_stress" && v != "hourglass")
        throw InputError("--vary stabilisation: '" + v +
                         "' is not one of none, artificial_stress, hourglass");
  return a;
}

struct Run {
  std::vector<std::string> values;  // one per axis
  std::vector<std::string> sets;    // overrides of this run
  fs::path dir;
  int code = -1;
  std::string output;  // first line of the run's messages when it failed
  nlohmann::json summary;
};

}  // namespace

std::vector<std::string> stabilisation_overrides(const std::string& scene_file,
                                                 const std::vector<std::string>& base,
                                                 const std::string& variant) {
  const Scene s = load_scene_file(scene_file, base);
  std::vector<std::string> sets;
  bool any = false;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    if (b.phase != "solid") continue;
    any = true;
    const std::string p = fmt::format("bodies.{}.", i);
    if (variant == "none") {
      sets.push_back(p + "hourglass={xi: 0}");
      sets.push_back(p + "artificial_stress={epsilon: 0}");
    } else if (variant == "artificial_stress") {
      // Monaghan's artificial stress (MMB Eq. 19-20) with the usual epsilon = 0.3, n = 4.
      sets.push_back(p + "hourglass={xi: 0}");
      sets.push_back(p + "artificial_stress={epsilon: 0.3, n: 4}");
    } else {
      // The scene's own hourglass control, or stiffness-based xi = 0.5 (MMB Table 2).
      if (!(module_params<SolidBodyKeys>(b.params).hg_xi > 0))
        sets.push_back(p + "hourglass={xi: 0.5}");
      sets.push_back(p + "artificial_stress={epsilon: 0}");
    }
  }
  if (!any) throw InputError("--vary stabilisation: scene " + scene_file + " has no solid body");
  return sets;
}

namespace {

// The index of the --against key among the varied keys (-1 without --against); its values must
// be numbers.
int against_axis(const std::string& key, const std::vector<Axis>& axes) {
  if (key.empty()) return -1;
  int against = -1;
  for (std::size_t a = 0; a < axes.size(); ++a)
    if (axes[a].key == key) against = static_cast<int>(a);
  if (against < 0) throw InputError("study: --against " + key + " is not one of the --vary keys");
  for (const auto& v : axes[against].values) {
    std::size_t used = 0;
    try {
      std::stod(v, &used);
    } catch (const std::exception&) {
    }
    if (used != v.size() || v.empty())
      throw InputError("study: --against " + key + ": value '" + v + "' is not a number");
  }
  return against;
}

// The index of the --repeat key among the varied keys (-1 without --repeat).
int repeat_axis(const std::string& key, const std::vector<Axis>& axes) {
  if (key.empty()) return -1;
  for (std::size_t a = 0; a < axes.size(); ++a)
    if (axes[a].key == key) return static_cast<int>(a);
  throw InputError("study: --repeat " + key +
                   " is not one of the --vary keys (e.g. --vary variables.seed=1,2,3 --repeat "
                   "variables.seed)");
}

// study_stats.csv and study.md's statistics section: each metric over the runs that differ only
// in the --repeat key (study_stats.hpp).
void write_repeat_stats(const fs::path& out, const std::vector<Axis>& axes, std::size_t repeat,
                        const std::vector<Run>& runs, const std::vector<std::string>& metrics) {
  std::vector<StudyRunValues> values;
  for (const auto& r : runs) {
    const auto& s = r.summary;
    StudyRunValues v{
        r.values, s.is_object() && s.value("status", std::string()) == "completed", {}};
    for (const auto& m : metrics) {
      const bool has =
          v.completed && s["metrics"].contains(m) && s["metrics"][m]["value"].is_number();
      v.metrics.push_back(has ? std::optional<double>(s["metrics"][m]["value"].get<double>())
                              : std::nullopt);
    }
    values.push_back(std::move(v));
  }
  std::vector<std::string> keys;
  for (const auto& a : axes) keys.push_back(a.key);
  const auto rows = study_stats(values, repeat, metrics.size());
  write_study_stats_csv(out / "study_stats.csv", keys, repeat, metrics, rows);
  std::ofstream md(out / "study.md", std::ios::app);
  write_study_stats_md(md, keys, repeat, metrics, rows);
  fmt::print("study: statistics over {}: {}\n", keys[repeat], (out / "study_stats.csv").string());
}

// study.csv: one row per run.
void write_study_csv(const fs::path& out, const std::vector<Axis>& axes,
                     const std::vector<Run>& runs, const std::vector<std::string>& metrics) {
  std::ofstream csv(out / "study.csv");
  for (const auto& a : axes) csv << csv_escape(a.key) << ",";
  csv << "particles,steps,wall_seconds,particle_steps_per_second,status";
  for (const auto& m : metrics) csv << "," << m << "_value," << m << "_relative_error";
  csv << "\n";
  for (const auto& r : runs) {
    for (const auto& v : r.values) csv << csv_escape(v) << ",";
    const auto& s = r.summary;
    const bool ok = s.is_object();
    csv << (ok ? s.value("particles", 0L) : 0) << "," << (ok ? s.value("steps", 0L) : 0) << ","
        << fmt::format("{:.6g}", ok ? s.value("wall_seconds", 0.0) : NAN) << ","
        << fmt::format("{:.6g}", ok ? s.value("particle_steps_per_second", 0.0) : NAN) << ","
        << csv_escape(ok ? s.value("status", std::string("?")) : r.output);
    for (const auto& m : metrics) {
      const bool has = ok && s["metrics"].contains(m);
      auto num = [&](const char* f) {
        return has && !s["metrics"][m][f].is_null()
                   ? fmt::format("{:.9g}", s["metrics"][m][f].get<double>())
                   : std::string("");
      };
      csv << "," << num("value") << "," << num("relative_error");
    }
    csv << "\n";
  }
  if (!csv) throw InputError("study: cannot write " + (out / "study.csv").string());
}

// study.md: the same as a table.
void write_study_md(const fs::path& out, const std::string& name, const std::vector<Axis>& axes,
                    const std::vector<Run>& runs, const std::vector<std::string>& metrics) {
  std::ofstream md(out / "study.md");
  md << "# Study of " << name << "\n\n|";
  for (const auto& a : axes) md << " " << a.key << " |";
  md << " particles | wall [s] | particle-steps/s |";
  for (const auto& m : metrics) md << " " << m << " | error |";
  md << " status |\n|";
  for (std::size_t c = 0; c < axes.size() + 3 + 2 * metrics.size() + 1; ++c) md << "---|";
  md << "\n";
  for (const auto& r : runs) {
    md << "|";
    for (const auto& v : r.values) md << " " << v << " |";
    const auto& s = r.summary;
    const bool ok = s.is_object();
    md << " " << (ok ? s.value("particles", 0L) : 0) << " | "
       << fmt::format("{:.2f}", ok ? s.value("wall_seconds", 0.0) : NAN) << " | "
       << fmt::format("{:.3g}", ok ? s.value("particle_steps_per_second", 0.0) : NAN) << " |";
    for (const auto& m : metrics) {
      const bool has = ok && s["metrics"].contains(m) && !s["metrics"][m]["value"].is_null();
      md << (has ? fmt::format(" {:.6g} | {:.2e} |", s["metrics"][m]["value"].get<double>(),
                               s["metrics"][m]["relative_error"].is_null()
                                   ? NAN
                                   : s["metrics"][m]["relative_error"].get<double>())
                 : std::string(" – | – |"));
    }
    md << " " << (ok ? s.value("status", std::string("?")) : r.output) << " |\n";
  }
}

// study.gp: the metric (or its error) against wall time, log-log; with --against, against that key.
void write_study_gp(const fs::path& out, const std::string& name, const std::string& metric,
                    const std::string& against, bool plot_value, std::size_t ncurves) {
  std::ofstream gp(out / "study.gp");
  if (!against.empty())  // linear axes: the value against the varied key
    gp << "set terminal pngcairo size 900,600 noenhanced\nset output 'study.png'\n"
       << "set xlabel '" << against << "'\nset ylabel '" << metric << "'\n"
       << "set title '" << name << ": " << metric << " against " << against
       << "'\nset key outside\nset grid\nset yrange [0:*]\nplot for [i=0:"
       << (ncurves == 0 ? 0 : ncurves - 1)
       << "] 'study.dat' index i using 1:2 with linespoints title columnheader(1)\n";
  else
    gp << "set terminal pngcairo size 900,600 noenhanced\nset output 'study.png'\n"
       << "set logscale xy\n"
       << "set xlabel 'wall time [s]'\nset ylabel '" << (plot_value ? "" : "relative error of ")
       << metric << "'\n"
       << "set title '" << name << ": " << (plot_value ? metric : "error")
       << " against run time'\nset key outside\n"
       << "set grid\nplot for [i=0:" << (ncurves == 0 ? 0 : ncurves - 1)
       << "] 'study.dat' index i using 1:2 with linespoints title columnheader(1), \\\n"
       << "     for [i=0:" << (ncurves == 0 ? 0 : ncurves - 1)
       << "] 'study.dat' index i using 1:2:3 with labels offset 1,0.7 notitle\n";
}

}  // namespace

int run_study(const StudyOptions& opt) {
  if (opt.scene.empty()) throw InputError("study: give a scene file");
  if (opt.vary.empty()) throw InputError("study: give at least one --vary key=v1,v2,...");
  if (opt.jobs < 1) throw InputError("study: --jobs must be at least 1");
  const Scene base = load_scene_file(opt.scene, opt.overrides);  // bad scene: error now
  std::vector<Axis> axes;
  for (const auto& v : opt.vary) axes.push_back(parse_vary(v));
  // --against KEY: the metric's value against that varied key, one curve per other combination.
  const int against = against_axis(opt.against, axes);
  const int repeat = repeat_axis(opt.repeat, axes);  // --repeat KEY: statistics over its values
  const bool plot_value = opt.plot_value || against >= 0;
  std::string metric = opt.metric;
  if (metric.empty() && !base.references.empty()) metric = base.references.front().name;
  if (!metric.empty()) {
    bool found = false;
    for (const auto& r : base.references) found = found || r.name == metric;
    if (!found)
      throw InputError("study: --metric '" + metric + "' is not a reference of the scene");
  }
  const fs::path out =
      opt.out.empty() ? fs::path("out") / ("study_" + base.name) : fs::path(opt.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw InputError("study: cannot write to " + out.string() + ": " + ec.message());

  // Every combination, checked before anything runs (a typo fails now, not after an hour).
  std::vector<Run> runs;
  std::vector<std::size_t> k(axes.size(), 0);
  while (true) {
    Run r;
    r.sets = opt.overrides;
    std::string tag;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const std::string& v = axes[a].values[k[a]];
      r.values.push_back(v);
      tag += (a ? "_" : "") + axes[a].key + "-" + v;
      if (axes[a].key != "stabilisation") r.sets.push_back(axes[a].key + "=" + v);
    }
    for (std::size_t a = 0; a < axes.size(); ++a)
      if (axes[a].key == "stabilisation")
        for (auto& s : stabilisation_overrides(opt.scene, r.sets, r.values[a])) r.sets.push_back(s);
    load_scene_file(opt.scene, r.sets);
    std::replace_if(
        tag.begin(), tag.end(),
        [](char c) { return !std::isalnum(c) && c != '-' && c != '_' && c != '.'; }, '_');
    r.dir = out / fmt::format("run{:02d}_{}", runs.size(), tag);
    runs.push_back(std::move(r));
    std::size_t a = 0;
    while (a < axes.size() && ++k[a] == axes[a].values.size()) k[a] = 0, ++a;
    if (a == axes.size()) break;
  }

  const auto [njobs, threads] = jobs_and_threads("study", opt.jobs, opt.threads);
  fmt::print("study: {} runs of {}, {} at a time, {} thread{} each, in {}\n", runs.size(),
             base.name, njobs, threads, threads > 1 ? "s" : "", out.string());
  std::vector<ChildRun> jobs;
  for (auto& r : runs) {
    fs::remove_all(r.dir, ec);
    fs::create_directories(r.dir, ec);
    ChildRun c{{"run", opt.scene, "--out", r.dir.string(), "--quiet", "--threads",
                std::to_string(threads)},
               r.dir / "study.log"};
    if (opt.fixed_threads) c.args.push_back("--fixed-threads");
    for (const auto& s : r.sets) c.args.push_back("--set"), c.args.push_back(s);
    jobs.push_back(std::move(c));
  }
  std::size_t done = 0;
  run_children(jobs, njobs, [&](std::size_t k) {
    Run& r = runs[k];
    ++done;
    r.code = jobs[k].code;
    std::ifstream js(r.dir / "summary.json");
    if (js) r.summary = nlohmann::json::parse(js, nullptr, false);
    if (r.code != 0) r.output = first_message(jobs[k].log);
    std::string what;
    for (std::size_t a = 0; a < axes.size(); ++a)
      what += (a ? " " : "") + axes[a].key + "=" + r.values[a];
    std::string err = "";
    if (!metric.empty() && r.summary.is_object() && r.summary["metrics"].contains(metric) &&
        !r.summary["metrics"][metric]["relative_error"].is_null())
      err = fmt::format(", {} error {:.3e}", metric,
                        r.summary["metrics"][metric]["relative_error"].get<double>());
    fmt::print("study: [{}/{}] {}: {}{}\n", done, runs.size(), what,
               r.code == 0 ? fmt::format("{:.1f} s wall", r.summary.value("wall_seconds", 0.0))
                           : "stopped (" + r.output + ")",
               err);
    std::fflush(stdout);
  });

  // study.csv: one row per run.
  std::vector<std::string> metrics;
  for (const auto& ref : base.references) metrics.push_back(ref.name);
  write_study_csv(out, axes, runs, metrics);
  // study.md: the same as a table.
  write_study_md(out, base.name, axes, runs, metrics);
  if (repeat >= 0) write_repeat_stats(out, axes, static_cast<std::size_t>(repeat), runs, metrics);
  // study.png: error against wall time, log-log, one curve per variant of the axes after the
  // first (the first axis, usually dp, runs along each curve).
  bool all_ok = true;
  for (const auto& r : runs) all_ok = all_ok && r.code == 0;
  if (metric.empty()) {
    fmt::print("study: the scene declares no reference value: no plot (study.csv, study.md)\n");
    return all_ok ? 0 : 3;
  }
  std::map<std::string, std::vector<std::pair<double, double>>> curves;
  std::map<std::pair<std::string, double>, std::string> point_label;  // first axis at each point
  for (const auto& r : runs) {
    const auto& s = r.summary;
    // A run that stopped early reports its metrics at the stop: not a point of the curve.
    if (!s.is_object() || s.value("status", std::string()) != "completed" ||
        !s["metrics"].contains(metric))
      continue;
    const auto& e = s["metrics"][metric][plot_value ? "value" : "relative_error"];
    if (e.is_null() || !(against >= 0 ? std::isfinite(e.get<double>()) : e.get<double>() > 0))
      continue;
    std::string label;
    const std::size_t along = against >= 0 ? static_cast<std::size_t>(against) : 0;
    for (std::size_t a = 0; a < axes.size(); ++a)
      if (a != along) label += (label.empty() ? "" : " ") + axes[a].key + "=" + r.values[a];
    if (label.empty()) label = axes[along].key + " varied";
    const double x = against >= 0 ? std::stod(r.values[along]) : s.value("wall_seconds", 0.0);
    curves[label].push_back({x, e.get<double>()});
    point_label[{label, x}] = axes[along].key + "=" + r.values[along];
  }
  {
    std::ofstream dat(out / "study.dat");
    for (auto& [label, pts] : curves) {
      std::sort(pts.begin(), pts.end());
      dat << "\"" << label << "\"\n";
      for (const auto& [t, e] : pts)
        dat << t << " " << e << " \"" << point_label[{label, t}] << "\"\n";
      dat << "\n\n";
    }
  }
  write_study_gp(out, base.name, metric, opt.against, plot_value, curves.size());
  if (curves.empty()) {
    fmt::print("study: no run measured {}: no plot (study.csv, study.md)\n", metric);
  } else if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    fmt::print(
        "study: gnuplot not found (apt-get install gnuplot-nox): no plot; study.csv, study.md "
        "and study.gp are written\n");
  } else {
    const std::string cmd = "cd '" + out.string() + "' && gnuplot study.gp 2>&1";
    if (std::system(cmd.c_str()) != 0)
      fmt::print("study: gnuplot failed: no plot; study.csv and study.md are written\n");
  }
  fmt::print("study: {} (table {}, plot {})\n", (out / "study.csv").string(),
             (out / "study.md").string(), (out / "study.png").string());
  return all_ok ? 0 : 3;
}

}  // namespace monosph
