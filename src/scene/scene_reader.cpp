#include "scene/scene_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace monosph {

void scene_error(const std::string& path, const std::string& msg) {
  throw InputError((path.empty() ? std::string("scene") : path) + ": " + msg);
}

namespace {
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> d(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t prev = d[0];
    d[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cur = d[j];
      d[j] = std::min({d[j] + 1, d[j - 1] + 1, prev + (a[i - 1] != b[j - 1])});
      prev = cur;
    }
  }
  return d[b.size()];
}

std::string describe(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  return "a map";
}

// Names that differ only in their digits (D1, D2): neither is a misspelling of the other.
bool siblings(const std::string& a, const std::string& b) {
  auto letters = [](std::string s) {
    s.erase(std::remove_if(s.begin(), s.end(),
                           [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }),
            s.end());
    return s;
  };
  return a != b && letters(a) == letters(b);
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}
}  // namespace

std::string closest_word(const std::string& word, const std::vector<std::string>& options) {
  std::string best;
  std::size_t bd = 1000;
  for (const auto& o : options) {
    std::size_t d = edit_distance(word, o);
    if (d < bd) bd = d, best = o;
  }
  return bd <= std::max<std::size_t>(2, word.size() / 3) ? best : "";
}

double as_number(const YAML::Node& n, const std::string& path, const Constants* constants) {
  if (!n.IsScalar()) scene_error(path, "expected a number, got " + describe(n));
  double v;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    // yaml-cpp refuses an overflowing number (1e400): say that it is not finite.
    char* end = nullptr;
    const double d = std::strtod(n.Scalar().c_str(), &end);
    if (!n.Scalar().empty() && end && *end == '\0' && std::isinf(d))
      scene_error(path, "expected a finite number, got " + describe(n));
    if (!constants) scene_error(path, "expected a number, got " + describe(n));
    v = constant_expression(n.Scalar(), path, *constants);  // expression.cpp
    if (!std::isfinite(v))
      scene_error(path, "expected a finite number, got " + describe(n) + fmt::format(" (= {})", v));
  }
  if (!std::isfinite(v)) scene_error(path, "expected a finite number, got " + describe(n));
  return v;
}

std::string as_text(const YAML::Node& n, const std::string& path) {
  if (!n.IsScalar()) scene_error(path, "expected a text value, got " + describe(n));
  return n.Scalar();
}

std::vector<double> as_vector(const YAML::Node& n, const std::string& path, int size,
                              const Constants* constants) {
  if (!n.IsSequence() || static_cast<int>(n.size()) != size)
    scene_error(path, "expected a list of " + std::to_string(size) + " numbers, got " +
                          describe(n) + (n.IsSequence() ? " of " + std::to_string(n.size()) : ""));
  std::vector<double> v;
  for (std::size_t i = 0; i < n.size(); ++i)
    v.push_back(as_number(n[i], path + "[" + std::to_string(i) + "]", constants));
  return v;
}

MapReader::MapReader(const YAML::Node& node, std::string path, const Constants* constants)
    : node_(node), path_(std::move(path)), constants_(constants) {
  if (!node.IsMap()) scene_error(path_, "expected a map of keys, got " + describe(node));
}

bool MapReader::has(const std::string& key) const {
  return node_[key].IsDefined() && !node_[key].IsNull();
}

YAML::Node MapReader::node(const std::string& key) {
  used_.insert(key);
  if (!has(key)) {
    // A misspelt key may be the cause: name a close one that is given (not one read already,
    // nor a sibling such as D2 for D1).
    std::vector<std::string> present;
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      const std::string k = it->first.Scalar();
      if (!used_.count(k) && !siblings(k, key)) present.push_back(k);
    }
    const std::string hint = closest_word(key, present);
    // (A for B is no misspelling: the names must share more than they differ in.)
    if (!hint.empty() && hint != key &&
        edit_distance(hint, key) < std::min(hint.size(), key.size()))
      scene_error(at(hint), "unknown key; did you mean '" + key + "'? (" + key + " is required)");
    scene_error(at(key), "missing (required)");
  }
  return node_[key];
}

YAML::Node MapReader::optional(const std::string& key) {
  used_.insert(key);
  if (!has(key)) return YAML::Node();
  return node_[key];
}

double MapReader::number(const std::string& key) {
  return as_number(node(key), at(key), constants_);
}
// A plain number as written; an expression with its value ('2*seed' = -2).
std::string MapReader::shown(const std::string& key, double v) const {
  const YAML::Node n = node_[key];
  try {
    n.as<double>();
    return n.Scalar();
  } catch (const YAML::Exception&) {
    return fmt::format("'{}' = {}", n.Scalar(), v);
  }
}
double MapReader::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : (used_.insert(key), fallback);
}
double MapReader::positive(const std::string& key) {
  double v = number(key);
  if (!(v > 0)) scene_error(at(key), "must be positive, got " + shown(key, v));
  return v;
}
double MapReader::positive(const std::string& key, double fallback) {
  return has(key) ? positive(key) : (used_.insert(key), fallback);
}
double MapReader::non_negative(const std::string& key, double fallback) {
  if (!has(key)) return used_.insert(key), fallback;
  double v = number(key);
  if (v < 0) scene_error(at(key), "must not be negative, got " + shown(key, v));
  return v;
}
int MapReader::integer(const std::string& key, int fallback) {
  if (!has(key)) return used_.insert(key), fallback;
  double v = number(key);
  if (v != std::floor(v)) scene_error(at(key), "expected a whole number, got " + shown(key, v));
  if (std::abs(v) > 2147483647.0)
    scene_error(at(key), "must lie within +-2147483647, got " + shown(key, v));
  return static_cast<int>(v);
}
bool MapReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return used_.insert(key), fallback;
  auto n = node(key);
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    scene_error(at(key), "expected true or false, got " + describe(n));
  }
}
std::string MapReader::text(const std::string& key) {
  return as_text(node(key), at(key));
}
std::string MapReader::text(const std::string& key, const std::string& fallback) {
  return has(key) ? text(key) : (used_.insert(key), fallback);
}
std::string MapReader::choice(const std::string& key, const std::vector<std::string>& options,
                              const std::string& fallback) {
  std::string v = fallback.empty() ? text(key) : text(key, fallback);
  if (std::find(options.begin(), options.end(), v) == options.end()) {
    std::string hint = closest_word(v, options);
    scene_error(at(key), "'" + v + "' is not allowed (allowed: " + join(options) + ")" +
                             (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
  return v;
}
std::vector<double> MapReader::vector(const std::string& key, int size) {
  return as_vector(node(key), at(key), size, constants_);
}
std::vector<std::string> MapReader::strings(const std::string& key) {
  auto n = node(key);
  std::vector<std::string> out;
  if (n.IsScalar()) return {n.Scalar()};
  if (!n.IsSequence()) scene_error(at(key), "expected a list, got " + describe(n));
  for (std::size_t i = 0; i < n.size(); ++i)
    out.push_back(as_text(n[i], at(key) + "[" + std::to_string(i) + "]"));
  return out;
}

void MapReader::finish() {
  std::vector<std::string> allowed(used_.begin(), used_.end());
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    std::string key = it->first.Scalar();
    if (used_.count(key)) continue;
    std::string hint = closest_word(key, allowed);
    scene_error(at(key), "unknown key (allowed: " + join(allowed) + ")" +
                             (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
}

}  // namespace monosph
