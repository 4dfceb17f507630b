// The scene's YAML: parsing, checks of the whole tree, and the command line's --set overrides.
#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>

#include <cstdint>
#include <map>
#include <sstream>
#include <utility>

#include "scene/scene_parts.hpp"

namespace monosph {

namespace {

// Anchors and aliases, checked on the parser's events before a tree is built: yaml-cpp builds an
// alias as a shared node, so an alias inside the block it names makes a cycle that every pass
// over the tree would follow without end, and nested aliases ("billion laughs": nine references a
// level) make a tree that every pass visits in full. Each alias is counted here once, at the
// size of the block it names.
class AliasCheck : public YAML::EventHandler {
 public:
  static constexpr double kMaxAliasNodes = 1e6;  // nodes that aliases may add to the written ones
  explicit AliasCheck(std::string origin) : origin_(std::move(origin)) {}
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t a) override { leaf(a); }
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t a,
                const std::string&) override {
    leaf(a);
  }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t a) override {
    for (const auto& f : open_)
      if (f.anchor == a)
        fail(m, "an alias refers to the block that contains it (line " +
                    std::to_string(f.line + 1) + "): the scene would be endless");
    added_ += size_[a];
    if (added_ > kMaxAliasNodes)
      fail(m, fmt::format("aliases expand the scene by more than {:.0f} nodes; write the "
                          "repeated block out or nest fewer aliases",
                          kMaxAliasNodes));
    count(size_[a]);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t a,
                       YAML::EmitterStyle::value) override {
    open_.push_back({a, m.line, 1});
  }
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t a,
                  YAML::EmitterStyle::value) override {
    open_.push_back({a, m.line, 1});
  }
  void OnSequenceEnd() override { close(); }
  void OnMapEnd() override { close(); }

 private:
  struct Block {
    YAML::anchor_t anchor;
    int line;
    double nodes;  // with the blocks its aliases name
  };
  void leaf(YAML::anchor_t a) {
    if (a) size_[a] = 1;
    count(1);
  }
  void count(double n) {
    if (!open_.empty()) open_.back().nodes += n;
  }
  void close() {
    const Block b = open_.back();
    open_.pop_back();
    if (b.anchor) size_[b.anchor] = b.nodes;
    count(b.nodes);
  }
  [[noreturn]] void fail(const YAML::Mark& m, const std::string& msg) const {
    throw InputError(origin_ + ": line " + std::to_string(m.line + 1) + ": " + msg);
  }
  std::string origin_;
  std::vector<Block> open_;
  std::map<YAML::anchor_t, double> size_;
  double added_ = 0;
};

// `<<` (the YAML merge key, which yaml-cpp leaves as a plain key): the keys of the map, or of
// each map of the list, that it names are added where the map does not give them itself (earlier
// maps of the list first). The tree has no cycles (AliasCheck).
void merge_keys(YAML::Node n) {
  if (n.IsSequence())
    for (std::size_t i = 0; i < n.size(); ++i) merge_keys(n[i]);
  if (!n.IsMap()) return;
  YAML::Node from;
  for (auto it = n.begin(); it != n.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == "<<" && it->first.Tag() != "!")
      from = it->second;
    else
      merge_keys(it->second);
  }
  if (!from || !(from.IsMap() || from.IsSequence())) return;  // reported as an unknown key
  std::vector<YAML::Node> maps;
  if (from.IsMap()) maps.push_back(from);
  for (std::size_t i = 0; from.IsSequence() && i < from.size(); ++i) maps.push_back(from[i]);
  for (auto& m : maps) {
    if (!m.IsMap()) return;  // a list of something else: left for the checks to name
    merge_keys(m);
  }
  n.remove("<<");
  for (const auto& m : maps)
    for (auto it = m.begin(); it != m.end(); ++it)
      if (it->first.IsScalar() && !std::as_const(n)[it->first.Scalar()])
        n[it->first.Scalar()] = it->second;
}

// The first document of the text (the one YAML::Load reads), aliases checked, merge keys resolved.
YAML::Node load_checked(const std::string& text, const std::string& origin) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  AliasCheck aliases(origin);
  parser.HandleNextDocument(aliases);
  YAML::Node root = YAML::Load(text);
  merge_keys(root);
  return root;
}

}  // namespace

