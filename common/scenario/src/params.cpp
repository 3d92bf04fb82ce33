#include "plexus/scenario/params.hpp"

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

}  // namespace plexus::scenario
