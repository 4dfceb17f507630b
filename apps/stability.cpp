#include "stability.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/input_file.hpp"
#include "core/types.hpp"
#include "parallel/threads.hpp"
#include "processes.hpp"
#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {
namespace fs = std::filesystem;

namespace {

struct SuiteScene {
  std::string file;                // scene file (relative to the suite file)
  std::vector<std::string> quick;  // --set overrides of the reduced run
  std::string name;                // the scene's name
  int code = -1;
  std::string message;  // the run's error, if it stopped
  nlohmann::json summary;
};

std::vector<SuiteScene> read_suite(const std::string& file) {
  const std::string text =
      read_input_file(file, "stability: cannot read the suite file " + file, kMaxSceneBytes);
  YAML::Node root = parse_scene_yaml(text, "stability: " + file);
  std::vector<SuiteScene> out;
  try {
    check_yaml_tree(root, file);
    MapReader top(root, "", nullptr);
    auto list = top.node("scenes");
    if (!list.IsSequence()) scene_error("scenes", "expected a list of {scene, quick}");
    for (std::size_t i = 0; i < list.size(); ++i) {
      MapReader q(list[i], "scenes[" + std::to_string(i) + "]", nullptr);
      SuiteScene s;
      s.file = (fs::path(file).parent_path() / q.text("scene")).string();
      if (q.has("quick"))
        s.quick = q.strings("quick");
      else
        q.optional("quick");  // named among the allowed keys of an error
      q.finish();
      out.push_back(std::move(s));
    }
    top.finish();
  } catch (const InputError& e) {
    throw InputError("stability: " + file + ": " + e.what());
  }
  return out;
}

std::string bound_text(const nlohmann::json& c) {
  const bool lo = c.contains("min"), hi = c.contains("max");
  if (lo && hi)
    return fmt::format("[{:.4g}, {:.4g}]", c["min"].get<double>(), c["max"].get<double>());
  if (lo) return fmt::format(">= {:.4g}", c["min"].get<double>());
  return fmt::format("<= {:.4g}", c["max"].get<double>());
}

std::string value_text(const nlohmann::json& c) {
  return c["value"].is_number() ? fmt::format("{:.4g}", c["value"].get<double>()) : "–";
}

}  // namespace

