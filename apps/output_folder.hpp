#pragma once
// The --out folder of a run, held for the run's life: created, and locked (flock on `.lock`, which
// also names the pid), so that a second run into it stops with one line; the kernel drops the
// lock of a process that died, so a stale lock never blocks. A new run (not a restart) first
// removes the files that would claim an earlier run's result (summary.json, final.h5,
// checkpoint.h5); a restart removes summary.json.
#include <filesystem>

#include "parallel/comm.hpp"

namespace monosph {

class OutputFolder {
 public:
  // Collective (rank 0 locks); InputError on every rank when the folder is in use or unwritable.
  OutputFolder(const std::filesystem::path& dir, bool restart, const Comm& comm);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace monosph
