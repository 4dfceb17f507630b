#include "runner.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "assemble.hpp"
#include "core/memory.hpp"
#include "core/motion_range.hpp"
#include "core/simulation.hpp"
#include "output/atomic_file.hpp"
#include "output/checkpoint.hpp"
#include "output/checkpoint_check.hpp"
#include "output/output_vtk.hpp"
#include "output/probe_csv.hpp"
#include "output/probes.hpp"
#include "output_folder.hpp"
#include "parallel/thread_governor.hpp"
#include "parallel/threads.hpp"
#include "run_summary.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;

namespace monosph {

namespace {

using Clock = std::chrono::steady_clock;

// SIGINT / SIGTERM / SIGUSR1 (which mpirun forwards to the ranks at once): the run finishes its
// step, writes its last frame, checkpoint.h5, the probes and summary.json (status "interrupted")
// and exits with 128 + the signal. SA_RESETHAND: a second signal stops at once.
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) {
  g_signal = sig;
}
class SignalGuard {
 public:
  SignalGuard() {
    g_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
    sigaction(SIGUSR1, &sa, &old_usr1_);
  }
  ~SignalGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
    sigaction(SIGUSR1, &old_usr1_, nullptr);
  }

 private:
  struct sigaction old_int_ {
  }, old_term_{}, old_usr1_{};
};

std::string hms(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--:--";
  long t = static_cast<long>(s + 0.5);
  return fmt::format("{}:{:02}:{:02}", t / 3600, (t / 60) % 60, t % 60);
}

// Progress on a terminal (one updating line) or plain log lines every 10 s otherwise.
class Progress {
 public:
  Progress(bool quiet, double t0, double t_end)
      : quiet_(quiet), tty_(isatty(STDERR_FILENO)), t0_(t0), t_end_(t_end), start_(Clock::now()) {}
  void update(double t, long steps, bool force = false) {
    if (quiet_) return;
    const auto now = Clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (!force && since < (tty_ ? 0.25 : 10.0)) return;
    last_ = now;
    const double wall = std::chrono::duration<double>(now - start_).count();
    const double frac = (t - t0_) / (t_end_ - t0_);
    const double eta = frac > 0 ? wall * (1 - frac) / frac : NAN;
    std::string line =
        fmt::format("t = {:.4e} / {:.4e} s ({:5.1f}%)  step {}  {:.0f} steps/s  ETA {}", t, t_end_,
                    100 * std::min(1.0, t / t_end_), steps,
                    wall > 0 ? (steps - steps0_) / wall : 0.0, hms(eta));
    if (tty_)
      fmt::print(stderr, "\r{:<100}", line);
    else
      fmt::print(stderr, "{}\n", line);
  }
  void start_steps(long s) { steps0_ = s; }
  void finish() {
    if (!quiet_ && tty_) fmt::print(stderr, "\n");
  }

 private:
  bool quiet_, tty_;
  double t0_, t_end_;
  long steps0_ = 0;
  Clock::time_point start_, last_{};
};

// probes.csv: a new file, or on a restart the rows the checkpoint counted (from the folder's file,
// else from the one next to the checkpoint) with the new rows after them.
void open_probe_csv(ProbeCsv& csv, const fs::path& file, const std::vector<std::string>& columns,
                    const CheckpointMeta* restart, const std::string& restart_file) {
  if (!restart) return csv.create(file, columns);
  long rows = -1;  // a checkpoint of an earlier version: the rows up to its time
  if (auto it = restart->scalars.find("probe_rows"); it != restart->scalars.end()) {
    if (!(it->second >= 0 && it->second < 1e15 && it->second == std::floor(it->second)))
      throw InputError("checkpoint: probe_rows is not a row count");
    rows = static_cast<long>(it->second);
  }
  csv.resume(file, fs::path(restart_file).parent_path() / "probes.csv", columns, rows,
             restart->time);
}

// The profile probes' files (rank 0 opens them; an error stops every rank).
template <int D>
void open_profiles(Probes<D>& probes, const fs::path& out, bool restart, double time,
                   const Comm& comm) {
  std::string err;
  try {
    probes.open_profiles(out, restart, time);
  } catch (const InputError& e) {
    err = e.what();
  }
  err = comm.first_message(err);
  if (!err.empty()) throw InputError(err);
}

// When the next frame, probe row and checkpoint are due.
struct Schedule {
  double output, probe, checkpoint;
};

