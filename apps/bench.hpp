#pragma once
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace monosph {

struct RunResult;

struct BenchOptions {
  std::string json;
  long steps = 200;
  std::vector<long> sizes{10000, 40000, 160000};
  long size3d = 50000;
  std::vector<int> threads{1, 2};
  bool fixed_threads = false;  // each measurement on exactly its thread count (no governor)
  std::string cases_dir = MONOSPH_CASES_DIR;
  std::string scene;              // bench this scene instead of the acoustic wave...
  std::vector<double> refine{1};  // ...at dp / each of these
  bool suite = false;             // the five kinds of scene (run_bench_suite)
  bool quick = false;             // suite at its smallest size only
  std::string append;             // markdown file the suite appends its rows to
};

// `monosph bench --suite`: five kinds of scene at 2-4 sizes, each thread count; the slowest
// pass of each run; JSON (--json) and a block appended to --append (docs/performance.md).
int run_bench_suite(const BenchOptions& opt);

// `monosph bench`: particle-steps per second of the acoustic-wave scene (2D sizes, one 3D size),
// or of any scene at refined spacings, on each thread count, and neighbour-build time per
// particle. Prints a table; optional JSON.
int run_bench(const BenchOptions& opt);
// STREAM triad bandwidth on `threads` threads over arrays of `bytes` in all (bench_memory.cpp).
struct Bandwidth {
  int threads;
  std::size_t bytes;
  double gb_per_s;
};
double triad_gb_per_s(int threads, std::size_t bytes);
// At each thread count: arrays of 8 MiB (in the last-level cache of most machines), 512 MiB (in
// main memory).
std::vector<Bandwidth> memory_bandwidth(const std::vector<int>& threads);

// Wall time of each pass of a run in ns per particle-step: {"forces": 412.5, ...}.
nlohmann::json ns_per_particle_step_by_pass(const RunResult& r);

// InputError "bench: cannot write FILE" unless FILE (if given) can be written.
void check_writable(const std::string& file);

}  // namespace monosph
