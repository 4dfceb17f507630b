#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "core/types.hpp"

namespace monosph {
namespace fs = std::filesystem;

namespace {

std::string errno_text() {
  return std::strerror(errno);
}

// Writes all of text to fd; false (errno set) on any failure.
bool write_all(int fd, std::string_view text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) errno = EIO;
    if (n <= 0) return false;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void cannot_write_file(const fs::path& file, const std::string& reason) {
  throw OutputError("output: cannot write " + file.string() + ": " + reason);
}

fs::path temporary_name(const fs::path& file) {
  fs::path tmp = file;
  tmp += ".tmp";
  return tmp;
}

namespace {

// Renames tmp to file, or removes tmp and throws (also when err already holds a failure).
void rename_into(const fs::path& tmp, const fs::path& file, std::string err) {
  std::error_code ec;
  if (err.empty()) {
    fs::rename(tmp, file, ec);
    if (!ec) return;
    err = ec.message();
  }
  fs::remove(tmp, ec);
  cannot_write_file(file, err);
}

}  // namespace

void commit_file(const fs::path& tmp, const fs::path& file, bool sync) {
  std::string err;
  if (sync) {
    const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) err = errno_text();
    if (fd >= 0) ::close(fd);
  }
  rename_into(tmp, file, err);
}

void write_file_atomic(const fs::path& file, std::string_view text, bool sync) {
  const fs::path tmp = temporary_name(file);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) cannot_write_file(file, errno_text());
  std::string err;
  if (!write_all(fd, text) || (sync && ::fsync(fd) != 0)) err = errno_text();
  if (::close(fd) != 0 && err.empty()) err = errno_text();
  rename_into(tmp, file, err);
}

std::string io_error_text(const std::string& fallback) {
  const int e = errno;
  if (e == ENOSPC || e == EFBIG || e == EDQUOT || e == EIO || e == EROFS) return std::strerror(e);
  return fallback;
}

void check_stream(std::ostream& s, const fs::path& file) {
  errno = 0;
  s.flush();
  if (!s) cannot_write_file(file, io_error_text("write failed"));
}

}  // namespace monosph
