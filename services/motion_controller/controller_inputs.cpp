#include "services/motion_controller/controller_inputs.hpp"

namespace plexus::scenario {

algorithms::ReferenceSample reference_sample(const InputPort& in) {
  algorithms::ReferenceSample r;
  r.p = {in[0], in[1]};
  r.dp = {in[2], in[3]};
  r.ddp = {in[4], in[5]};
  return r;
}

bool is_second(const YamlMap& p, const std::string& key, const std::string& first, const std::string& second) {
  const auto s = p.required<std::string>(key);
  if (s != first && s != second) p.fail(key, "expected " + first + " or " + second + ", got '" + s + "'");
  return s == second;
}

}  // namespace plexus::scenario
