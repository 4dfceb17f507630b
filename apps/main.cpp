// monosph command line: run, info, bench, study, stability.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <climits>
#include <cmath>

#include "assemble.hpp"
#include "bench.hpp"
#include "core/types.hpp"
#include "info.hpp"
#include "output/vtk_quiet.hpp"
#include "parallel/comm.hpp"
#include "parallel/threads.hpp"
#include "runner.hpp"
#include "stability.hpp"
#include "study.hpp"

namespace {
int run_main(int argc, char** argv);

// A whole number in [lo, hi]: "--threads: expected a whole number, got 'abc'" (CLI11's range
// check prints its bound with 300 digits and calls a word "not in range").
CLI::Validator whole_number(long long lo, long long hi = INT_MAX) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        long long v = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec != std::errc() || end != s.data() + s.size() || s.empty())
          return "expected a whole number, got '" + s + "'";
        if (v < lo) return fmt::format("must be at least {}, got {}", lo, v);
        if (v > hi) return fmt::format("must be at most {}, got {}", hi, v);
        return "";
      },
      fmt::format("INT>={}", lo));
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !(v > 0) || !std::isfinite(v))
          return "expected a positive number, got '" + s + "'";
        return "";
      },
      "NUMBER>0");
}

// --threads above the cores this process may use: clamped with one warning (thousands of
// threads made libgomp fail or crash; more threads than cores only wait on each other).
int clamp_threads(int n) {
  const int cpus = monosph::usable_cpus();
  if (n <= cpus) return n;
  if (monosph::Comm::world().root())
    fmt::print(stderr,
               "monosph: warning: --threads {} is more than the {} core{} this machine lets the "
               "run use; using {}\n",
               n, cpus, cpus == 1 ? "" : "s", cpus);
  return cpus;
}

