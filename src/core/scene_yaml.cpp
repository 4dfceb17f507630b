// The scene's YAML: parsing, checks of the whole tree, and the command line's --set overrides.
#include <sstream>

#include "scene_parts.hpp"

namespace monosph {

YAML::Node parse_scene_yaml(const std::string& text, const std::string& origin) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(origin + ": invalid YAML at line " + std::to_string(e.mark.line + 1) +
                     ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

void apply_override(YAML::Node& root, const std::string& item) {
  auto eq = item.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + item + ": expected key=value, e.g. --set end_time=0.1");
  std::string key = item.substr(0, eq), value = item.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  YAML::Node value_node;
  try {
    value_node = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + item + ": invalid value: " + e.msg);
  }
  // Walk with explicit node copies (yaml-cpp nodes are handles).
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node cur = chain.back();
    const std::string& k = parts[i];
    if (cur.IsSequence()) {
      std::size_t idx;
      try {
        idx = std::stoul(k);
      } catch (...) {
        throw InputError("--set " + key + ": '" + k + "' must be a list index");
      }
      if (idx >= cur.size()) throw InputError("--set " + key + ": index " + k + " out of range");
      chain.push_back(cur[idx]);
    } else {
      if (!cur[k].IsDefined() || cur[k].IsNull()) cur[k] = YAML::Node(YAML::NodeType::Map);
      chain.push_back(cur[k]);
    }
  }
  YAML::Node last = chain.back();
  const std::string& k = parts.back();
  if (last.IsSequence()) {
    std::size_t idx = std::stoul(k);
    if (idx >= last.size()) throw InputError("--set " + key + ": index " + k + " out of range");
    last[idx] = value_node;
  } else {
    last[k] = value_node;
  }
}

}  // namespace monosph