YAML::Node parse_scene_yaml(const std::string& text, const std::string& origin) {
  try {
    return load_checked(text, origin);
  } catch (const YAML::ParserException& e) {
    throw InputError(origin + ": invalid YAML at line " + std::to_string(e.mark.line + 1) +
                     ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

namespace {

std::string kind_of(const YAML::Node& n) {
  return n.IsSequence() ? "a list" : n.IsMap() ? "a map" : "nothing";
}

// Valid UTF-8: no stray continuation bytes, overlong forms, surrogates or code points above
// U+10FFFF (JSON, the file system and ParaView take nothing else).
bool valid_utf8(const std::string& s) {
  std::size_t i = 0;
  const std::size_t n = s.size();
  while (i < n) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int len = c < 0x80           ? 1
                    : (c >> 5) == 0x6  ? 2
                    : (c >> 4) == 0xE  ? 3
                    : (c >> 3) == 0x1E ? 4
                                       : 0;
    if (len == 0 || i + len > n) return false;
    std::uint32_t cp = len == 1 ? c : c & (0x7F >> len);
    for (int k = 1; k < len; ++k) {
      const auto d = static_cast<unsigned char>(s[i + k]);
      if ((d >> 6) != 0x2) return false;
      cp = (cp << 6) | (d & 0x3F);
    }
    static const std::uint32_t kMin[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < kMin[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    i += len;
  }
  return true;
}

std::string line_of(const YAML::Node& n) {
  return std::to_string(n.Mark().line + 1);
}

void check_node(const YAML::Node& n, const std::string& path) {
  if (n.IsScalar()) {
    if (!valid_utf8(n.Scalar())) scene_error(path, "not valid UTF-8 (line " + line_of(n) + ")");
  } else if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i)
      check_node(n[i], path + "[" + std::to_string(i) + "]");
  } else if (n.IsMap()) {
    std::map<std::string, YAML::Node> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node key = it->first;
      if (!key.IsScalar())
        scene_error(path, "a key must be a plain name, got " + kind_of(key) + " (line " +
                              line_of(key) + ")");
      const std::string k = key.Scalar();
      const std::string kp = path.empty() ? k : path + "." + k;
      if (!valid_utf8(k)) scene_error(path, "a key is not valid UTF-8 (line " + line_of(key) + ")");
      auto [at, fresh] = seen.emplace(k, key);
      if (!fresh)
        scene_error(kp, "given twice (lines " + line_of(at->second) + " and " + line_of(key) + ")");
      check_node(it->second, kp);
    }
  }
}

// A list index of --set: digits only.
std::size_t list_index(const std::string& key, const std::string& part, const std::string& list,
                       std::size_t size) {
  const std::string what = "(" + list + " is a list of " + std::to_string(size) + ")";
  if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos)
    throw InputError("--set " + key + ": '" + part + "' is not a list index " + what);
  const std::size_t idx = std::stoul(part);
  if (idx >= size) throw InputError("--set " + key + ": index " + part + " out of range " + what);
  return idx;
}

}  // namespace

void check_yaml_tree(const YAML::Node& root, const std::string& origin) {
  check_node(root, "");
}

// `--set a.b.0.c=value`: the value (YAML) replaces or adds the key; list items by index.
void apply_override(YAML::Node& root, const std::string& item) {
  auto eq = item.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + item + ": expected key=value, e.g. --set end_time=0.1");
  std::string key = item.substr(0, eq), value = item.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  if (key.back() == '.') parts.push_back("");
  for (const auto& part : parts)
    if (part.empty()) throw InputError("--set " + key + ": empty key name (a.b.c=value)");
  YAML::Node value_node;
  try {
    value_node = load_checked(value, "--set " + item + ": invalid value");
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + item + ": invalid value: " + e.msg);
  }
  // Walk with explicit node copies (yaml-cpp nodes are handles).
  std::vector<YAML::Node> chain{root};
  std::string walked;  // the path so far
  for (std::size_t i = 0; i < parts.size(); ++i) {
    YAML::Node cur = chain.back();
    const std::string& k = parts[i];
    const bool last = i + 1 == parts.size();
    if (cur.IsScalar())
      throw InputError("--set " + key + ": " + walked + " is a value, not a map of keys");
    if (cur.IsSequence()) {
      const std::size_t idx = list_index(key, k, walked, cur.size());
      if (last) cur[idx] = value_node;
      chain.push_back(cur[idx]);
    } else if (last) {
      cur[k] = value_node;
    } else {
      if (!cur[k].IsDefined() || cur[k].IsNull()) cur[k] = YAML::Node(YAML::NodeType::Map);
      chain.push_back(cur[k]);
    }
    walked += (walked.empty() ? "" : ".") + k;
  }
}

}  // namespace monosph