// A fresh start (fill, first forces) or the state of a checkpoint; when output is due next.
template <int D>
Schedule start(Simulation<D>& sim, const CheckpointMeta* restart_meta,
               const std::string& restart_file) {
  const Scene& scene = sim.scene();
  Schedule next{0, 0, scene.checkpoint_every};
  if (restart_meta) {
    // Each rank reads its share of the file (any number of ranks).
    read_checkpoint<D>(restart_file, sim.particles(), sim.comm().rank(), sim.comm().size());
    sim.adopt_particles();
    sim.set_state(restart_meta->time, restart_meta->step, restart_meta->dt);
    auto get = [&](const char* k, double d) {
      auto it = restart_meta->scalars.find(k);
      return it == restart_meta->scalars.end() ? d : it->second;
    };
    next.output = get("next_output", 0);
    next.probe = get("next_probe", 0);
    next.checkpoint = get("next_checkpoint", scene.checkpoint_every);
    // --set output.every, output.checkpoint_every or end_time (the last frame of every: 0) on a
    // restart: the next frame and checkpoint come at the latest one new interval on.
    const double t = sim.time();
    next.output =
        scene.output_every > 0 ? std::min(next.output, t + scene.output_every) : scene.end_time;
    if (scene.checkpoint_every > 0)
      next.checkpoint = std::min(next.checkpoint, t + scene.checkpoint_every);
    sim.set_substeps(static_cast<int>(get("substeps", 1)));
    sim.load_state(restart_meta->scalars);
    for (const auto& m : sim.modules()) m->load_state(sim, restart_meta->scalars);
    sim.init(true);
  } else {
    sim.create_particles();
    sim.init(false);
  }
  return next;
}

// Output fields the scene asks for must exist.
template <int D>
void check_output_fields(const Particles<D>& p, const Scene& scene) {
  for (const auto& f : scene.output_fields) {
    if (!p.has(f)) {
      std::string names;
      for (const auto& ff : p.fields()) names += (names.empty() ? "" : ", ") + ff.name;
      throw InputError("output.fields: no particle field '" + f +
                       "' in this scene (available: " + names + ")");
    }
  }
}

// Steps end on checkpoint times (restarts reproduce the run): an interval shorter than the first
// step would shorten every step to it (1e-12 s: 1e10 steps for 0.01 s, and a file each).
void check_checkpoint_interval(const Scene& scene, double dt) {
  if (scene.checkpoint_every > 0 && scene.checkpoint_every < dt)
    throw InputError(fmt::format(
        "output.checkpoint_every: {:g} s is shorter than the time step ({:.3g} s at the start): "
        "every step would end on a checkpoint; give at least {:.3g} s, or 0 for none",
        scene.checkpoint_every, dt, dt));
}

// The output folder exists and every rank can write to it.
void check_writable(const fs::path& out, const Comm& comm) {
  std::error_code ec;
  fs::create_directories(out, ec);
  const fs::path test_file = out / (".write-test-" + std::to_string(comm.rank()));
  std::ofstream test(test_file);
  const bool ok = !ec && test;
  test.close();
  fs::remove(test_file, ec);
  if (comm.min(ok ? 1L : 0L) == 0)
    throw InputError("output: cannot write to directory " + out.string());
}

// A checkpoint's metadata: time, step, scene, and when output is due next.
template <int D>
CheckpointMeta checkpoint_meta(Simulation<D>& sim, const Schedule& next, long probe_rows) {
  CheckpointMeta meta;
  meta.time = sim.time();
  meta.step = sim.step();
  meta.dt = sim.dt();
  meta.scene_yaml = sim.scene().yaml;
  meta.next_id = sim.particles().next_id();
  meta.scalars["next_output"] = next.output;
  meta.scalars["next_probe"] = next.probe;
  meta.scalars["next_checkpoint"] = next.checkpoint;
  meta.scalars["reference_end_time"] = sim.scene().reference_end_time;
  meta.scalars["probe_rows"] = static_cast<double>(probe_rows);
  meta.scalars["substeps"] = sim.substeps();
  return meta;
}

// The run's size and speed (particles summed over the ranks: collective).
template <int D>
void measure_speed(RunResult& res, Simulation<D>& sim, long step0, double wall, double mean_threads,
                   bool fixed_threads, const std::map<std::string, double>& passes0) {
  res.particles = static_cast<std::size_t>(sim.comm().sum(static_cast<long>(sim.owned())));
  res.steps = sim.step() - step0;
  res.wall_seconds = wall;
  res.particle_steps_per_second = wall > 0 ? double(res.particles) * res.steps / wall : 0;
  res.neighbour_builds = sim.neighbours().builds();
  res.configuration_updates = sim.configuration_updates();
  res.neighbour_seconds = sim.neighbours().build_seconds();
  res.mean_threads = mean_threads;
  res.fixed_threads = fixed_threads;
  res.pass_seconds = sim.pass_seconds();  // of the timed steps: without the start-up forces
  for (const auto& [pass, s] : passes0) res.pass_seconds[pass] -= s;
}

