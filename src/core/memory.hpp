#pragma once
// Memory of this process: heap bytes in use (glibc mallinfo2) and resident set sizes.
#include <cstddef>

namespace monosph {

std::size_t heap_in_use();          // bytes allocated by malloc/new and not yet freed
std::size_t resident_bytes();       // VmRSS now
std::size_t peak_resident_bytes();  // VmHWM: the largest resident set so far

}  // namespace monosph
