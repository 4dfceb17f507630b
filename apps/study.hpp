#pragma once
// `monosph study`: a scene run for every combination of varied keys; error against wall time.
#include <string>
#include <vector>

namespace monosph {

struct StudyOptions {
  std::string scene;
  std::vector<std::string> vary;       // "key=v1,v2,..." (a scene key path, or `stabilisation`)
  std::vector<std::string> overrides;  // --set for every run
  std::string out;                     // default out/study_<scene name>
  std::string metric;                  // reference metric to plot (default: the scene's first)
  int jobs = 1;                        // runs at once (separate processes)
  int threads = 0;                     // threads per run (0: the cores / jobs)
  bool fixed_threads = false;          // runs hold their thread count (run --fixed-threads)
  bool plot_value = false;             // plot the metric's value, not its relative error
  std::string against;  // a --vary key: plot the metric's value against it (linear axes)
  std::string repeat;   // a --vary key (e.g. variables.seed): statistics over its values
};

// Returns the exit code: 0 when every run completed, 3 when some stopped, 2 on bad input.
int run_study(const StudyOptions& opt);

// The --set overrides that turn `stabilisation=none|artificial_stress|hourglass` into keys of
// every solid body of the scene (exposed for tests).
std::vector<std::string> stabilisation_overrides(const std::string& scene_file,
                                                 const std::vector<std::string>& base_overrides,
                                                 const std::string& variant);

}  // namespace monosph