template <int D>
RunResult run_impl(Scene scene, const RunOptions& opt, const CheckpointMeta* restart_meta) {
  RunResult res;
  const fs::path out = opt.out.empty() ? fs::path("out") / scene.name : fs::path(opt.out);
  SignalGuard signals;  // from the start: a signal during the set-up stops after the first step
  // Before the set-up, whose parallel regions would also wait for descheduled threads.
  const int threads = omp_get_max_threads();
  // --fixed-threads: a governor that never learns of other processes keeps `threads`.
  ThreadGovernor governor(usable_cpus(), threads,
                          opt.fixed_threads ? ThreadGovernor::Sampler([] { return -1; })
                                            : ThreadGovernor::Sampler(other_runnable_threads));
  // Locked before anything is read or written there (and cleared of an earlier run's results).
  std::unique_ptr<OutputFolder> folder;
  if (opt.write_output)
    folder = std::make_unique<OutputFolder>(out, restart_meta != nullptr, Comm::world());
  Simulation<D> sim(scene);
  assemble_modules(sim);
  // A guard that trips before the first step (an initial velocity of 1e5 m/s, a restarted
  // particle outside the domain) stops the run as one in a step would: last state and summary.
  std::string start_abort;
  Schedule next{};
  try {
    next = start(sim, restart_meta, opt.restart);
  } catch (const RunAborted& e) {
    start_abort = e.what();
  }
  if (start_abort.empty()) check_checkpoint_interval(scene, sim.first_dt());
  auto& p = sim.particles();
  check_output_fields(p, scene);
  Probes<D> probes(sim);
  if (restart_meta) probes.load_state(restart_meta->scalars);  // the same tracked particles
  const Comm& comm = sim.comm();
  const bool root = comm.root();  // rank 0 writes the series, probes and summary (MPI)
  check_writable(out, comm);
  std::unique_ptr<VtkSeries<D>> vtk;
  if (opt.write_output) {
    vtk = std::make_unique<VtkSeries<D>>(out, scene.name);
    vtk->set_piece(comm.rank(), comm.size());
    if (restart_meta) vtk->restore_frames(sim.time());
  }
  const fs::path csv_path = out / "probes.csv";
  ProbeCsv csv(comm);
  if (opt.write_output) open_probe_csv(csv, csv_path, probes.columns(), restart_meta, opt.restart);
  if (opt.write_output) open_profiles(probes, out, restart_meta != nullptr, sim.time(), comm);
  auto sample = [&] {
    if (!opt.write_output) return;
    sim.diagnostics();
    csv.row(sim.time(), sim.step(), probes.sample(sim));
  };
  // probes.csv and the profile files: a failed write (disk full) stops the run at the next frame
  // or at the end, on every rank at once (OutputError, exit code 6).
  auto check_csv = [&] {
    csv.flush();  // collective
    const std::string err = comm.first_message(probes.write_error());
    if (!err.empty()) throw OutputError(err);
  };
  long rebuilt_step = -1, ckpt_step = -1;
  auto checkpoint = [&](const fs::path& file) {
    ckpt_step = sim.step();
    csv.flush();  // the rows the checkpoint counts are in the file
    // A run with ghosts or dual-criteria stepping rebuilds first: its restart starts from the
    // same list (bit-identical on one rank). Only once per step: a second rebuild at the same
    // positions still moves the solids' reference state by round-off (the final checkpoint right
    // after a periodic one). Other runs keep the state of their last rebuild (Simulation).
    if (sim.checkpoint_rebuilds() && sim.step() != rebuilt_step)
      sim.rebuild_neighbours(), rebuilt_step = sim.step();
    CheckpointMeta meta = checkpoint_meta(sim, next, csv.rows());
    sim.save_state(meta.scalars);
    probes.save_state(meta.scalars);
    for (const auto& m : sim.modules()) m->save_state(meta.scalars);
    write_checkpoint<D>(file, p, sim.owned(), meta, comm);
  };

  long frame_step = -1;  // step of the last frame written
  auto frame = [&] {
    check_csv();
    sim.diagnostics();
    frame_step = sim.step();
    return vtk->write(p, sim.owned(), sim.time(), sim.step(), scene.output_fields);
  };
  const double eps = 1e-12 * scene.end_time;
  if (!restart_meta && start_abort.empty()) {
    if (opt.write_output) frame();
    next.output = scene.output_every > 0 ? scene.output_every : scene.end_time;
    sample();
    next.probe = scene.probe_every;
  }
  if (!restart_meta && start_abort.empty()) {  // one line: solid bodies that would pass through
    const std::string w = untouched_bodies_warning(sim);
    if (root && !w.empty()) fmt::print(stderr, "monosph: warning: {}\n", w);
  }
  Progress progress(opt.quiet || !root, sim.time(), scene.end_time);
  progress.start_steps(sim.step());
  std::string status = "completed";
  const auto t0 = Clock::now();
  const long step0 = sim.step();
  const auto passes0 = sim.pass_seconds();
  // A guard that trips: the message, exit code 3, the last state as a frame.
  auto stopped = [&](const std::string& why) {
    status = why;
    res.exit_code = 3;
    if (root) fmt::print(stderr, "\nmonosph: run stopped: {}\n", why);
    if (!opt.write_output) return;
    try {
      auto f = frame();
      if (root) fmt::print(stderr, "monosph: last state written to {}\n", f.string());
    } catch (const std::exception& w) {
      fmt::print(stderr, "monosph: could not write the last state: {}\n", w.what());
    }
  };
  if (!start_abort.empty()) stopped(start_abort);
  try {
    while (start_abort.empty() && sim.time() < scene.end_time - eps) {
      // Land exactly on checkpoint times so that restarts reproduce the run.
      double stop = scene.end_time;
      if (scene.checkpoint_every > 0) stop = std::min(stop, next.checkpoint);
      sim.advance(stop);
      if (sim.time() >= next.probe - eps) {
        sample();
        next.probe += scene.probe_every;
        if (next.probe <= sim.time()) next.probe = sim.time();
      }
      if (opt.write_output && sim.time() >= next.output - eps) {
        frame();
        next.output += scene.output_every > 0 ? scene.output_every : scene.end_time;
      }
      if (opt.write_output && scene.checkpoint_every > 0 && sim.time() >= next.checkpoint - eps) {
        next.checkpoint += scene.checkpoint_every;
        checkpoint(out / "checkpoint.h5");
      }
      progress.update(sim.time(), sim.step());
      governor.update();
      if (opt.max_steps > 0 && sim.step() - step0 >= opt.max_steps) break;
      if (const long sig = comm.max(static_cast<long>(g_signal)); sig != 0) {
        status = "interrupted";
        res.exit_code = 128 + static_cast<int>(sig);
        if (root) fmt::print(stderr, "\nmonosph: run interrupted by {}\n", strsignal(int(sig)));
        break;
      }
    }
  } catch (const RunAborted& e) {
    stopped(e.what());
  }
  // However the run ended (end time, --steps, an interrupt), its last state is the last frame.
  if (opt.write_output && frame_step != sim.step()) frame();
  progress.update(sim.time(), sim.step(), true);
  progress.finish();
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  measure_speed(res, sim, step0, wall, governor.mean_threads(), opt.fixed_threads, passes0);
  if (!opt.write_output) return res;
  check_csv();
  if (res.exit_code == 0) checkpoint(out / "final.h5");
  // An interrupted run continues from its last state: checkpoint.h5 (restart from it).
  if (status == "interrupted" && ckpt_step != sim.step()) checkpoint(out / "checkpoint.h5");
  csv.close();
  // MPI figures (collective: before rank 0 goes on alone).
  const nlohmann::json mpi = mpi_summary(sim, res.steps);
  // Largest resident set of any rank (collective).
  const long peak_memory = comm.max(static_cast<long>(peak_resident_bytes()));
  // Rank 0 writes the summary alone; the others wait for it (however it ends), so that none exits
  // before it is written: a rank's non-zero exit (an interrupt) makes mpirun kill the job.
  struct WaitForRoot {
    const Comm& c;
    ~WaitForRoot() { c.barrier(); }
  } wait_for_root{comm};
  if (!root) return res;

  write_summary(sim, res, status, {threads, governor.changes() > 0, opt.quiet}, mpi, peak_memory,
                out);
  return res;
}

}  // namespace

