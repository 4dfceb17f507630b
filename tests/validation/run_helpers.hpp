#pragma once
// Runs the monosph binary and reads what it wrote.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "output/checkpoint.hpp"

namespace monosph::test {

struct Result {
  int code = -1;
  std::string output;  // stdout + stderr
};

// Runs a shell command; its output and exit code.
inline Result run_command(const std::string& cmd) {
  Result r;
  FILE* f = popen(cmd.c_str(), "r");
  if (!f) return r;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, f)) r.output.append(buf, n);
  int st = pclose(f);
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

inline Result run_monosph(const std::string& args) {
  return run_command(std::string(MONOSPH_BIN) + " " + args + " 2>&1");
}

inline std::string source(const std::string& rel) {
  return std::string(MONOSPH_SOURCE_DIR) + "/" + rel;
}
inline std::string out_dir(const std::string& name) {
  auto d = std::filesystem::path(MONOSPH_TEST_OUT) / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d.parent_path());  // for a log beside it (DIR.log)
  return d.string();
}

inline nlohmann::json summary(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  return nlohmann::json::parse(in);
}

// A run of a thread-count comparison (--threads 2 --fixed-threads) really ran on two threads:
// the thread governor would otherwise lower a run beside busy processes to one.
inline void expect_two_threads(const std::string& dir) {
  const auto js = summary(dir);
  EXPECT_EQ(js["threads"], 2) << dir;
  EXPECT_EQ(js["threads_fixed"], true) << dir;
  EXPECT_EQ(js["threads_mean"], 2.0) << dir << ": not two threads throughout";
}

// probes.csv as named columns.
struct Table {
  std::vector<std::string> head;
  std::vector<std::vector<double>> cols;
  const std::vector<double>& operator[](const std::string& name) const {
    for (std::size_t k = 0; k < head.size(); ++k)
      if (head[k] == name) return cols[k];
    throw std::runtime_error("no column " + name);
  }
};

inline Table read_csv(const std::string& file) {
  Table t;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) t.head.push_back(c);
  t.cols.assign(t.head.size(), {});
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::size_t k = 0;
    for (std::string c; std::getline(ls, c, ',') && k < t.cols.size(); ++k)
      t.cols[k].push_back(std::stod(c));
  }
  return t;
}

inline double max_of(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}
inline double min_of(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}

// Two 2D checkpoints hold the same time, step, module state (cluster, contact, output counters)
// and fields, bit for bit: a restart reproduced the uninterrupted run.
inline void expect_same_checkpoint(const std::string& a, const std::string& b) {
  Particles<2> pa, pb;
  auto ma = read_checkpoint<2>(a, pa);
  auto mb = read_checkpoint<2>(b, pb);
  EXPECT_EQ(ma.time, mb.time);
  EXPECT_EQ(ma.step, mb.step);
  EXPECT_EQ(ma.scalars, mb.scalars);
  ASSERT_EQ(pa.size(), pb.size());
  for (const auto& f : pa.fields()) {
    const auto& g = pb.field(f.name);
    EXPECT_EQ(f.real, g.real) << f.name;
    EXPECT_EQ(f.ints, g.ints) << f.name;
  }
}

}  // namespace monosph::test
