#include "output/probe_csv.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <limits>
#include <sstream>
#include <string_view>

#include "core/input_file.hpp"
#include "core/types.hpp"
#include "output/atomic_file.hpp"

namespace fs = std::filesystem;

namespace monosph {

namespace {

std::string header_of(const std::vector<std::string>& columns) {
  std::string h = "time,step";
  for (const auto& c : columns) h += "," + c;
  return h;
}

// A whole cell as a number (nan and inf as fmt writes them included).
bool parse_number(std::string_view s, double& v) {
  if (s.empty()) return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

std::size_t probe_csv_prefix(const std::string& text, const std::string& header, std::size_t ncols,
                             long rows, double time, const std::string& file, long& kept) {
  auto fail = [&](const std::string& why) {
    throw InputError(
        fmt::format("{}: {}; a restart continues the file of its own run (restart "
                    "into another --out folder, or move the file away)",
                    file, why));
  };
  std::size_t pos = text.find('\n');
  if (pos == std::string::npos || text.compare(0, pos, header) != 0)
    fail("its header is not this run's columns");
  ++pos;
  kept = 0;
  for (long line = 2; rows < 0 || kept < rows; ++line) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) {  // the end, or a partly written last row
      if (rows < 0) break;
      fail(fmt::format("{} complete rows, the checkpoint counted {} (rows missing)", kept, rows));
    }
    const std::string_view row(text.data() + pos, end - pos);
    std::size_t n = 0, start = 0;
    double t = 0, v = 0;
    bool ok = true;
    for (; ok && start <= row.size(); ++n) {
      std::size_t comma = row.find(',', start);
      if (comma == std::string_view::npos) comma = row.size();
      ok = parse_number(row.substr(start, comma - start), n == 0 ? t : v);
      start = comma + 1;
    }
    if (!ok || n != ncols) {
      if (rows < 0) break;
      fail(fmt::format("line {} is malformed", line));
    }
    if (!(t <= time)) {
      if (rows < 0) break;
      fail(fmt::format("line {} is later (t = {:.17g}) than the checkpoint (t = {:.17g})", line, t,
                       time));
    }
    pos = end + 1;
    ++kept;
  }
  return pos;
}

// A failed write (disk full...): OutputError (exit code 6) on every rank.
void ProbeCsv::check(bool ok, const std::string& what) {
  const std::string err = comm_.first_message(ok ? ""
                                                 : "output: cannot write " + path_.string() + ": " +
                                                       io_error_text("write failed") + what);
  if (!err.empty()) throw OutputError(err);
}

void ProbeCsv::create(const fs::path& file, const std::vector<std::string>& columns) {
  path_ = file;
  rows_ = 0;
  bool opened = true;
  if (comm_.root()) {
    out_.open(file, std::ios::trunc);
    opened = out_.is_open();
    errno = 0;
    out_ << header_of(columns) << "\n";
    out_.flush();
  }
  // A file that cannot be created: bad output folder (InputError, exit code 2).
  const std::string err =
      comm_.first_message(opened ? "" : "output: cannot write " + file.string());
  if (!err.empty()) throw InputError(err);
  check(!comm_.root() || bool(out_), "");
}

void ProbeCsv::resume(const fs::path& file, const fs::path& from,
                      const std::vector<std::string>& columns, long rows, double time) {
  path_ = file;
  std::string err;
  double kept = 0;
  if (comm_.root()) {
    try {
      std::error_code ec;
      const bool here = fs::exists(file, ec);
      const fs::path src = here ? file : from;
      long k = 0;
      if (here || (!from.empty() && fs::exists(from, ec))) {
        const std::string text =  // a FIFO or device there would block the restart
            read_input_file(src.string(), "restart: cannot read " + src.string(), 0);
        const std::size_t keep = probe_csv_prefix(text, header_of(columns), columns.size() + 2,
                                                  rows, time, src.string(), k);
        if (here) {
          fs::resize_file(file, keep, ec);
          if (ec) throw InputError("output: cannot write " + file.string() + ": " + ec.message());
          out_.open(file, std::ios::app);
        } else {
          out_.open(file, std::ios::trunc);
          out_.write(text.data(), static_cast<std::streamsize>(keep));
        }
      } else {  // no rows to continue: the rows from the restart on
        out_.open(file, std::ios::trunc);
        out_ << header_of(columns) << "\n";
        k = rows < 0 ? 0 : rows;
      }
      out_.flush();
      if (!out_) throw InputError("output: cannot write " + file.string());
      kept = static_cast<double>(k);
    } catch (const InputError& e) {
      err = e.what();
    }
  }
  err = comm_.first_message(err);
  if (!err.empty()) throw InputError(err);
  comm_.bcast(std::span<double>(&kept, 1), 0);
  rows_ = static_cast<long>(kept);
}

void ProbeCsv::row(double time, long step, const std::vector<double>& values) {
  ++rows_;
  if (!comm_.root()) return;
  std::string line = fmt::format("{:.17g},{}", time, step);
  for (double v : values) line += fmt::format(",{:.17g}", v);
  line += '\n';
  out_ << line;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_flush_ > std::chrono::seconds(1)) out_.flush(), last_flush_ = now;
}

void ProbeCsv::flush() {
  errno = 0;
  if (comm_.root()) out_.flush();
  check(!comm_.root() || bool(out_), "");
}

void ProbeCsv::close() {
  errno = 0;
  if (comm_.root() && out_.is_open()) out_.close();
  check(!comm_.root() || bool(out_), "");
}

void read_probe_table(const fs::path& file, std::vector<std::string>& head,
                      std::vector<std::vector<double>>& cols) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) return;
  head.clear();
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) head.push_back(c);
  cols.assign(head.size(), {});
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::size_t k = 0;
    for (std::string c; k < cols.size(); ++k) {
      double v = std::numeric_limits<double>::quiet_NaN();
      if (std::getline(ls, c, ',') && !parse_number(c, v))
        v = std::numeric_limits<double>::quiet_NaN();
      cols[k].push_back(v);
    }
  }
}

}  // namespace monosph
