// Small validated reads that component and metric parameters share.
#pragma once

#include <string>
#include <vector>

#include "plexus/base/yaml_reader.hpp"

namespace plexus::scenario {

/// Optional number >= 0 (standard deviations, quanta); `fallback` when absent.
double optional_non_negative(const YamlMap& params, const std::string& key, double fallback = 0.0);

/// Required non-empty list of names (at most `max_size`).
std::vector<std::string> required_names(const YamlMap& params, const std::string& key, std::size_t max_size);

}  // namespace plexus::scenario