RunResult run_scene(const RunOptions& opt) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  CheckpointMeta meta;
  Scene scene;
  if (!opt.restart.empty()) {
    // The scene stored in the checkpoint, with any --set overrides on top.
    int dim = checkpoint_dimension(opt.restart);
    Particles<2> probe2;
    Particles<3> probe3;
    meta = dim == 2 ? read_checkpoint<2>(opt.restart, probe2)
                    : read_checkpoint<3>(opt.restart, probe3);
    scene = load_scene_text(meta.scene_yaml, opt.overrides, opt.restart);
    if (dim == 2)  // material, body, phase... indices against the scene
      check_checkpoint_indices(opt.restart, probe2, meta, scene);
    else
      check_checkpoint_indices(opt.restart, probe3, meta, scene);
    // The end time of the scene as first written (the checkpoint's text has its --set values).
    if (auto it = meta.scalars.find("reference_end_time"); it != meta.scalars.end())
      scene.reference_end_time = it->second;
  } else {
    scene = load_scene_file(opt.scene, opt.overrides);
  }
  const CheckpointMeta* rm = opt.restart.empty() ? nullptr : &meta;
  return scene.dimension == 2 ? run_impl<2>(scene, opt, rm) : run_impl<3>(scene, opt, rm);
}

}  // namespace monosph
