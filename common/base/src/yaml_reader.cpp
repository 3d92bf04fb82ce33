#include "plexus/base/yaml_reader.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

namespace plexus {
namespace {

std::string line_of(const YAML::Node& n) {
  const auto m = n.Mark();
  return m.line >= 0 ? std::to_string(m.line + 1) : "?";
}

std::string scalar_text(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsMap()) return "a mapping";
  if (n.IsSequence()) return "a list";
  return "nothing";
}

/// yaml-cpp keeps the first of two equal keys without a word; plexus refuses them.
void check_unique_keys(const YAML::Node& n, const std::string& origin, const std::string& path) {
  if (n.IsMap()) {
    std::map<std::string, int> first_line;
    for (const auto& kv : n) {
      if (!kv.first.IsScalar()) continue;
      const std::string key = kv.first.Scalar();
      const std::string dotted = path.empty() ? key : path + "." + key;
      const int line = kv.first.Mark().line + 1;
      const auto [it, fresh] = first_line.emplace(key, line);
      if (!fresh)
        throw InputError(origin + ":" + std::to_string(line) + ": " + dotted + ": duplicate key (first at line " +
                         std::to_string(it->second) + ")");
      check_unique_keys(kv.second, origin, dotted);
    }
  } else if (n.IsSequence()) {
    std::size_t i = 0;
    for (const auto& e : n) check_unique_keys(e, origin, path + "." + std::to_string(i++));
  }
}

/// yaml-cpp builds an alias as the very node its anchor names. An alias inside that node
/// (`a: &x [*x]`) makes the tree a cycle, which every walk of it follows until the stack
/// overflows; aliases of aliases (`b: &b [*a, *a, ...]`, `c: [*b, *b, ...]`) make a tree
/// whose walks take exponential time. Both are refused from the parser's events, before the
/// tree is built: an alias of an anchor still open, and aliases that repeat more than
/// kMaxAliasNodes nodes in all (counted as expanded: an anchored list of a thousand scalars
/// aliased twice repeats 2002). Anchors in a hand-written file repeat tens of nodes. Found
/// while writing the scenario loader's fuzz target (tests/fuzz) and confirmed through it.
class AliasCheck final : public YAML::EventHandler {
 public:
  static constexpr uint64_t kMaxAliasNodes = 100'000;

  explicit AliasCheck(const std::string& origin) : origin_(origin) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t anchor) override { leaf(anchor); }
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t anchor, const std::string&) override {
    leaf(anchor);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(anchor);
  }
  void OnMapEnd() override { close(); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const std::string at = origin_ + ":" + std::to_string(mark.line + 1) + ": ";
    if (anchor < open_.size() && open_[anchor])
      throw InputError(at + "an alias inside the node its anchor names (a cycle)");
    const uint64_t n = anchor < size_.size() ? size_[anchor] : 1;
    nodes_ += n;
    added_ += n;
    if (added_ > kMaxAliasNodes)
      throw InputError(at + "aliases repeat more than " + std::to_string(kMaxAliasNodes) + " nodes in all");
  }

 private:
  void grow(YAML::anchor_t anchor) {
    if (anchor >= size_.size()) {
      size_.resize(anchor + 1, 0);
      open_.resize(anchor + 1, false);
    }
  }
  void leaf(YAML::anchor_t anchor) {
    ++nodes_;
    if (anchor != YAML::NullAnchor) {
      grow(anchor);
      size_[anchor] = 1;
    }
  }
  void open(YAML::anchor_t anchor) {
    ++nodes_;
    stack_.emplace_back(anchor, nodes_);
    if (anchor != YAML::NullAnchor) {
      grow(anchor);
      open_[anchor] = true;
    }
  }
  void close() {
    if (stack_.empty()) return;
    const auto [anchor, first] = stack_.back();
    stack_.pop_back();
    if (anchor != YAML::NullAnchor) {
      size_[anchor] = nodes_ - first + 1;  // the node and everything below it, aliases expanded
      open_[anchor] = false;
    }
  }

  const std::string& origin_;
  uint64_t nodes_ = 0, added_ = 0;
  std::vector<std::pair<YAML::anchor_t, uint64_t>> stack_;
  std::vector<uint64_t> size_;  // by anchor
  std::vector<bool> open_;      // by anchor
};

}  // namespace

YAML::Node load_yaml_string(const std::string& text, const std::string& origin) {
  YAML::Node root;
  try {
    {
      std::istringstream in(text);
      YAML::Parser parser(in);
      AliasCheck check(origin);
      parser.HandleNextDocument(check);  // the first document: the one YAML::Load returns
    }
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    std::string line = e.mark.line >= 0 ? std::to_string(e.mark.line + 1) : "?";
    throw InputError(origin + ":" + line + ": YAML syntax error: " + e.msg);
  }
  check_unique_keys(root, origin, "");
  return root;
}

YAML::Node load_yaml_file(const std::string& path) {
  // Scenario and QoS files are hand-written: the largest in deploy/ is under 20 kB. A file
  // beyond 4 MB is not one (a 48 MB file took 44 s and 5.7 GB to parse before its first
  // error), so it is refused before parsing.
  constexpr std::uintmax_t kMaxBytes = 4u << 20;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxBytes)
    throw InputError(path + ": " + std::to_string(size >> 20) +
                     " MB, larger than the 4 MB limit for a plexus YAML file");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  return load_yaml_string(ss.str(), path);
}

