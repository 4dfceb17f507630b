#include "processes.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

namespace monosph {
namespace fs = std::filesystem;

std::string self_executable() {
  return fs::read_symlink("/proc/self/exe").string();
}

namespace {
pid_t start(const std::string& self, const ChildRun& r) {
  std::vector<std::string> args = {self};
  args.insert(args.end(), r.args.begin(), r.args.end());
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    FILE* f = std::fopen(r.log.c_str(), "w");
    if (f) dup2(fileno(f), 1), dup2(fileno(f), 2);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(self.c_str(), argv.data());
    _exit(127);
  }
  if (pid < 0) throw std::runtime_error("cannot start a run (fork failed)");
  return pid;
}
}  // namespace

void run_children(std::vector<ChildRun>& jobs, int parallel,
                  const std::function<void(std::size_t)>& done) {
  const std::string self = self_executable();
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, finished = 0;
  while (finished < jobs.size()) {
    while (next < jobs.size() && static_cast<int>(running.size()) < parallel)
      running[start(self, jobs[next])] = next, ++next;
    int st = 0;
    const pid_t pid = waitpid(-1, &st, 0);
    if (pid < 0) break;
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t k = it->second;
    running.erase(it);
    ++finished;
    jobs[k].code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    done(k);
  }
}

std::string first_message(const fs::path& log) {
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("monosph:", 0) == 0) return line;
  return "";
}

}  // namespace monosph
