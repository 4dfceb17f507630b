// monosph command line: run, info, bench, study, stability.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "bench.hpp"
#include "core/comm.hpp"
#include "core/threads.hpp"
#include "core/types.hpp"
#include "info.hpp"
#include "runner.hpp"
#include "stability.hpp"
#include "study.hpp"

namespace {
int run_main(int argc, char** argv);
}

int main(int argc, char** argv) {
  monosph::reexec_with_short_spin(argv);  // before MPI and OpenMP start
  monosph::Comm::init(&argc, &argv);      // under mpirun only
  const int code = run_main(argc, argv);
  monosph::Comm::finalize();
  return code;
}

namespace {
int run_main(int argc, char** argv) {
  using namespace monosph;
  CLI::App app{"monosph: Eulerian-kernel SPH for fluids, hourglass-controlled solids and grains"};
  app.require_subcommand(1);

  RunOptions run;
  auto* cmd_run = app.add_subcommand("run", "run a scene to its end time");
  cmd_run->add_option("scene", run.scene, "scene file (YAML)");
  cmd_run->add_option("--set", run.overrides, "override a scene key, e.g. --set end_time=0.1")
      ->take_all();
  cmd_run->add_option("--out", run.out, "output folder (default out/<scene name>)");
  cmd_run
      ->add_option("--threads", run.threads,
                   "OpenMP threads (default: OMP_NUM_THREADS, else the usable cores)")
      ->check(CLI::PositiveNumber);
  cmd_run->add_option("--restart", run.restart, "continue from a checkpoint file (.h5)");
  cmd_run->add_flag("--quiet", run.quiet, "no progress line");
  cmd_run->add_option("--steps", run.max_steps, "stop after this many steps (then write final.h5)")
      ->check(CLI::PositiveNumber);

  std::string info_scene;
  std::vector<std::string> info_set;
  auto* cmd_info = app.add_subcommand("info", "particle counts, modules and memory of a scene");
  cmd_info->add_option("scene", info_scene, "scene file (YAML)")->required();
  cmd_info->add_option("--set", info_set, "override a scene key")->take_all();

  BenchOptions bench;
  auto* cmd_bench =
      app.add_subcommand("bench", "particle-steps per second (acoustic wave, or --scene)");
  cmd_bench->add_option("--json", bench.json, "write the results as JSON to this file");
  cmd_bench->add_option("--steps", bench.steps, "steps per measurement")
      ->check(CLI::PositiveNumber);
  cmd_bench->add_option("--sizes", bench.sizes, "2D particle counts (approximate)");
  cmd_bench->add_option("--size-3d", bench.size3d, "3D particle count (approximate, 0: skip)");
  cmd_bench->add_option("--threads", bench.threads, "thread counts to measure");
  cmd_bench->add_option("--cases", bench.cases_dir, "folder that holds the cases");
  cmd_bench->add_option("--scene", bench.scene, "bench this scene instead of the acoustic wave");
  cmd_bench->add_option("--refine", bench.refine, "with --scene: run at dp divided by each factor");
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
  cmd_study->add_option("--jobs", study.jobs, "runs at once (processes)")
      ->check(CLI::PositiveNumber);
  cmd_study->add_option("--threads", study.threads, "threads per run (default: cores / jobs)")
      ->check(CLI::PositiveNumber);

  StabilityOptions stab;
  auto* cmd_stab = app.add_subcommand(
      "stability", "run the stability suite (cases/stability) and print its pass/fail table");
  cmd_stab->add_option("--suite", stab.suite, "suite file (default cases/stability/suite.yaml)");
  cmd_stab->add_flag("--quick", stab.quick, "the reduced runs (as in CI)");
  cmd_stab->add_option("--only", stab.only, "run only these scenes (names)")->take_all();
  cmd_stab->add_option("--out", stab.out, "output folder (default out/stability)");
  cmd_stab->add_option("--jobs", stab.jobs, "scenes at once (processes)")
      ->check(CLI::PositiveNumber);
  cmd_stab->add_option("--threads", stab.threads, "threads per run (default: cores / jobs)")
      ->check(CLI::PositiveNumber);

  set_default_threads();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (*cmd_run) {
      if (run.scene.empty() && run.restart.empty())
        throw InputError("run: give a scene file or --restart FILE");
      return run_scene(run).exit_code;
    }
    if (*cmd_info) return print_info(info_scene, info_set);
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
  } catch (const std::exception& e) {
    const Comm& c = Comm::world();
    fmt::print(stderr, "monosph: internal error{}: {}\n",
               c.parallel() ? fmt::format(" on rank {}", c.rank()) : "", e.what());
    return 4;
  }
  return 0;
}
}  // namespace
