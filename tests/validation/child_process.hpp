#pragma once
// A run started as a child process, for the tests that signal it: start, wait for a file it
// writes, signal it, wait for its exit. Every wait polls with a generous time limit; no sleep
// decides a test.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../output_files.hpp"

namespace monosph::test {

struct Child {
  pid_t pid = -1;
  int code = -1;  // exit code, 128 + signal when a signal ended it (as a shell reports it)
  bool done = false;
};

// Runs `cmd` (a shell command line) with its output into `log`; the child is the command itself
// (sh -c exec), so a signal sent to pid reaches it.
inline Child start_child(const std::string& cmd, const std::string& log) {
  const std::string line = "exec " + cmd + " >" + log + " 2>&1";
  Child c;
  c.pid = fork();
  if (c.pid == 0) {
    execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return c;
}

// True once the child has exited (code set).
inline bool reap(Child& c) {
  if (c.done) return true;
  int st = 0;
  if (waitpid(c.pid, &st, WNOHANG) != c.pid) return false;
  c.done = true;
  c.code = WIFEXITED(st) ? WEXITSTATUS(st) : WIFSIGNALED(st) ? 128 + WTERMSIG(st) : -1;
  return true;
}

inline void pause_ms(int ms) {
  std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

// Waits until `file` exists (true), the child has exited (false) or the time limit is over.
inline bool wait_for_file(Child& c, const std::filesystem::path& file, double limit_s = 120) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (std::chrono::steady_clock::now() < end) {
    if (std::filesystem::exists(file)) return true;
    if (reap(c)) return std::filesystem::exists(file);
    pause_ms(2);
  }
  return false;
}

// Waits for the child's exit; after the time limit it is killed and the code is -1.
inline int wait_exit(Child& c, double limit_s = 300) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (!reap(c)) {
    if (std::chrono::steady_clock::now() > end) {
      kill(c.pid, SIGKILL);
      waitpid(c.pid, nullptr, 0);
      ADD_FAILURE() << "pid " << c.pid << " did not end within " << limit_s << " s";
      return -1;
    }
    pause_ms(5);
  }
  return c.code;
}

// The processes whose parent is `pid` (the ranks mpirun started).
inline std::vector<pid_t> children_of(pid_t pid) {
  std::vector<pid_t> out;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string stat;
    std::getline(in, stat);
    const auto close = stat.rfind(')');  // "pid (comm) state ppid ..."
    if (close == std::string::npos) continue;
    char state = 0;
    long ppid = 0;
    if (std::sscanf(stat.c_str() + close + 1, " %c %ld", &state, &ppid) == 2 && ppid == pid)
      out.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return out;
}

// Whether a process `pid` is still there (not yet reaped: a zombie counts as gone).
inline bool alive(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return false;
  const auto close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z';
}

inline std::string log_of(const std::string& dir) {
  return dir + ".log";
}

// Starts `cmd`, waits for dir/checkpoint.h5 and calls send(child); returns the exit code. A run
// that ended before the signal (the test was not scheduled for the whole run) starts again.
template <class Send>
int interrupt_run(const std::string& cmd, const std::string& dir, Send send) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::filesystem::remove_all(dir);
    Child c = start_child(cmd, log_of(dir));
    if (!wait_for_file(c, dir + "/checkpoint.h5")) {
      wait_exit(c);
      ADD_FAILURE() << "no checkpoint.h5: " << file_text(log_of(dir));
      return -1;
    }
    if (!reap(c)) send(c);
    const int code = wait_exit(c);
    if (code != 0) return code;
  }
  ADD_FAILURE() << "the run ended before the signal three times";
  return -1;
}

inline std::string last_line(const std::string& text) {
  if (text.empty() || text.back() != '\n') return "(no final newline)";
  const auto start = text.rfind('\n', text.size() - 2);
  return text.substr(start == std::string::npos ? 0 : start + 1);
}

// Two files equal byte for byte, else the line where they first differ.
inline void expect_same_file(const std::string& a, const std::string& b) {
  const std::string ta = file_text(a), tb = file_text(b);
  if (ta == tb) return;
  std::size_t k = 0;
  while (k < ta.size() && k < tb.size() && ta[k] == tb[k]) ++k;
  ADD_FAILURE() << a << " (" << ta.size() << " bytes) and " << b << " (" << tb.size()
                << " bytes) differ from line " << std::count(ta.begin(), ta.begin() + k, '\n') + 1;
}

}  // namespace monosph::test
