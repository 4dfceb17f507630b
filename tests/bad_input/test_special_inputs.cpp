// Inputs that are not what they seem: a FIFO or an oversized file as the scene or as an STL mesh
// (exit 2, one line, no hang), and a guard that trips before the first step (exit 3 with the last
// state and summary.json, as a guard in a step).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "../output_files.hpp"
#include "corpus.hpp"
#include "fault_helpers.hpp"

using namespace monosph::test;
namespace fs = std::filesystem;

namespace {

// A FIFO with no writer: opening it to read blocks for ever (the run hung before the check).
std::string make_fifo(const std::string& dir, const std::string& name) {
  fs::create_directories(dir);
  const std::string path = dir + "/" + name;
  fs::remove(path);
  EXPECT_EQ(mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

// kSolid3d with its triangle surface read from `stl`.
std::string scene_with_stl(const std::string& dir, const std::string& stl) {
  SceneCase c{"stl", kSolid3d,
              "triangles: [[[0.15, 0.001, 0.15], [0.19, 0.001, 0.15], [0.15, 0.001, 0.19]]]", "",
              ""};
  const std::string text = "stl: " + stl;
  c.replace = text.c_str();
  return write_scene(dir, "stl_scene", edited(c));
}

}  // namespace

TEST(SpecialInputs, SceneFileThatIsAFifoIsRefused) {
  const std::string dir = out_dir("special_scene_fifo");
  const std::string fifo = make_fifo(dir, "scene.yaml");
  auto r = run_limited("run " + fifo + " --out " + dir + "/run");
  expect_clean_failure(r, 2,
                       {fifo + ": cannot read scene file (it is a FIFO, not a regular file)"});
}

TEST(SpecialInputs, StlThatIsAFifoOrTooLargeIsRefused) {
  const std::string dir = out_dir("special_stl");
  const std::string fifo = make_fifo(dir, "mesh.stl");
  auto a = run_limited("run " + scene_with_stl(dir, fifo) + " --out " + dir + "/run");
  expect_clean_failure(a, 2,
                       {"surfaces[1] (wedge).stl: cannot read STL file '" + fifo +
                        "' (it is a FIFO, not a regular file)"});
  // 3 GiB, sparse: refused by its size, before a byte is read.
  const std::string big = dir + "/big.stl";
  { std::ofstream(big, std::ios::binary) << "solid big\n"; }
  fs::resize_file(big, 3ull << 30);
  auto b = run_limited("run " + scene_with_stl(dir, big) + " --out " + dir + "/run");
  fs::remove(big);
  expect_clean_failure(b, 2,
                       {"surfaces[1] (wedge).stl: cannot read STL file '" + big +
                        "' (it has 3221225472 bytes, more than the limit of 2147483648 bytes)"});
}

TEST(SpecialInputs, GuardTrippingBeforeTheFirstStepLeavesTheLastStateAndSummary) {
  // 1e5 m/s in water of sound speed 10 m/s: the Mach guard trips on the start-up forces, before
  // any step. Before: exit 3 and only .lock in the folder.
  const std::string dir = out_dir("special_first_step_guard");
  SceneCase c{"fast", kFluid, "velocity: [\"speed\", \"0\"]", "velocity: [\"speed\", \"1.0e5\"]",
              ""};
  const std::string scene = write_scene(dir, "fast", edited(c));
  fs::remove_all(dir + "/run");
  auto r = run_limited("run " + scene + " --out " + dir + "/run");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("monosph: run stopped:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("of its wave speed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("last state written to"), std::string::npos) << r.output;
  const auto js = summary(dir + "/run");
  EXPECT_NE(js["status"].get<std::string>().find("of its wave speed"), std::string::npos)
      << js.dump();
  EXPECT_EQ(js["steps"], 0);
  const auto frames = read_pvd(dir + "/run/corpus.pvd");
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].time, 0.0);
  EXPECT_FALSE(fs::exists(dir + "/run/final.h5"));
}
