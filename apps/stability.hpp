#pragma once
// `monosph stability`: the stability suite (cases/stability): stiff and extreme scenes that check
// themselves (scene `checks`), run and summed up in one pass/fail table.
#include <string>
#include <vector>

namespace monosph {

struct StabilityOptions {
  std::string suite;  // suite file (default cases/stability/suite.yaml)
  std::string out = "out/stability";
  std::vector<std::string> only;  // scene names to run (default: all)
  bool quick = false;             // each scene's reduced run (`quick` overrides): CI
  int jobs = 1;                   // scenes at once (processes)
  int threads = 0;                // threads per run (default: the cores / jobs)
  bool fixed_threads = false;     // runs hold their thread count (run --fixed-threads)
};

// Returns 0 when every check of every scene passed, 5 when one failed or a run stopped, 2 on
// bad input.
int run_stability(const StabilityOptions& opt);

}  // namespace monosph
