#include "run_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "output/atomic_file.hpp"
#include "output/probe_csv.hpp"
#include "output/probes.hpp"

namespace monosph {

template <int D>
nlohmann::json mpi_summary(Simulation<D>& sim, long run_steps) {
  const auto* dec = sim.decomposition();
  const Comm& comm = sim.comm();
  nlohmann::json mpi;
  if (dec) {
    const auto& st = dec->stats();
    const double steps = std::max(1L, run_steps);
    mpi["halo_bytes_per_step"] = comm.sum(st.halo_bytes) / steps;  // all ranks together
    mpi["exchanges_per_step"] = st.exchanges / steps;
    mpi["collectives_per_step"] = comm.collectives() / steps;
    mpi["exchange_seconds_max"] = comm.max(st.exchange_seconds);
    mpi["rebuild_seconds_max"] = comm.max(st.rebuild_seconds);
    mpi["wait_seconds_max"] = comm.max(st.wait_seconds);
    mpi["ghosts"] = comm.sum(static_cast<long>(dec->ghosts()));
    mpi["owned_max"] = comm.max(static_cast<long>(dec->owned()));
    mpi["peers_max"] = comm.max(st.peers);
    mpi["rebalances"] = st.rebalances;
    mpi["imbalance_last"] = st.imbalance;  // largest / mean work at the last rebuild
    mpi["migrated"] = comm.sum(st.migrated);
  }
  return mpi;
}

template <int D>
nlohmann::json summary_json(Simulation<D>& sim, const RunResult& res, const std::string& status,
                            int threads, const nlohmann::json& mpi, long peak_memory,
                            const std::filesystem::path& out) {
  const Scene& scene = sim.scene();
  const Comm& comm = sim.comm();
  nlohmann::json js;
  js["scene"] = scene.name;
  js["dimension"] = D;
  js["particles"] = res.particles;
  js["steps"] = sim.step();
  js["steps_this_run"] = res.steps;
  js["simulated_time"] = sim.time();
  js["wall_seconds"] = res.wall_seconds;
  js["particle_steps_per_second"] = res.particle_steps_per_second;
  js["threads"] = threads;
  js["threads_mean"] = res.mean_threads;    // lower while other processes used the CPUs
  js["threads_fixed"] = res.fixed_threads;  // --fixed-threads: threads_mean equals threads
  js["ranks"] = comm.size();
  if (sim.decomposition()) {
    js["halo_bytes_per_step"] = mpi["halo_bytes_per_step"];
    js["mpi"] = mpi;
  }
  js["status"] = status;
  js["dp"] = scene.dp;
  js["h"] = scene.h();
  js["kernel"] = kernel_name(scene.kernel);
  js["neighbour_builds"] = res.neighbour_builds;
  js["configuration_updates"] = res.configuration_updates;
  js["neighbour_seconds"] = res.neighbour_seconds;
  js["pass_seconds"] = sim.pass_seconds();  // this rank's (rank 0 under MPI)
  js["last_dt"] = sim.dt();
  if (scene.multi_rate) js["solid_substeps"] = sim.total_substeps();  // over this run's steps
  js["peak_memory_bytes"] = peak_memory;
  js["output"] = (out / (scene.name + ".pvd")).string();
  return js;
}

template nlohmann::json summary_json<2>(Simulation<2>&, const RunResult&, const std::string&, int,
                                        const nlohmann::json&, long, const std::filesystem::path&);
template nlohmann::json summary_json<3>(Simulation<3>&, const RunResult&, const std::string&, int,
                                        const nlohmann::json&, long, const std::filesystem::path&);

template nlohmann::json mpi_summary<2>(Simulation<2>&, long);
template nlohmann::json mpi_summary<3>(Simulation<3>&, long);

bool measure_run(nlohmann::json& js, const Scene& scene, const std::filesystem::path& csv,
                 double time, const std::string& status) {
  js["metrics"] = nlohmann::json::object();
  bool all = true;
  {
    std::vector<std::string> head;
    std::vector<std::vector<double>> cols;
    read_probe_table(csv, head, cols);
    // The column of a probe (a vector probe: its x component, or the component named "load_y").
    auto column = [&](const std::string& probe) -> const std::vector<double>* {
      auto spec = std::find_if(scene.probes.begin(), scene.probes.end(),
                               [&](const ProbeSpec& s) { return s.name == probe; });
      std::string col =
          spec != scene.probes.end() && (spec->type == "momentum" || spec->type == "reaction_force")
              ? probe + "_x"
              : probe;
      auto it = std::find(head.begin(), head.end(), col);
      if (it == head.end() || cols.empty()) return nullptr;
      return &cols[it - head.begin()];
    };
    // The measure of a probe's column, or NaN and why not.
    auto measure = [&](const std::string& probe, const std::string& what, double start,
                       std::string& why) {
      const auto* y = column(probe);
      const double v = y ? measure_series(what, cols[0], *y, start, &why) : NAN;
      if (!y) why = "probes.csv has no column of probe '" + probe + "'";
      if (!std::isfinite(v) && why.empty()) why = "the probe's values are not finite";
      return v;
    };
    for (const auto& ref : scene.references) {
      std::string why;
      const double value = measure(ref.probe, ref.measure, ref.start, why);
      // A measure over a window (final, max, min, mean) is the reference's only once the run has
      // simulated the time the scene gives it; before that it is "not reached", not an error.
      const double needs = ref.needs_time(scene.reference_end_time);
      const bool reached = time >= needs * (1 - 1e-9);
      nlohmann::json m;
      m["value"] = std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
      if (!std::isfinite(value)) m["why_no_value"] = why;
      m["reference"] =
          std::isfinite(ref.value) ? nlohmann::json(ref.value) : nlohmann::json(nullptr);
      m["reached"] = reached;
      m["needs_time"] = needs;
      m["relative_error"] =
          reached && std::isfinite(value) && std::isfinite(ref.value) && ref.value != 0
              ? nlohmann::json(std::abs(value - ref.value) / std::abs(ref.value))
              : nlohmann::json(nullptr);
      js["metrics"][ref.name] = m;
    }
    // Pass criteria: a run that stopped fails all of them.
    if (!scene.checks.empty()) {
      js["checks"] = nlohmann::json::object();
      for (const auto& c : scene.checks) {
        std::string why;
        const double value = measure(c.probe, c.measure, c.start, why);
        const bool pass =
            status == "completed" && std::isfinite(value) && value >= c.min && value <= c.max;
        all = all && pass;
        nlohmann::json m;
        m["value"] = std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
        if (!std::isfinite(value)) m["why_no_value"] = why;
        if (std::isfinite(c.min)) m["min"] = c.min;
        if (std::isfinite(c.max)) m["max"] = c.max;
        m["pass"] = pass;
        js["checks"][c.name] = m;
      }
      js["checks_passed"] = all;
    }
  }
  return all;
}

void print_measures(const nlohmann::json& js, const Scene& scene, double time) {
  for (const auto& ref : scene.references) {
    const nlohmann::json& m = js["metrics"][ref.name];
    if (!m["reached"].get<bool>()) {
      fmt::print(stderr,
                 "monosph: {} not reached: its measure needs {:.6g} s simulated, the run "
                 "reached {:.6g} s\n",
                 ref.name, m["needs_time"].get<double>(), time);
      continue;
    }
    if (m["value"].is_null()) {
      fmt::print(stderr, "monosph: {} could not be measured from probe '{}': {}\n", ref.name,
                 ref.probe, m["why_no_value"].get<std::string>());
      continue;
    }
    if (m["reference"].is_null()) {
      fmt::print(stderr, "monosph: {} = {:.6g} (no reference value)\n", ref.name,
                 m["value"].get<double>());
      continue;
    }
    const double v = m["value"], rv = m["reference"];
    fmt::print(stderr, "monosph: {} = {:.6g} (reference {:.6g}, relative error {:.3e})\n", ref.name,
               v, rv, std::abs(v - rv) / std::abs(rv));
  }
  for (const auto& c : scene.checks) {
    const nlohmann::json& m = js["checks"][c.name];
    fmt::print(stderr, "monosph: check {} = {} ({}{}{}): {}\n", c.name,
               m["value"].is_null() ? "not measured: " + m["why_no_value"].get<std::string>()
                                    : fmt::format("{:.6g}", m["value"].get<double>()),
               std::isfinite(c.min) ? fmt::format(">= {:g}", c.min) : "",
               std::isfinite(c.min) && std::isfinite(c.max) ? ", " : "",
               std::isfinite(c.max) ? fmt::format("<= {:g}", c.max) : "",
               m["pass"].get<bool>() ? "pass" : "FAIL");
  }
}

template <int D>
void write_summary(Simulation<D>& sim, RunResult& res, const std::string& status,
                   const RunReport& how, const nlohmann::json& mpi, long peak_memory,
                   const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  const Scene& scene = sim.scene();
  const Comm& comm = sim.comm();
  nlohmann::json js = summary_json(sim, res, status, how.threads, mpi, peak_memory, out);
  if (!measure_run(js, scene, out / "probes.csv", sim.time(), status) && res.exit_code == 0)
    res.exit_code = 5;
  try {
    write_file_atomic(out / "summary.json", js.dump(2) + "\n");
  } catch (const OutputError&) {
    // Without its summary a final.h5 would pass for the end of a completed run.
    std::error_code rm;
    if (res.exit_code == 0) fs::remove(out / "final.h5", rm);
    throw;
  }
  const std::string done = fmt::format(
      "monosph: {} — {} particles, {} steps, {:.2f} s wall, {:.3g} particle-steps/s, {}{} "
      "threads{}",
      status == "completed" || status == "interrupted" ? status : "stopped", res.particles,
      res.steps, res.wall_seconds, res.particle_steps_per_second,
      comm.parallel() ? fmt::format("{} ranks x ", comm.size()) : "", how.threads,
      how.busy ? fmt::format(" (mean {:.3f}: other processes were busy)", res.mean_threads) : "");
  if (how.quiet)  // the one line a script's log keeps: status and where the summary is
    fmt::print(stderr, "{}; summary {}\n", done, (out / "summary.json").string());
  if (!how.quiet) {
    fmt::print(stderr, "{}\n", done);
    print_measures(js, scene, sim.time());
    fmt::print(stderr, "monosph: ParaView file {}\nmonosph: summary {}\n",
               (out / (scene.name + ".pvd")).string(), (out / "summary.json").string());
  }
}

template void write_summary<2>(Simulation<2>&, RunResult&, const std::string&, const RunReport&,
                               const nlohmann::json&, long, const std::filesystem::path&);
template void write_summary<3>(Simulation<3>&, RunResult&, const std::string&, const RunReport&,
                               const nlohmann::json&, long, const std::filesystem::path&);

}  // namespace monosph
