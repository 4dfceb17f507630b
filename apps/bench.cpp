#include "bench.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "runner.hpp"
#include "scene/scene.hpp"

namespace monosph {

void check_writable(const std::string& file) {
  if (file.empty()) return;
  // Open it for appending (as root, access() says yes to /proc); a file made here goes again.
  const bool existed = std::filesystem::exists(file);
  const bool ok = static_cast<bool>(std::ofstream(file, std::ios::app));
  if (ok && !existed) std::filesystem::remove(file);
  if (!ok) throw InputError("bench: cannot write " + file);
}

nlohmann::json ns_per_particle_step_by_pass(const RunResult& r) {
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [pass, s] : r.pass_seconds)
    passes[pass] =
        r.steps > 0 && r.particles > 0 ? 1e9 * s / (double(r.steps) * double(r.particles)) : 0.0;
  return passes;
}

int run_bench(const BenchOptions& opt) {
  check_writable(opt.json);  // before the runs, not after them
  nlohmann::json rows = nlohmann::json::array();
  struct Case {
    int dim;
    long n;  // particles wanted (acoustic wave), or 0 with a refinement factor
    double refine;
    std::string file;
    double dp = 0;
  };
  std::vector<Case> cases;
  if (!opt.scene.empty()) {
    for (double f : opt.refine) cases.push_back({0, 0, f, opt.scene});
  } else {
    for (long n : opt.sizes)
      cases.push_back({2, n, 1, opt.cases_dir + "/acoustic_wave/scene.yaml"});
    if (opt.size3d > 0)
      cases.push_back({3, opt.size3d, 1, opt.cases_dir + "/acoustic_wave/scene_3d.yaml"});
  }
  for (auto& c : cases) {  // every scene checked before the first run
    Scene base = load_scene_file(c.file);
    c.dim = base.dimension;
    double vol = 1;
    for (int a = 0; a < base.dimension; ++a) vol *= base.domain_max[a] - base.domain_min[a];
    c.dp = c.n > 0 ? std::pow(vol / c.n, 1.0 / base.dimension) : base.dp / c.refine;
    load_scene_file(c.file, {fmt::format("dp={:.17g}", c.dp)});
  }
  fmt::print("{:>3} {:>9} {:>8} {:>7} {:>12} {:>14} {:>12}\n", "dim", "particles", "threads",
             "steps", "wall [s]", "part-steps/s", "nbuild [us/p]");
  for (const auto& c : cases) {
    const double dp = c.dp;
    for (int th : opt.threads) {
      RunOptions ro;
      ro.scene = c.file;
      ro.overrides = {fmt::format("dp={:.17g}", dp), "output.checkpoint_every=0"};
      ro.threads = th;
      ro.fixed_threads = opt.fixed_threads;
      ro.quiet = true;
      ro.max_steps = opt.steps;
      ro.write_output = false;
      RunResult r = run_scene(ro);
      if (r.exit_code != 0) return r.exit_code;  // interrupted or diverged: no figures
      const double nb_us =
          r.neighbour_builds ? 1e6 * r.neighbour_seconds / r.neighbour_builds / r.particles : 0;
      fmt::print("{:>3} {:>9} {:>8} {:>7} {:>12.3f} {:>14.4g} {:>12.3f}\n", c.dim, r.particles, th,
                 r.steps, r.wall_seconds, r.particle_steps_per_second, nb_us);
      std::fflush(stdout);
      rows.push_back({{"dimension", c.dim},
                      {"particles", r.particles},
                      {"threads", th},
                      {"threads_mean", r.mean_threads},
                      {"steps", r.steps},
                      {"wall_seconds", r.wall_seconds},
                      {"particle_steps_per_second", r.particle_steps_per_second},
                      {"neighbour_build_us_per_particle", nb_us},
                      {"ns_per_particle_step_by_pass", ns_per_particle_step_by_pass(r)}});
    }
  }
  if (!opt.json.empty()) {
    std::ofstream out(opt.json);
    if (!out) throw InputError("bench: cannot write " + opt.json);
    out << nlohmann::json{{"scene", opt.scene.empty() ? "acoustic_wave" : opt.scene},
                          {"results", rows}}
               .dump(2)
        << "\n";
    fmt::print("written {}\n", opt.json);
  }
  return 0;
}

}  // namespace monosph
