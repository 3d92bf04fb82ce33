// Validated reading of YAML configuration (scenarios, QoS profiles, parameters).
//
// Every error is an InputError with one line that names the file, the line and the
// dotted key: "deploy/qos.yaml:12: profiles.sensor.history.depth: expected an integer, got 'x'".
// A YamlMap remembers which keys were read; reject_unknown() turns every other key into
// an error, so a misspelt key is never silently ignored.
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "plexus/base/input_error.hpp"

namespace plexus {

/// Loads a YAML file; a missing file or a syntax error throws InputError naming the file.
YAML::Node load_yaml_file(const std::string& path);

/// Parses YAML text; `origin` names it in errors.
YAML::Node load_yaml_string(const std::string& text, const std::string& origin);

/// The scalar under `key` of `node`, or "" when it is absent or not a scalar (for reports,
/// which show what a run folder holds and never fail on it).
inline std::string scalar_or_empty(const YAML::Node& node, const char* key) {
  return node[key] && node[key].IsScalar() ? node[key].Scalar() : std::string();
}

class YamlMap {
 public:
  /// `node` must be a mapping; `file` and `path` (dotted key prefix, may be empty) name it in errors.
  YamlMap(YAML::Node node, std::string file, std::string path = {});

  bool has(const std::string& key) const;

  /// Value of a required key, converted to T (bool, integers, double, std::string).
  template <class T>
  T required(const std::string& key) const {
    return convert<T>(child(key, true), key);
  }

  /// Value of an optional key, or `fallback` when the key is absent. The fallback is the
  /// documented default of that key, never a substitute for a value that failed to parse.
  template <class T>
  T optional(const std::string& key, T fallback) const {
    YAML::Node n = child(key, false);
    return n ? convert<T>(n, key) : fallback;
  }

  /// A nested mapping (required).
  YamlMap map(const std::string& key) const;
  /// A nested sequence (required); each element is returned with its position in errors.
  std::vector<YAML::Node> sequence(const std::string& key) const;
  /// The raw node of a key (marks it read). Null node if absent.
  YAML::Node node(const std::string& key) const;
  /// Keys in document order.
  std::vector<std::string> keys() const;

  /// Throws for the first key that was never read.
  void reject_unknown() const;

  /// Throws InputError "file:line: path.key: message" for a value that is out of range.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  /// "file:line" of this map.
  std::string where() const;
  const std::string& file() const { return file_; }
  /// Dotted path of a key below this map.
  std::string key_path(const std::string& key) const;
  /// "file:line" of any node of this file.
  std::string where(const YAML::Node& n) const;

 private:
  YAML::Node child(const std::string& key, bool required) const;
  /// A key's text; InputError for a key that is a mapping, a list or empty.
  std::string key_text(const YAML::Node& key) const;
  template <class T>
  T convert(const YAML::Node& n, const std::string& key) const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  mutable std::set<std::string> read_;
};

}  // namespace plexus
