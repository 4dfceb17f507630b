#pragma once
#include <string>
#include <vector>

namespace monosph {
// `monosph info`: particle counts per body, modules, memory estimate; with `config` the parsed
// configuration as JSON instead (every value the run uses). Returns the exit code.
int print_info(const std::string& scene, const std::vector<std::string>& overrides,
               bool config = false);
}  // namespace monosph
