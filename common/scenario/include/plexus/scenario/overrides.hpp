// `--set dotted.key=value`: edits of the scenario tree applied before validation.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace plexus::scenario {

/// One `--set path=value`. `value` is parsed as YAML (a scalar, `[1, 2]` or `{a: 1}`).
struct Override {
  std::string path;  ///< dotted key path; list elements by index (`metrics.0.from`)
  std::string value;
  std::string text() const { return "--set " + path + "=" + value; }
};

/// Parses "a.b.c=value"; throws InputError for a malformed argument.
Override parse_override(const std::string& argument);

/// Applies the overrides to `root` in order. A missing last key is created (validation
/// then rejects it if the schema does not know it); a missing intermediate mapping, an
/// index out of range or a path through a scalar throws InputError naming the argument.
void apply_overrides(YAML::Node root, const std::vector<Override>& overrides);

/// Rewrites a validation error about a key that an override set, so that it names the
/// override instead of a line of the file. Returns `message` unchanged otherwise.
std::string attribute_to_override(const std::string& message, const std::string& file,
                                  const std::vector<Override>& overrides);

}  // namespace plexus::scenario
