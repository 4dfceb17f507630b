#pragma once
// Runs of the monosph binary in child processes, several at a time (study, stability).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace monosph {

struct ChildRun {
  std::vector<std::string> args;  // arguments after the program name
  std::filesystem::path log;      // stdout and stderr of the run
  int code = -1;                  // exit code (-1: killed by a signal)
};

// This executable (/proc/self/exe): children run the same build.
std::string self_executable();

// Runs every job, at most `parallel` at once; `done(k)` is called as job k ends.
void run_children(std::vector<ChildRun>& jobs, int parallel,
                  const std::function<void(std::size_t)>& done);

// The first "monosph: ..." line of a log (the error of a failed run), or "".
std::string first_message(const std::filesystem::path& log);

}  // namespace monosph
