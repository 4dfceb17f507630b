#pragma once
// probes.csv, the probe series of a run: `time,step,<columns>`, one row per sample, written by
// rank 0. It is flushed at every checkpoint, which stores the number of rows: a restart keeps
// exactly those rows (their bytes as written) and appends after them, so a run stopped in any way
// and restarted from a checkpoint writes the file of the uninterrupted run.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "parallel/comm.hpp"

namespace monosph {

class ProbeCsv {
 public:
  // Every rank counts the rows; rank 0 writes them.
  explicit ProbeCsv(const Comm& comm) : comm_(comm) {}
  // A new file holding the header (collective; InputError when it cannot be created,
  // OutputError when the header cannot be written).
  void create(const std::filesystem::path& file, const std::vector<std::string>& columns);
  // A restart: continues `file` after its first `rows` data rows (rows < 0, a checkpoint that did
  // not count them: the complete rows with time <= `time`). When `file` does not exist, the rows
  // come from `from` (probes.csv next to the checkpoint), else the file starts anew. InputError
  // (one line naming the file and the line) when the file is not this run's: other columns, a
  // malformed row or fewer rows than the checkpoint counted. Collective.
  void resume(const std::filesystem::path& file, const std::filesystem::path& from,
              const std::vector<std::string>& columns, long rows, double time);
  // Rank 0 also writes the buffer out about once a second (a user can follow the run).
  void row(double time, long step, const std::vector<double>& values);
  long rows() const { return rows_; }
  // Collective: the rows are in the file (OutputError on every rank when a write failed: disk
  // full, exit code 6).
  void flush();
  void close();

 private:
  void check(bool ok, const std::string& what);
  const Comm& comm_;
  std::filesystem::path path_;
  std::ofstream out_;
  long rows_ = 0;
  std::chrono::steady_clock::time_point last_flush_ = std::chrono::steady_clock::now();
};

// The bytes of `text` (a probe CSV) to keep on a restart: the header line, which must equal
// `header`, and `rows` data rows (rows < 0: the leading complete rows with time <= `time`), each
// complete (ends with a newline), with `ncols` numbers and time <= `time`. InputError naming
// `file` otherwise. Also returns the number of rows kept.
std::size_t probe_csv_prefix(const std::string& text, const std::string& header, std::size_t ncols,
                             long rows, double time, const std::string& file, long& kept);

// Reads a probe CSV (header, then numbers) for the metrics; a malformed cell reads as NaN.
void read_probe_table(const std::filesystem::path& file, std::vector<std::string>& head,
                      std::vector<std::vector<double>>& cols);

}  // namespace monosph