YamlMap::YamlMap(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {
  if (!node_ || !node_.IsMap()) {
    const std::string at = node_ ? file_ + ":" + line_of(node_) : file_;
    throw InputError(at + ": " + (path_.empty() ? std::string("document") : path_) + ": expected a mapping, got " +
                     (node_ ? scalar_text(node_) : "nothing"));
  }
}

std::string YamlMap::where() const { return file_ + ":" + line_of(node_); }
std::string YamlMap::where(const YAML::Node& n) const { return file_ + ":" + line_of(n); }

std::string YamlMap::key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

bool YamlMap::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

YAML::Node YamlMap::child(const std::string& key, bool required) const {
  read_.insert(key);
  YAML::Node n = node_[key];
  if (!n && required) throw InputError(where() + ": " + key_path(key) + ": required key is missing");
  if (n && n.IsNull() && required) throw InputError(where(n) + ": " + key_path(key) + ": required key has no value");
  return n;
}

YAML::Node YamlMap::node(const std::string& key) const { return child(key, false); }

YamlMap YamlMap::map(const std::string& key) const {
  YAML::Node n = child(key, true);
  if (!n.IsMap()) throw InputError(where(n) + ": " + key_path(key) + ": expected a mapping, got " + scalar_text(n));
  return YamlMap(n, file_, key_path(key));
}

std::vector<YAML::Node> YamlMap::sequence(const std::string& key) const {
  YAML::Node n = child(key, true);
  if (!n.IsSequence()) throw InputError(where(n) + ": " + key_path(key) + ": expected a list, got " + scalar_text(n));
  return std::vector<YAML::Node>(n.begin(), n.end());
}

std::string YamlMap::key_text(const YAML::Node& key) const {
  // A YAML key can be a mapping or a list (`? [a, b]: 1`); yaml-cpp's as<std::string>() then
  // threw its own exception past every caller (found by fuzzing the QoS file parser).
  if (!key.IsScalar())
    throw InputError(where(key) + ": " + (path_.empty() ? std::string("document") : path_) +
                     ": a key must be a name, got " + scalar_text(key));
  return key.Scalar();
}

std::vector<std::string> YamlMap::keys() const {
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(key_text(kv.first));
  return out;
}

void YamlMap::reject_unknown() const {
  for (const auto& kv : node_) {
    const auto k = key_text(kv.first);
    if (!read_.count(k)) throw InputError(where(kv.first) + ": " + key_path(k) + ": unknown key");
  }
}

void YamlMap::fail(const std::string& key, const std::string& message) const {
  YAML::Node n = node_[key];
  throw InputError((n ? where(n) : where()) + ": " + key_path(key) + ": " + message);
}

template <class T>
T YamlMap::convert(const YAML::Node& n, const std::string& key) const {
  auto bad = [&](const char* expected) {
    return InputError(where(n) + ": " + key_path(key) + ": expected " + expected + ", got " + scalar_text(n));
  };
  if constexpr (std::is_same_v<T, std::string>) {
    if (!n.IsScalar()) throw bad("a string");
    return n.Scalar();
  } else if constexpr (std::is_same_v<T, bool>) {
    bool v{};
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) throw bad("true or false");
    return v;
  } else if constexpr (std::is_integral_v<T>) {
    if (!n.IsScalar()) throw bad("an integer");
    const std::string& s = n.Scalar();
    std::size_t used = 0;
    long long v = 0;
    try {
      v = std::stoll(s, &used, 0);
    } catch (const std::exception&) {
      throw bad("an integer");
    }
    if (used != s.size()) throw bad("an integer");
    if (v < static_cast<long long>(std::numeric_limits<T>::min()) ||
        (v > 0 && static_cast<unsigned long long>(v) > static_cast<unsigned long long>(std::numeric_limits<T>::max())))
      throw InputError(where(n) + ": " + key_path(key) + ": " + s + " is out of range");
    return static_cast<T>(v);
  } else {
    static_assert(std::is_floating_point_v<T>);
    if (!n.IsScalar()) throw bad("a finite number");
    const std::string& s = n.Scalar();
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      throw bad("a finite number");
    }
    if (used != s.size() || !std::isfinite(v)) throw bad("a finite number");
    return static_cast<T>(v);
  }
}

template std::string YamlMap::convert<std::string>(const YAML::Node&, const std::string&) const;
template bool YamlMap::convert<bool>(const YAML::Node&, const std::string&) const;
template int YamlMap::convert<int>(const YAML::Node&, const std::string&) const;
template unsigned YamlMap::convert<unsigned>(const YAML::Node&, const std::string&) const;
template long YamlMap::convert<long>(const YAML::Node&, const std::string&) const;
template unsigned long YamlMap::convert<unsigned long>(const YAML::Node&, const std::string&) const;
template long long YamlMap::convert<long long>(const YAML::Node&, const std::string&) const;
template unsigned long long YamlMap::convert<unsigned long long>(const YAML::Node&, const std::string&) const;
template double YamlMap::convert<double>(const YAML::Node&, const std::string&) const;

}  // namespace plexus
