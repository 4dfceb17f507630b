// `monosph bench --suite`: particle-steps per second of the five kinds of scene at several
// sizes and thread counts, the share of the slowest pass, the machine's memory bandwidth, JSON and
// a row block appended to docs/performance.md (commit and machine named).
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bench.hpp"
#include "core/types.hpp"
#include "runner.hpp"
#include "scene/scene.hpp"

namespace monosph {
namespace {

struct SuiteCase {
  std::string label, scene;
  std::vector<double> refine;  // dp divided by each
};

std::string shell_line(const std::string& cmd) {
  std::string out;
  if (FILE* f = popen(cmd.c_str(), "r")) {
    char buf[512];
    if (fgets(buf, sizeof buf, f)) out = buf;
    pclose(f);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string machine() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  char host[256] = "?";
  gethostname(host, sizeof host);
  return fmt::format("{}, {} ({} cores)", host, model, sysconf(_SC_NPROCESSORS_ONLN));
}

}  // namespace

int run_bench_suite(const BenchOptions& opt) {
  const std::string c = opt.cases_dir;
  // Sizes: about 10k, 40k and 160k particles (2D), 10k and 100k (3D); the dam break also at
  // about 1M, for the cost per particle-step from 10k to 1M.
  std::vector<SuiteCase> cases = {
      {"2D fluid (dam break)", c + "/dam_break/scene.yaml", {1.5, 3, 6, 14.6}},
      {"2D solid, hourglass control (oscillating plate)",
       c + "/oscillating_plate/scene.yaml",
       {1.4, 2.8, 5.6}},
      {"2D plasticity + damage (metal cutting)", c + "/metal_cutting/scene.yaml", {2, 4, 8}},
      {"AFM (fluid, PMMA, grains)", c + "/abrasive_flow_machining/scene.yaml", {1, 2}},
      {"3D solid (Taylor bar)", c + "/taylor_bar/scene.yaml", {1.36, 2.9}},
      {"3D solid, total Lagrangian (Taylor bar)", c + "/taylor_bar/scene_tlsph.yaml", {1.36, 2.9}},
  };
  if (opt.quick)
    for (auto& k : cases) k.refine.resize(1);
  check_writable(opt.json);
  check_writable(opt.append);
  // What a second thread can gain on arrays in the cache and in main memory (bench_memory.cpp).
  const std::vector<Bandwidth> bw = memory_bandwidth(opt.threads);
  nlohmann::json bw_rows = nlohmann::json::array();
  std::string bw_line = "memory bandwidth (STREAM triad, GB/s):";
  for (const auto& b : bw) {
    bw_rows.push_back({{"threads", b.threads}, {"mib", b.bytes >> 20}, {"gb_per_s", b.gb_per_s}});
    bw_line += fmt::format(" {} MiB on {} thread{} {:.1f};", b.bytes >> 20, b.threads,
                           b.threads == 1 ? "" : "s", b.gb_per_s);
  }
  bw_line.back() = '\n';
  fmt::print("{}", bw_line);
  nlohmann::json rows = nlohmann::json::array();
  fmt::print("{:<50} {:>9} {:>3} {:>6} {:>9} {:>13} {:>24}\n", "case", "particles", "thr", "steps",
             "wall [s]", "part-steps/s", "slowest pass (share)");
  for (const auto& k : cases) {
    const Scene base = load_scene_file(k.scene);
    for (double r : k.refine) {
      for (int th : opt.threads) {
        RunOptions ro;
        ro.scene = k.scene;
        ro.overrides = {fmt::format("dp={:.17g}", base.dp / r), "output.checkpoint_every=0"};
        ro.threads = th;
        ro.fixed_threads = opt.fixed_threads;
        ro.quiet = true;
        ro.max_steps = opt.steps;
        ro.write_output = false;
        RunResult res = run_scene(ro);
        if (res.exit_code != 0) return res.exit_code;  // interrupted or diverged: no figures
        double total = 0, worst = 0;
        std::string slow;
        for (const auto& [pass, s] : res.pass_seconds) {
          total += s;
          if (s > worst) worst = s, slow = pass;
        }
        const std::string share =
            total > 0 ? fmt::format("{} ({:.0f} %)", slow, 100 * worst / total) : "";
        fmt::print("{:<50} {:>9} {:>3} {:>6} {:>9.2f} {:>13.4g} {:>24}\n", k.label, res.particles,
                   th, res.steps, res.wall_seconds, res.particle_steps_per_second, share);
        std::fflush(stdout);
        rows.push_back({{"case", k.label},
                        {"scene", k.scene},
                        {"dp", base.dp / r},
                        {"particles", res.particles},
                        {"threads", th},
                        {"threads_mean", res.mean_threads},
                        {"steps", res.steps},
                        {"wall_seconds", res.wall_seconds},
                        {"particle_steps_per_second", res.particle_steps_per_second},
                        {"ns_per_particle_step_by_pass", ns_per_particle_step_by_pass(res)},
                        {"slowest_pass", slow}});
      }
    }
  }
  const std::string commit =
      shell_line("git -C '" + opt.cases_dir + "/..' rev-parse --short HEAD 2>/dev/null");
  const std::string where = machine();
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", std::gmtime(&now));
  if (!opt.json.empty()) {
    std::ofstream out(opt.json);
    if (!out) throw InputError("bench: cannot write " + opt.json);
    out << nlohmann::json{{"suite", rows},
                          {"memory_bandwidth", bw_rows},
                          {"commit", commit},
                          {"machine", where},
                          {"date", date}}
               .dump(2)
        << "\n";
    fmt::print("written {}\n", opt.json);
  }
  if (!opt.append.empty()) {
    std::ofstream md(opt.append, std::ios::app);
    if (!md) throw InputError("bench: cannot append to " + opt.append);
    md << "\n### `monosph bench --suite`, " << date << " UTC, commit "
       << (commit.empty() ? "?" : commit) << ", " << where << "\n\n"
       << bw_line << "\n"
       << "| case | particles | threads | steps | particle-steps/s | slowest pass (ns per "
          "particle-step) |\n|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
      const std::string slow = r["slowest_pass"];
      md << "| " << r["case"].get<std::string>() << " | " << r["particles"] << " | " << r["threads"]
         << " | " << r["steps"] << " | "
         << fmt::format("{:.3g}", r["particle_steps_per_second"].get<double>()) << " | "
         << (slow.empty() ? std::string("–")
                          : fmt::format("{} ({:.0f})", slow,
                                        r["ns_per_particle_step_by_pass"][slow].get<double>()))
         << " |\n";
    }
    fmt::print("appended to {}\n", opt.append);
  }
  return 0;
}

}  // namespace monosph
