#pragma once
// Runs of the binary that must fail cleanly: the documented exit code (not a signal), one line
// of output, within a time limit, and no file left behind that claims success.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../validation/run_helpers.hpp"

namespace monosph::test {

constexpr int kTimeLimitSeconds = 60;  // per case (a case takes well under a second)

// `prefix` runs in the shell before the binary (e.g. "ulimit -f 40;").
inline Result run_limited(const std::string& args, const std::string& prefix = "") {
  return run_command(prefix + " timeout " + std::to_string(kTimeLimitSeconds) + " " + MONOSPH_BIN +
                     " " + args + " --threads 1 --quiet 2>&1");
}

// summary.json absent, or a complete JSON whose status is not "completed"; no final.h5 file.
inline void expect_nothing_claims_success(const std::string& out, bool final_may_exist = false) {
  namespace fs = std::filesystem;
  const fs::path s = fs::path(out) / "summary.json";
  if (fs::is_regular_file(s)) {
    std::ifstream in(s);
    const auto js = nlohmann::json::parse(in, nullptr, false);
    EXPECT_FALSE(js.is_discarded()) << s << " is not complete JSON";
    if (!js.is_discarded()) {
      EXPECT_NE(js.value("status", ""), "completed") << s;
    }
  }
  if (!final_may_exist) {
    EXPECT_FALSE(fs::is_regular_file(fs::path(out) / "final.h5")) << out;
  }
  for (const auto& e : fs::directory_iterator(out)) {
    if (e.is_regular_file()) {
      EXPECT_NE(e.path().extension(), ".tmp") << e.path() << " left behind";
    }
  }
}

// The run failed with `code` (a code 128 + n would be a signal, 124 the time limit) and one line
// that holds every fragment.
inline void expect_clean_failure(const Result& r, int code, const std::vector<std::string>& parts) {
  EXPECT_EQ(r.code, code) << r.output;
  for (const auto& p : parts) {
    EXPECT_NE(r.output.find(p), std::string::npos) << p << "\n" << r.output;
  }
  EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace monosph::test
