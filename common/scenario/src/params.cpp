#include "plexus/scenario/params.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>

#include "plexus/base/input_error.hpp"

namespace plexus::scenario {

double optional_non_negative(const YamlMap& params, const std::string& key, double fallback) {
  const double v = params.optional<double>(key, fallback);
  if (v < 0.0) params.fail(key, "must be >= 0");
  return v;
}

std::vector<std::string> required_names(const YamlMap& params, const std::string& key, std::size_t max_size) {
  std::vector<std::string> out;
  for (const auto& n : params.sequence(key)) {
    if (!n.IsScalar()) params.fail(key, "expected a list of names");
    out.push_back(n.Scalar());
  }
  if (out.empty() || out.size() > max_size) params.fail(key, "needs 1 to " + std::to_string(max_size) + " names");
  return out;
}

double number(const YamlMap& p, const YAML::Node& n, const std::string& key) {
  try {
    // yaml-cpp reads .nan and .inf as numbers; a parameter is finite, as YamlMap reads it.
    if (n.IsScalar())
      if (const double v = n.as<double>(); std::isfinite(v)) return v;
  } catch (const YAML::Exception&) {}
  throw InputError(p.where(n) + ": " + p.key_path(key) + ": expected a finite number, got '" +
                   (n.IsScalar() ? n.Scalar() : "a collection") + "'");
}

std::vector<double> numbers(const YamlMap& p, const YAML::Node& n, const std::string& key, std::size_t size) {
  if (!n.IsSequence() || (size > 0 && n.size() != size)) {
    throw InputError(p.where(n) + ": " + p.key_path(key) + ": expected a list of " +
                     (size > 0 ? std::to_string(size) + " " : "") + "numbers");
  }
  std::vector<double> out;
  for (const auto& e : n) out.push_back(number(p, e, key));
  return out;
}

double degrees(const YamlMap& p, const std::string& key, double fallback_rad, const std::string& min) {
  constexpr double kRad = std::numbers::pi / 180.0;
  if (!p.has(key)) return fallback_rad;
  const double v = p.required<double>(key);
  const bool ok = std::isfinite(v) && (min == "> 0" ? v > 0.0 : min == ">= 0" ? v >= 0.0 : true);
  if (!ok)
    p.fail(key, "must be finite" + (min.empty() ? std::string() : " and " + min) + " (got " + std::to_string(v) + ")");
  return v * kRad;
}

std::string choice(const YamlMap& p, const std::string& key, const std::string& fallback,
                   std::initializer_list<const char*> allowed) {
  const auto s = p.optional<std::string>(key, fallback);
  std::string list;
  for (const char* a : allowed) {
    if (s == a) return s;
    list += list.empty() ? a : std::string(", ") + a;
  }
  p.fail(key, "expected one of " + list + ", got '" + s + "'");
}

std::string scenario_relative_path(const ComponentConfig& c, const std::string& key) {
  const YamlMap& p = c.params();
  const std::filesystem::path v = p.required<std::string>(key);
  if (v.empty()) p.fail(key, "must name a file");
  if (v.is_absolute()) return v.string();
  return (std::filesystem::path(c.base_dir) / v).lexically_normal().string();
}

}  // namespace plexus::scenario
