#include "scene/scene_variables.hpp"

#include <algorithm>
#include <cctype>

namespace monosph {

namespace {
// Names an expression already gives a meaning to (coordinates, time, constants, muparser's
// built-in functions, our uniform(seed, stream)).
const std::vector<std::string> kReserved = {
    "x",    "y",    "z",    "t",    "pi",    "e",     "sin",   "cos",  "tan",   "asin",   "acos",
    "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "log2", "log10", "log",    "ln",
    "exp",  "sqrt", "sign", "rint", "abs",   "min",   "max",   "sum",  "avg",   "uniform"};

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::string declared_list(const YAML::Node& vars) {
  std::string s;
  if (vars && vars.IsMap())
    for (auto it = vars.begin(); it != vars.end(); ++it)
      s += (s.empty() ? "" : ", ") + it->first.as<std::string>();
  return s.empty() ? "none" : s;
}
}  // namespace

Constants read_variables(MapReader& root) {
  Constants c;
  if (!root.has("variables")) return root.optional("variables"), c;
  const YAML::Node n = root.node("variables");
  if (!n.IsMap()) scene_error("variables", "expected a map of names to numbers, e.g. {angle: 30}");
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = it->first.as<std::string>();
    const std::string path = "variables." + name;
    if (!identifier(name))
      scene_error(path, "a variable name is a letter or _ followed by letters, digits or _");
    if (std::find(kReserved.begin(), kReserved.end(), name) != kReserved.end())
      scene_error(path, "'" + name +
                            "' already has a meaning in expressions (x, y, z, t, pi, e, "
                            "uniform and muparser's functions are reserved)");
    c[name] = as_number(it->second, path, nullptr);  // plain numbers
  }
  return c;
}

void check_variable_override(const YAML::Node& root, const std::string& item) {
  const std::string prefix = "variables.";
  if (item.compare(0, prefix.size(), prefix) != 0) return;
  const auto eq = item.find('=');
  const std::string name =
      item.substr(prefix.size(), eq == std::string::npos ? std::string::npos : eq - prefix.size());
  const YAML::Node vars = root["variables"];
  if (vars && vars.IsMap() && vars[name].IsDefined()) return;
  std::vector<std::string> names;
  if (vars && vars.IsMap())
    for (auto it = vars.begin(); it != vars.end(); ++it)
      names.push_back(it->first.as<std::string>());
  const std::string hint = closest_word(name, names);
  throw InputError("--set " + item.substr(0, eq) + ": the scene declares no variable '" + name +
                   "' (variables: " + declared_list(vars) + ")" +
                   (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
}

}  // namespace monosph
