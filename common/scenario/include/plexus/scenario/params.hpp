// Small validated reads that component and metric parameters share.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/component.hpp"

namespace plexus::scenario {

/// Optional number >= 0 (standard deviations, quanta); `fallback` when absent.
double optional_non_negative(const YamlMap& params, const std::string& key, double fallback = 0.0);

/// Required non-empty list of names (at most `max_size`).
std::vector<std::string> required_names(const YamlMap& params, const std::string& key, std::size_t max_size);

/// A number node `n` of `p` (an element of a list under `key`); an error names its line.
double number(const YamlMap& p, const YAML::Node& n, const std::string& key);

/// A list of exactly `size` numbers (size 0: any length).
std::vector<double> numbers(const YamlMap& p, const YAML::Node& n, const std::string& key, std::size_t size);

/// Optional angle-like key given in degrees (deg, deg/s, deg/s^2), returned in radians;
/// exactly `fallback_rad` when absent. `min` is "> 0", ">= 0" or "" (any finite value).
double degrees(const YamlMap& p, const std::string& key, double fallback_rad, const std::string& min = "");

/// Optional key with one of the `allowed` values; `fallback` when absent.
std::string choice(const YamlMap& p, const std::string& key, const std::string& fallback,
                   std::initializer_list<const char*> allowed);

/// A path parameter: absolute, or relative to the scenario's folder (ComponentConfig::base_dir).
std::string scenario_relative_path(const ComponentConfig& c, const std::string& key);

}  // namespace plexus::scenario
