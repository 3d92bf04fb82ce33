#include "plexus/scenario/overrides.hpp"

#include <cctype>
#include <functional>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"

namespace plexus::scenario {
namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

bool is_index(const std::string& s) {
  if (s.empty() || s.size() > 6) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

/// The first `n` parts, dotted.
std::string join_parts(const std::vector<std::string>& parts, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) out += (i ? "." : "") + parts[i];
  return out;
}

/// {parts[from]: {parts[from+1]: ... value}}
YAML::Node nested(const std::vector<std::string>& parts, std::size_t from, const YAML::Node& value) {
  if (from == parts.size()) return value;
  YAML::Node map(YAML::NodeType::Map);
  map[parts[from]] = nested(parts, from + 1, value);
  return map;
}

}  // namespace

Override parse_override(const std::string& argument) {
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("--set " + argument + ": expected dotted.key=value");
  Override o{argument.substr(0, eq), argument.substr(eq + 1)};
  for (const auto& part : split_path(o.path))
    if (part.empty()) throw InputError(o.text() + ": empty key in the dotted path");
  return o;
}

void apply_overrides(YAML::Node root, const std::vector<Override>& overrides) {
  for (const auto& o : overrides) {
    const auto parts = split_path(o.path);
    // yaml-cpp: assigning to a bound Node rebinds shared data, so every handle below is
    // fresh, and the tree is only changed by `map[key] = value` or `list[i] = value`.
    std::function<void(YAML::Node, std::size_t)> set = [&](YAML::Node here, std::size_t i) {
      const std::string walked = join_parts(parts, i + 1);
      const bool last = i + 1 == parts.size();
      if (here.IsSequence() && is_index(parts[i])) {
        const std::size_t idx = std::stoul(parts[i]);
        if (idx >= here.size()) throw InputError(o.text() + ": " + walked + ": no such list element");
        if (last) {
          here[idx] = load_yaml_string(o.value, o.text());
        } else {
          set(here[idx], i + 1);
        }
      } else if (here.IsMap()) {
        if (last) {
          here[parts[i]] = load_yaml_string(o.value, o.text());
        } else if (here[parts[i]]) {
          set(here[parts[i]], i + 1);
        } else {  // a missing optional section: validation rejects it if the schema has no such key
          here[parts[i]] = nested(parts, i + 1, load_yaml_string(o.value, o.text()));
        }
      } else {
        const std::string parent = i == 0 ? std::string("the document") : join_parts(parts, i);
        throw InputError(o.text() + ": " + parent + ": not a mapping or a list (or no such list element)");
      }
    };
    set(root, 0);
  }
}

std::string attribute_to_override(const std::string& message, const std::string& file,
                                  const std::vector<Override>& overrides) {
  // Validation errors read "file:line: key.path: message".
  if (message.rfind(file + ":", 0) != 0) return message;
  const std::size_t after_line = message.find(": ", file.size() + 1);
  if (after_line == std::string::npos) return message;
  const std::string line = message.substr(file.size() + 1, after_line - file.size() - 1);
  const std::string rest = message.substr(after_line + 2);
  const std::string key = rest.substr(0, rest.find(": "));
  const auto starts_with = [](const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; };
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    const std::string& p = it->path;
    // The error is about the value the override set, something inside it, or (for a node
    // the override created, which has no line) a section on the override's path.
    if (key == p || starts_with(key, p + ".") || (line == "?" && starts_with(p, key + ".")))
      return file + ": " + it->text() + ": " + rest;
  }
  return message;
}

}  // namespace plexus::scenario
