#pragma once
// Reading what a run wrote, for the unit and run tests: a whole file, the frames of a .pvd.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace monosph::test {

inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct PvdEntry {
  double time;
  std::string file;
};
inline std::vector<PvdEntry> read_pvd(const std::filesystem::path& file) {
  const std::string text = file_text(file);
  std::vector<PvdEntry> out;
  std::regex re(R"re(<DataSet[^>]*timestep="([^"]*)"[^>]*file="([^"]*)")re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    out.push_back({std::stod((*it)[1].str()), (*it)[2].str()});
  return out;
}

}  // namespace monosph::test