int run_stability(const StabilityOptions& opt) {
  if (opt.jobs < 1) throw InputError("stability: --jobs must be at least 1");
  const std::string suite =
      opt.suite.empty() ? std::string(MONOSPH_CASES_DIR) + "/stability/suite.yaml" : opt.suite;
  std::vector<SuiteScene> scenes = read_suite(suite);
  // Every scene (with its reduced-run overrides) is read now: a typo fails before any run.
  std::vector<SuiteScene> chosen;
  for (auto& s : scenes) {
    const Scene sc = load_scene_file(s.file, opt.quick ? s.quick : std::vector<std::string>{});
    s.name = sc.name;
    if (sc.checks.empty()) throw InputError("stability: scene " + s.file + " declares no checks");
    if (opt.only.empty() || std::find(opt.only.begin(), opt.only.end(), s.name) != opt.only.end())
      chosen.push_back(s);
  }
  for (const auto& o : opt.only) {
    bool found = false;
    for (const auto& s : scenes) found = found || s.name == o;
    if (!found) {
      std::string names;
      for (const auto& s : scenes) names += (names.empty() ? "" : ", ") + s.name;
      throw InputError("stability: --only " + o + ": no such scene in the suite (" + names + ")");
    }
  }
  const fs::path out(opt.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || access(out.c_str(), W_OK) != 0)
    throw InputError("stability: cannot write to " + out.string() +
                     (ec ? ": " + ec.message() : ""));

  const auto [njobs, threads] = jobs_and_threads("stability", opt.jobs, opt.threads);
  fmt::print("stability: {} scene{}{}, {} at a time, {} thread{} each, in {}\n", chosen.size(),
             chosen.size() == 1 ? "" : "s", opt.quick ? " (quick)" : "", njobs, threads,
             threads > 1 ? "s" : "", out.string());
  std::fflush(stdout);
  std::vector<ChildRun> jobs;
  for (const auto& s : chosen) {
    const fs::path dir = out / s.name;
    fs::remove_all(dir, ec);
    fs::create_directories(dir, ec);
    ChildRun c{
        {"run", s.file, "--out", dir.string(), "--quiet", "--threads", std::to_string(threads)},
        dir / "run.log"};
    if (opt.fixed_threads) c.args.push_back("--fixed-threads");
    if (opt.quick)
      for (const auto& q : s.quick) c.args.push_back("--set"), c.args.push_back(q);
    jobs.push_back(std::move(c));
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t done = 0;
  run_children(jobs, njobs, [&](std::size_t k) {
    SuiteScene& s = chosen[k];
    s.code = jobs[k].code;
    std::ifstream js(out / s.name / "summary.json");
    if (js) s.summary = nlohmann::json::parse(js, nullptr, false);
    if (s.code != 0 && s.code != 5) s.message = first_message(jobs[k].log);
    const bool ok = s.summary.is_object() && s.summary.value("checks_passed", false);
    fmt::print("stability: [{}/{}] {}: {}{}\n", ++done, chosen.size(), s.name, ok ? "pass" : "FAIL",
               s.summary.is_object()
                   ? fmt::format(" ({} steps, {:.1f} s)", s.summary.value("steps", 0L),
                                 s.summary.value("wall_seconds", 0.0))
                   : std::string());
    std::fflush(stdout);
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // The table: one row per check, a run that stopped first with its message.
  int checks = 0, failed = 0;
  std::string table = fmt::format("{:<20} {:<20} {:>12}  {:<24} {}\n", "scene", "check", "value",
                                  "bound", "result");
  std::string md = "| scene | check | value | bound | result |\n|---|---|---|---|---|\n";
  nlohmann::json js = nlohmann::json::object();
  for (const auto& s : chosen) {
    nlohmann::json entry = {{"scene", s.file}, {"exit_code", s.code}};
    if (!s.message.empty() || !s.summary.is_object()) {
      const std::string why = s.message.empty() ? "no summary.json" : s.message;
      table += fmt::format("{:<20} {:<20} {:>12}  {:<24} {}\n", s.name, "(run)", "–", "completes",
                           "FAIL: " + why);
      md += fmt::format("| {} | (run) | – | completes | **FAIL**: {} |\n", s.name, why);
      entry["message"] = why;
      ++failed, ++checks;
    }
    if (s.summary.is_object()) {
      entry["status"] = s.summary.value("status", std::string());
      entry["steps"] = s.summary.value("steps", 0L);
      entry["wall_seconds"] = s.summary.value("wall_seconds", 0.0);
      entry["checks"] = s.summary.value("checks", nlohmann::json::object());
      for (const auto& [name, c] : entry["checks"].items()) {
        const bool pass = c.value("pass", false);
        ++checks, failed += !pass;
        table += fmt::format("{:<20} {:<20} {:>12}  {:<24} {}\n", s.name, name, value_text(c),
                             bound_text(c), pass ? "pass" : "FAIL");
        md += fmt::format("| {} | {} | {} | {} | {} |\n", s.name, name, value_text(c),
                          bound_text(c), pass ? "pass" : "**FAIL**");
      }
    }
    js[s.name] = entry;
  }
  fmt::print("\n{}\nstability: {} scenes, {} checks: {} passed, {} failed; {:.0f} s\n", table,
             chosen.size(), checks, checks - failed, failed, seconds);
  std::ofstream(out / "stability.md") << md;
  std::ofstream(out / "stability.json") << js.dump(2) << "\n";
  fmt::print("stability: table in {}, details in {}\n", (out / "stability.md").string(),
             (out / "stability.json").string());
  return failed == 0 ? 0 : 5;
}

}  // namespace monosph
