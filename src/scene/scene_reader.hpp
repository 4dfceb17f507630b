#pragma once
// Strict YAML map reader: every read is checked and every key must be known. Errors are one
// line: "<path>: <problem> (<what is allowed>)".
#include <yaml-cpp/yaml.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace monosph {

[[noreturn]] void scene_error(const std::string& path, const std::string& msg);
std::string closest_word(const std::string& word, const std::vector<std::string>& options);

class MapReader {
 public:
  MapReader(const YAML::Node& node, std::string path);
  const std::string& path() const { return path_; }
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
  YAML::Node node_;
  std::string path_;
  std::set<std::string> used_;
};

// scene_yaml.cpp: the first document of a YAML text; aliases that form a cycle or expand it by
// more than a million nodes are refused, merge keys (<<) resolved. `origin` names the file.
YAML::Node parse_scene_yaml(const std::string& text, const std::string& origin);

// Every map key of the tree a plain, unique name, every text valid UTF-8 (yaml-cpp accepts
// complex keys and keeps both entries of a key given twice). `origin` names the file.
void check_yaml_tree(const YAML::Node& root, const std::string& origin);

// Scalar conversion with a path-naming error.
double as_number(const YAML::Node& n, const std::string& path);
std::string as_text(const YAML::Node& n, const std::string& path);
std::vector<double> as_vector(const YAML::Node& n, const std::string& path, int size);

}  // namespace monosph
