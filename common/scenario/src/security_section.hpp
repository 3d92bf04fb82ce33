// The scenario's `security:` section (docs/security.md), read and validated.
#pragma once

#include <string>

#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::scenario {

/// Reads `security` of `top`: `enabled` (required), `pki` (required when enabled),
/// `governance` and `identities` (optional). Relative paths: `pki` and identity folders from
/// `base_dir`, `governance` from the PKI folder. Only the keys: files are checked by
/// `plexus launch`, which uses them.
ScenarioSecurity load_security_section(const YamlMap& top, const std::string& base_dir);

}  // namespace plexus::scenario