bool is_command(const CLI::App& app, const std::string& word) {
  try {
    app.get_subcommand(word);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

// A restart continues the stored scene: only keys that do not change its physics may be set.
void check_restart_overrides(const std::vector<std::string>& sets) {
  for (const auto& s : sets) {
    const std::string key = s.substr(0, s.find('='));
    const bool ok = key == "end_time" || key == "output.every" ||
                    key == "output.checkpoint_every" || key.rfind("limits", 0) == 0;
    if (!ok)
      throw monosph::InputError(
          "--set " + key +
          ": cannot be changed on a restart (allowed: end_time, output.every, "
          "output.checkpoint_every, limits)");
  }
}
}  // namespace

int main(int argc, char** argv) {
  monosph::Comm::init(&argc, &argv);  // under mpirun only
  monosph::register_modules();
  const int code = run_main(argc, argv);
  monosph::Comm::finalize();
  return code;
}

namespace {
int run_main(int argc, char** argv) {
  using namespace monosph;
  CLI::App app{"monosph: Eulerian-kernel SPH for fluids, hourglass-controlled solids and grains"};
  app.require_subcommand(1);

  // The thread governor lowers the thread count while other processes keep the CPUs busy.
  const char* kFixedThreads =
      "hold the thread count for the whole run, even while other processes are busy (tests, "
      "benchmarks, reproducibility: summary.json threads_mean then equals threads)";
  RunOptions run;
  auto* cmd_run = app.add_subcommand("run", "run a scene to its end time");
  cmd_run->add_option("scene", run.scene, "scene file (YAML)");
  cmd_run->add_option("--set", run.overrides, "override a scene key, e.g. --set end_time=0.1")
      ->take_all();
  cmd_run->add_option("--out", run.out, "output folder (default out/<scene name>)");
  cmd_run
      ->add_option("--threads", run.threads,
                   "OpenMP threads (default: OMP_NUM_THREADS, else the usable cores)")
      ->check(whole_number(1));
  cmd_run->add_option("--restart", run.restart, "continue from a checkpoint file (.h5)");
  cmd_run->add_flag("--fixed-threads", run.fixed_threads, kFixedThreads);
  cmd_run->add_flag("--quiet", run.quiet, "no progress line");
  cmd_run->add_option("--steps", run.max_steps, "stop after this many steps (then write final.h5)")
      ->check(whole_number(1, LONG_MAX));

  std::string info_scene;
  std::vector<std::string> info_set;
  auto* cmd_info = app.add_subcommand("info", "particle counts, modules and memory of a scene");
  cmd_info->add_option("scene", info_scene, "scene file (YAML)")->required();
  cmd_info->add_option("--set", info_set, "override a scene key")->take_all();
  bool info_config = false;
  cmd_info->add_flag("--config", info_config,
                     "print the parsed configuration (every value, defaults included) as JSON");

  BenchOptions bench;
  auto* cmd_bench =
      app.add_subcommand("bench", "particle-steps per second (acoustic wave, or --scene)");
  cmd_bench->add_option("--json", bench.json, "write the results as JSON to this file");
  cmd_bench->add_option("--steps", bench.steps, "steps per measurement")
      ->check(whole_number(1, LONG_MAX));
  cmd_bench->add_option("--sizes", bench.sizes, "2D particle counts (approximate)")
      ->check(whole_number(1, LONG_MAX));
  cmd_bench->add_option("--size-3d", bench.size3d, "3D particle count (approximate, 0: skip)")
      ->check(whole_number(0, LONG_MAX));
  cmd_bench->add_option("--threads", bench.threads, "thread counts to measure")
      ->check(whole_number(1));
  cmd_bench->add_flag("--fixed-threads", bench.fixed_threads, kFixedThreads);
  cmd_bench->add_option("--cases", bench.cases_dir, "folder that holds the cases");
  cmd_bench->add_option("--scene", bench.scene, "bench this scene instead of the acoustic wave");
  cmd_bench->add_option("--refine", bench.refine, "with --scene: run at dp divided by each factor")
      ->check(positive_number());
  cmd_bench->add_flag("--suite", bench.suite,
                      "fluid, solid, plasticity, AFM and 3D scenes at several sizes");
  cmd_bench->add_flag("--quick", bench.quick, "with --suite: the smallest size of each only");
  cmd_bench->add_option("--append", bench.append,
                        "with --suite: append the rows to this markdown file "
                        "(e.g. docs/performance.md)");

  StudyOptions study;
  auto* cmd_study = app.add_subcommand(
      "study", "run every combination of --vary values; error against wall time (CSV, MD, PNG)");
  cmd_study->add_option("scene", study.scene, "scene file (YAML)")->required();
  cmd_study->add_option("--vary", study.vary, "key=v1,v2,... (scene key or stabilisation)")
      ->required()
      ->take_all();
  cmd_study->add_option("--set", study.overrides, "override a scene key in every run")->take_all();
  cmd_study->add_option("--out", study.out, "output folder (default out/study_<scene name>)");
  cmd_study->add_option("--metric", study.metric, "reference metric to plot (default: first)");
  cmd_study->add_flag("--plot-value", study.plot_value,
                      "plot the metric's value instead of its relative error (e.g. a disorder)");
  cmd_study->add_option("--against", study.against,
                        "plot the metric's value against this --vary key (linear axes, one curve "
                        "per combination of the other keys), e.g. variables.angle");
  cmd_study->add_option("--repeat", study.repeat,
                        "a --vary key whose values repeat each combination of the others (e.g. "
                        "variables.seed=1,2,...,N): study_stats.csv gets each metric's mean, "
                        "Student-t 95 % interval, std and count of zeros over them");
  cmd_study->add_option("--jobs", study.jobs, "runs at once (processes)")->check(whole_number(1));
  cmd_study->add_option("--threads", study.threads, "threads per run (default: cores / jobs)")
      ->check(whole_number(1));
  cmd_study->add_flag("--fixed-threads", study.fixed_threads, kFixedThreads);

  StabilityOptions stab;
  auto* cmd_stab = app.add_subcommand(
      "stability", "run the stability suite (cases/stability) and print its pass/fail table");
  cmd_stab->add_option("--suite", stab.suite, "suite file (default cases/stability/suite.yaml)");
  cmd_stab->add_flag("--quick", stab.quick, "the reduced runs (as in CI)");
  cmd_stab->add_option("--only", stab.only, "run only these scenes (names)")->take_all();
  cmd_stab->add_option("--out", stab.out, "output folder (default out/stability)");
  cmd_stab->add_option("--jobs", stab.jobs, "scenes at once (processes)")->check(whole_number(1));
  cmd_stab->add_option("--threads", stab.threads, "threads per run (default: cores / jobs)")
      ->check(whole_number(1));
  cmd_stab->add_flag("--fixed-threads", stab.fixed_threads, kFixedThreads);

  set_default_threads();
  silence_vtk();  // VTK's errors become our checked, one-line failures
  if (argc > 1 && argv[1][0] != '-' && !is_command(app, argv[1])) {
    if (Comm::world().root())
      fmt::print(stderr,
                 "monosph: error: unknown command '{}' (commands: run, info, study, stability, "
                 "bench; --help lists them)\n",
                 argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    if (Comm::world().root()) fmt::print(stderr, "monosph: error: {}\n", e.what());
    return 2;
  }
  try {
    if (run.threads > 0) run.threads = clamp_threads(run.threads);
    if (study.threads > 0) study.threads = clamp_threads(study.threads);
    if (stab.threads > 0) stab.threads = clamp_threads(stab.threads);
    if (*cmd_bench && cmd_bench->count("--threads") > 0) {
      for (int& t : bench.threads) t = clamp_threads(t);
    } else if (*cmd_bench) {  // the default thread counts: those this machine has
      const int cpus = usable_cpus();
      std::erase_if(bench.threads, [cpus](int t) { return t > cpus; });
      if (bench.threads.empty()) bench.threads = {1};
    }
    if (*cmd_run) {
      if (run.scene.empty() && run.restart.empty())
        throw InputError("run: give a scene file or --restart FILE");
      if (!run.scene.empty() && !run.restart.empty())
        throw InputError(
            "run: give either a scene file or --restart, not both (a restart "
            "continues the scene stored in the checkpoint)");
      if (!run.restart.empty()) check_restart_overrides(run.overrides);
      return run_scene(run).exit_code;
    }
    if (*cmd_info) return print_info(info_scene, info_set, info_config);
    if (*cmd_bench) return bench.suite ? run_bench_suite(bench) : run_bench(bench);
    if (*cmd_study) return run_study(study);
    if (*cmd_stab) return run_stability(stab);
  } catch (const InputError& e) {
    // Under MPI every rank stops with the same message: rank 0 prints it.
    if (Comm::world().root()) fmt::print(stderr, "monosph: error: {}\n", e.what());
    return 2;
  } catch (const RunAborted& e) {
    if (Comm::world().root()) fmt::print(stderr, "monosph: run stopped: {}\n", e.what());
    return 3;
  } catch (const OutputError& e) {  // disk full, I/O error: every rank throws it together
    if (Comm::world().root()) fmt::print(stderr, "monosph: error: {}\n", e.what());
    return 6;
  } catch (const std::exception& e) {
    const Comm& c = Comm::world();
    fmt::print(stderr, "monosph: internal error{}: {}\n",
               c.parallel() ? fmt::format(" on rank {}", c.rank()) : "", e.what());
    return 4;
  }
  return 0;
}
}  // namespace
