// Bad-input corpus, part 4: the command line of every verb (run, info, study, stability, bench):
// unknown options, missing arguments, bad values, --set syntax, --vary, --restart.
#include "corpus.hpp"

using namespace monosph::test;

namespace {

// `args` with {scene} (a valid scene file), {out} (the case's output folder) and {ckpt} (a
// checkpoint of that scene, made for the case) filled in.
struct LineCase {
  const char* name;
  const char* args;
  const char* message;
};
void PrintTo(const LineCase& c, std::ostream* os) {
  *os << c.name;
}

const LineCase kCases[] = {
    {"no_verb", "", "A subcommand is required"},
    {"unknown_verb", "frobnicate", "unknown command 'frobnicate' (commands: run, info"},
    {"run_unknown_option", "run {scene} --frob", "The following argument was not expected: --frob"},
    {"run_without_scene", "run --quiet", "run: give a scene file or --restart FILE"},
    {"run_two_scenes", "run {scene} {scene}", "The following argument was not expected"},
    {"run_scene_is_a_folder", "run /tmp --out {out}", "/tmp: cannot read scene file"},
    {"run_scene_is_dev_zero", "run /dev/zero --out {out}",
     "/dev/zero: cannot read scene file (it is a character device, not a regular file)"},
    {"stability_suite_is_dev_zero", "stability --suite /dev/zero --out {out}",
     "stability: cannot read the suite file /dev/zero (it is a character device"},
    {"run_out_without_value", "run {scene} --out", "--out: 1 required"},
    {"run_out_is_a_file", "run {scene} --threads 1 --out {scene}", "cannot write to directory"},
    {"threads_text", "run {scene} --threads abc", "--threads: expected a whole number, got 'abc'"},
    {"threads_zero", "run {scene} --threads 0", "--threads: must be at least 1, got 0"},
    {"threads_negative", "run {scene} --threads -3", "--threads: must be at least 1, got -3"},
    {"threads_fraction", "run {scene} --threads 1.5",
     "--threads: expected a whole number, got '1.5'"},
    {"threads_overflow", "run {scene} --threads 99999999999999999999",
     "--threads: expected a whole number, got '99999999999999999999'"},
    {"steps_zero", "run {scene} --steps 0", "--steps: must be at least 1, got 0"},
    {"steps_text", "run {scene} --steps many", "--steps: expected a whole number, got 'many'"},
    {"steps_exponent", "run {scene} --steps 1e400",
     "--steps: expected a whole number, got '1e400'"},
    {"set_without_equals", "run {scene} --set dp", "--set dp: expected key=value"},
    {"set_without_key", "run {scene} --set =5", "--set =5: expected key=value"},
    {"set_index_not_a_number", "run {scene} --set bodies.x=1",
     "--set bodies.x: 'x' is not a list index (bodies is a list of 3)"},
    {"set_last_index_not_a_number", "run {scene} --set bodies.1.initial.velocity.x=1",
     "--set bodies.1.initial.velocity.x: 'x' is not a list index"},
    {"set_index_out_of_range", "run {scene} --set bodies.99.name=x",
     "--set bodies.99.name: index 99 out of range (bodies is a list of 3)"},
    {"set_below_a_number", "run {scene} --set dp.x=1",
     "--set dp.x: dp is a value, not a map of keys"},
    {"set_empty_part", "run {scene} --set time_step..cfl=1",
     "--set time_step..cfl: empty key name"},
    {"set_invalid_value", "run {scene} --set \"dp=[1\"", "--set dp=[1: invalid value"},
    {"set_wrong_type", "run {scene} --set dp=fine", "dp: expected a number, got 'fine'"},
    {"set_unknown_key", "run {scene} --set time_stp.cfl=0.2", "time_stp: unknown key"},
    {"set_complex_value_key", "run {scene} --set \"kernel={[a]: 1}\"",
     "kernel: a key must be a plain name, got a list"},
    {"set_undeclared_variable", "run {scene} --set variables.sped=1",
     "--set variables.sped: the scene declares no variable 'sped'"},
    {"restart_missing_file", "run --restart /nonexistent.h5 --out {out}", "/nonexistent.h5"},
    {"restart_with_scene", "run {scene} --restart {ckpt} --out {out}",
     "run: give either a scene file or --restart, not both"},
    {"restart_set_dp", "run --restart {ckpt} --set dp=0.005 --out {out}",
     "--set dp: cannot be changed on a restart (allowed: end_time, output.every, "
     "output.checkpoint_every, limits)"},
    {"restart_not_hdf5", "run --restart {scene} --out {out}", "not a monosph checkpoint"},
    {"info_without_scene", "info", "scene is required"},
    {"info_missing_scene", "info /nonexistent.yaml", "/nonexistent.yaml: cannot read scene file"},
    {"info_bad_set", "info {scene} --set dp=-1", "dp: must be positive"},
    {"info_size_guard", "info {scene} --set dp=1e-12", "dp: 1e-12 gives about"},
    {"study_without_vary", "study {scene} --out {out}", "--vary is required"},
    {"study_vary_without_values", "study {scene} --vary dp --out {out}",
     "--vary dp: expected key=v1,v2,..."},
    {"study_vary_empty_value", "study {scene} --vary dp=0.01,,0.02 --out {out}",
     "--vary dp=0.01,,0.02: empty value"},
    {"study_vary_bad_value", "study {scene} --vary dp=0.01,abc --out {out}",
     "dp: expected a number, got 'abc'"},
    {"study_vary_unknown_key", "study {scene} --vary dpp=0.01 --out {out}", "dpp: unknown key"},
    {"study_stabilisation_typo", "study {scene} --vary stabilisation=hourglas --out {out}",
     "--vary stabilisation: 'hourglas' is not one of none, artificial_stress, hourglass"},
    {"study_jobs_zero", "study {scene} --vary dp=0.01 --jobs 0 --out {out}",
     "--jobs: must be at least 1, got 0"},
    {"study_threads_text", "study {scene} --vary dp=0.01 --threads x --out {out}",
     "--threads: expected a whole number, got 'x'"},
    {"study_metric_unknown", "study {scene} --vary dp=0.01 --metric speed --out {out}",
     "study: --metric 'speed' is not a reference of the scene"},
    {"study_against_not_varied", "study {scene} --vary dp=0.01 --against cfl --out {out}",
     "study: --against cfl is not one of the --vary keys"},
    {"stability_only_unknown", "stability --only nosuch --out {out}",
     "stability: --only nosuch: no such scene in the suite"},
    {"stability_jobs_text", "stability --jobs many --out {out}",
     "--jobs: expected a whole number, got 'many'"},
    {"stability_threads_zero", "stability --threads 0 --out {out}",
     "--threads: must be at least 1, got 0"},
    {"stability_missing_suite", "stability --suite /nonexistent.yaml --out {out}",
     "stability: cannot read the suite file /nonexistent.yaml"},
    {"stability_suite_unknown_key", "stability --suite {suite} --out {out}",
     "scenes[0].scne: unknown key; did you mean 'scene'?"},
    {"bench_threads_zero", "bench --threads 0", "--threads: must be at least 1, got 0"},
    {"bench_sizes_negative", "bench --sizes -5", "--sizes: must be at least 1, got -5"},
    {"bench_sizes_text", "bench --sizes many", "--sizes: expected a whole number, got 'many'"},
    {"bench_steps_zero", "bench --steps 0", "--steps: must be at least 1, got 0"},
    {"bench_refine_zero", "bench --scene {scene} --refine 0",
     "--refine: expected a positive number, got '0'"},
    {"bench_missing_scene", "bench --scene /nonexistent.yaml",
     "/nonexistent.yaml: cannot read scene file"},
    {"bench_json_unwritable", "bench --sizes 1000 --steps 1 --threads 1 --json /proc/bench.json",
     "bench: cannot write /proc/bench.json"},
};

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

}  // namespace

