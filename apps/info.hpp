#pragma once
#include <string>
#include <vector>

namespace monosph {
// `monosph info`: particle counts per body, modules, memory estimate. Returns the exit code.
int print_info(const std::string& scene, const std::vector<std::string>& overrides);
}  // namespace monosph
