#pragma once
// Strict YAML map reader: every read is checked and every key must be known. Errors are one
// line: "<path>: <problem> (<what is allowed>)". A number key may be an expression of the
// scene's variables (the `constants` a reader is given; null: plain numbers only), e.g.
// center: ["2e-5*(uniform(seed,1)-0.5)", 5.5e-5]; the context is explicit: every reader and
// every as_number call names its constants.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "scene/expression.hpp"

namespace monosph {

[[noreturn]] void scene_error(const std::string& path, const std::string& msg);
std::string closest_word(const std::string& word, const std::vector<std::string>& options);

class MapReader {
 public:
  MapReader(const YAML::Node& node, std::string path, const Constants* constants);
  const std::string& path() const { return path_; }
  // The names number keys may use (null: none); a reader of a sub-map passes them on.
  const Constants* constants() const { return constants_; }
  void set_constants(const Constants* constants) { constants_ = constants; }
  std::string at(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) const;
  YAML::Node node(const std::string& key);      // required
  YAML::Node optional(const std::string& key);  // null if absent

  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  double positive(const std::string& key);
  double positive(const std::string& key, double fallback);
  double non_negative(const std::string& key, double fallback);
  int integer(const std::string& key, int fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string text(const std::string& key);
  std::string text(const std::string& key, const std::string& fallback);
  std::string choice(const std::string& key, const std::vector<std::string>& options,
                     const std::string& fallback = "");
  std::vector<double> vector(const std::string& key, int size);
  std::vector<std::string> strings(const std::string& key);  // list of scalars (or one scalar)

  // Fails on any key that was not read: "unknown key (allowed: ...); did you mean ...?".
  void finish();

 private:
  std::string shown(const std::string& key, double v) const;  // value for a range message

  YAML::Node node_;
  std::string path_;
  std::set<std::string> used_;
  const Constants* constants_ = nullptr;
};

// scene_yaml.cpp: the first document of a YAML text; aliases that form a cycle or expand it by
// more than a million nodes are refused, merge keys (<<) resolved. `origin` names the file.
YAML::Node parse_scene_yaml(const std::string& text, const std::string& origin);

// Every map key of the tree a plain, unique name, every text valid UTF-8 (yaml-cpp accepts
// complex keys and keeps both entries of a key given twice). `origin` names the file.
void check_yaml_tree(const YAML::Node& root, const std::string& origin);

// Scalar conversion with a path-naming error. A number that is not one is evaluated as an
// expression of `constants` when given (null: plain numbers only, as the variables themselves).
double as_number(const YAML::Node& n, const std::string& path, const Constants* constants);
std::string as_text(const YAML::Node& n, const std::string& path);
std::vector<double> as_vector(const YAML::Node& n, const std::string& path, int size,
                              const Constants* constants);

}  // namespace monosph
