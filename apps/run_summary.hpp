#pragma once
// The end of a run (runner.cpp): MPI figures, the scene's reference measures and pass criteria
// from probes.csv (summary.json "metrics", "checks"), and the lines printed about them.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/simulation.hpp"
#include "runner.hpp"

namespace monosph {

// Halo traffic, collectives, waits, imbalance (all ranks; collective). Empty without MPI.
template <int D>
nlohmann::json mpi_summary(Simulation<D>& sim, long steps);

// summary.json without its measures: the run's size, speed, status, passes and output.
template <int D>
nlohmann::json summary_json(Simulation<D>& sim, const RunResult& res, const std::string& status,
                            int threads, const nlohmann::json& mpi, long peak_memory,
                            const std::filesystem::path& out);

// Adds "metrics" and, when the scene has checks, "checks" and "checks_passed" to `js`, measured
// from the probe table `csv` of a run that reached `time` with `status`. False if a check fails
// (a run that stopped fails all of them).
bool measure_run(nlohmann::json& js, const Scene& scene, const std::filesystem::path& csv,
                 double time, const std::string& status);

// How the end of a run is reported: the threads asked for, whether other processes made the
// thread governor use fewer, and --quiet.
struct RunReport {
  int threads;
  bool busy, quiet;
};

// Rank 0: summary.json (metrics and checks measured; res.exit_code 5 if a check fails) and the
// closing lines. An unwritable summary removes final.h5 (it would pass for a completed run).
template <int D>
void write_summary(Simulation<D>& sim, RunResult& res, const std::string& status,
                   const RunReport& how, const nlohmann::json& mpi, long peak_memory,
                   const std::filesystem::path& out);

// One line per reference measure and check of `js` (from measure_run).
void print_measures(const nlohmann::json& js, const Scene& scene, double time);

}  // namespace monosph
