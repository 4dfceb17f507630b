#include "core/input_file.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/types.hpp"

namespace fs = std::filesystem;

namespace monosph {

namespace {
std::string kind_of(fs::file_type t) {
  switch (t) {
    case fs::file_type::directory:
      return "it is a folder";
    case fs::file_type::character:
      return "it is a character device, not a regular file";
    case fs::file_type::block:
      return "it is a block device, not a regular file";
    case fs::file_type::fifo:
      return "it is a FIFO, not a regular file";
    case fs::file_type::socket:
      return "it is a socket, not a regular file";
    default:
      return "it is not a regular file";
  }
}
}  // namespace

void check_input_file(const std::string& file, const std::string& cannot,
                      std::uintmax_t max_bytes) {
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);  // through symbolic links
  if (!fs::exists(st)) throw InputError(cannot + " (no such file)");
  if (!fs::is_regular_file(st)) throw InputError(cannot + " (" + kind_of(st.type()) + ")");
  const std::uintmax_t size = fs::file_size(file, ec);
  if (!ec && max_bytes > 0 && size > max_bytes)
    throw InputError(fmt::format("{} (it has {} bytes, more than the limit of {} bytes)", cannot,
                                 size, max_bytes));
  if (!std::ifstream(file)) throw InputError(cannot + " (no permission to read it)");
}

std::string read_input_file(const std::string& file, const std::string& cannot,
                            std::uintmax_t max_bytes) {
  check_input_file(file, cannot, max_bytes);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(cannot + " (a read error)");
  return text.str();
}

}  // namespace monosph
