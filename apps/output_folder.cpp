#include "output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "core/types.hpp"

namespace fs = std::filesystem;

namespace monosph {

namespace {

// Locks dir/.lock for this process (fd), or returns the one-line reason it cannot.
std::string lock(const fs::path& dir, bool restart, int& fd) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path file = dir / ".lock";
  fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    return "output: cannot write to directory " + dir.string() + " (" + std::strerror(errno) + ")";
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    char pid[32] = {};
    const ssize_t n = ::pread(fd, pid, sizeof pid - 1, 0);
    ::close(fd), fd = -1;
    if (err != EWOULDBLOCK)
      return "output: cannot lock " + file.string() + ": " + std::strerror(err);
    std::string who = n > 0 ? std::string(pid, static_cast<std::size_t>(n)) : "";
    while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
    return "output: " + dir.string() + " is in use by another run" +
           (who.empty() ? "" : " (pid " + who + ")") +
           "; choose another --out folder or wait until that run ends";
  }
  const std::string me = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, me.data(), me.size(), 0) < 0)
    return "output: cannot write " + file.string() + ": " + std::strerror(errno);
  // The files that would claim an earlier run's result (a restart may start from final.h5).
  for (const char* f : {"summary.json", "final.h5", "checkpoint.h5"}) {
    if (restart && std::string(f) != "summary.json") continue;
    fs::remove(dir / f, ec);
    if (ec) return "output: cannot remove " + (dir / f).string() + ": " + ec.message();
  }
  return "";
}

}  // namespace

OutputFolder::OutputFolder(const fs::path& dir, bool restart, const Comm& comm) {
  std::string err;
  if (comm.root()) err = lock(dir, restart, fd_);
  err = comm.first_message(err);
  if (!err.empty()) {
    if (fd_ >= 0) ::close(fd_), fd_ = -1;
    throw InputError(err);
  }
}

OutputFolder::~OutputFolder() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace monosph
