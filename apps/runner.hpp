#pragma once
// `monosph run`: a scene from start (or a checkpoint) to its end time, with VTK frames, probes,
// checkpoints, a progress line and summary.json.
#include <map>
#include <string>
#include <vector>

namespace monosph {

struct RunOptions {
  std::string scene;  // may be empty with a restart file
  std::vector<std::string> overrides;
  std::string out;
  std::string restart;
  int threads = 0;             // 0: keep the current default (set_default_threads)
  bool fixed_threads = false;  // hold `threads` for the whole run (no thread governor)
  bool quiet = false;
  long max_steps = 0;  // stop after this many steps (bench); 0: no limit
  bool write_output = true;
};

struct RunResult {
  int exit_code = 0;
  std::size_t particles = 0;
  long steps = 0;
  double wall_seconds = 0, particle_steps_per_second = 0, neighbour_seconds = 0;
  int neighbour_builds = 0;
  double mean_threads = 0;     // lower than the threads asked for while other processes were busy
  bool fixed_threads = false;  // --fixed-threads: held at the threads asked for
  long configuration_updates = 0;  // pair-geometry updates (fewer with dual-criteria steps)
  std::map<std::string, double> pass_seconds;  // wall seconds of each pass in the timed steps
};

RunResult run_scene(const RunOptions& opt);

}  // namespace monosph
