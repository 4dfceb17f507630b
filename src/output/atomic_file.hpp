#pragma once
// Output files that scripts read (summary.json, .pvd, frames, checkpoints) are written
// atomically: to FILE.tmp in the same folder, every write checked, fsync (sync = true), then
// renamed over FILE. A failed write removes the temporary and leaves any earlier FILE as it was,
// never an empty or half file. Frames and the .pvd skip the fsync (a frame per output time).
#include <filesystem>
#include <ostream>
#include <string_view>

namespace monosph {

// Writes text to file atomically; throws OutputError("output: cannot write FILE: reason").
void write_file_atomic(const std::filesystem::path& file, std::string_view text, bool sync = true);

// The temporary name write_file_atomic uses for file (FILE.tmp).
std::filesystem::path temporary_name(const std::filesystem::path& file);

// Flushes tmp to disk (sync) and renames it to file; on failure removes tmp and throws
// OutputError.
void commit_file(const std::filesystem::path& tmp, const std::filesystem::path& file,
                 bool sync = true);

// Flushes s (the stream of file) and throws OutputError naming file if a write to it failed.
void check_stream(std::ostream& s, const std::filesystem::path& file);

// The reason of a failed write: strerror(errno) for an I/O error (disk full, file too large...),
// otherwise `fallback`.
std::string io_error_text(const std::string& fallback);

// "output: cannot write FILE: reason"
[[noreturn]] void cannot_write_file(const std::filesystem::path& file, const std::string& reason);

}  // namespace monosph