class CorpusCommandLine : public ::testing::TestWithParam<LineCase> {};

TEST_P(CorpusCommandLine, ExitsWithCode2AndOneLineNamingTheOption) {
  const LineCase& c = GetParam();
  const std::string out = out_dir("corpus_cli_" + std::string(c.name));
  std::string args = c.args;
  const std::string scene = write_scene(out, "scene", kFluid);
  args = replace_all(args, "{scene}", scene);
  args = replace_all(args, "{out}", out + "/run");
  if (args.find("{suite}") != std::string::npos)
    args = replace_all(args, "{suite}", write_scene(out, "suite", "scenes:\n  - {scne: a.yaml}\n"));
  if (args.find("{ckpt}") != std::string::npos) {
    auto r = run_monosph("run " + scene + " --steps 1 --threads 1 --quiet --out " + out + "/first");
    ASSERT_EQ(r.code, 0) << r.output;
    args = replace_all(args, "{ckpt}", out + "/first/final.h5");
  }
  expect_bad_input(args, c.message, out + "/run");
}

INSTANTIATE_TEST_SUITE_P(Verbs, CorpusCommandLine, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// --threads above the machine's cores: clamped with one warning, never a crash (libgomp fails
// to create thousands of threads).
TEST(CommandLine, ThreadsAboveTheCoresAreClampedWithAWarning) {
  const std::string out = out_dir("corpus_threads_clamp");
  const std::string scene = write_scene(out, "scene", kFluid);
  auto r =
      run_monosph("run " + scene + " --threads 100000 --steps 2 --quiet --out " + out + "/run");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("monosph: warning: --threads 100000 is more than the"), std::string::npos)
      << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 2) << r.output;  // + the end line
}

// A frame VTK cannot write (a folder in the way) used to print a dozen coloured VTK lines before
// the one-line message: VTK's own error output is off, the failed write is our one line.
TEST(CommandLine, NoVtkErrorLinesForAnUnwritableFrame) {
  const std::string out = out_dir("corpus_vtk_quiet");
  const std::string scene = write_scene(out, "scene", kFluid);
  std::filesystem::create_directories(out + "/run/corpus_000000.vtu");
  auto r = run_monosph("run " + scene + " --steps 1 --threads 1 --quiet --out " + out + "/run");
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("ERR|"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}
