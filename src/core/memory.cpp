#include "core/memory.hpp"

#include <malloc.h>

#include <fstream>
#include <string>

namespace monosph {

namespace {
// A "VmXXX:   1234 kB" line of /proc/self/status, in bytes (0 where there is none).
std::size_t status_kb(const std::string& key) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return std::stoull(line.substr(key.size() + 1)) * 1024;
  return 0;
}
}  // namespace

std::size_t heap_in_use() {
  const struct mallinfo2 mi = mallinfo2();
  return mi.uordblks + mi.hblkhd;  // arena chunks in use + mmapped blocks
}

std::size_t resident_bytes() {
  return status_kb("VmRSS");
}

std::size_t peak_resident_bytes() {
  return status_kb("VmHWM");
}

}  // namespace monosph
