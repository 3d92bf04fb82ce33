#include "services/common/arm_fields.hpp"

namespace plexus::scenario {

std::vector<std::string> names(const std::string& prefix, int n) {
  std::vector<std::string> out;
  for (int i = 1; i <= n; ++i) out.push_back(prefix + std::to_string(i));
  return out;
}

std::vector<std::string> concat(std::initializer_list<std::vector<std::string>> parts) {
  std::vector<std::string> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

std::vector<std::string> estimate_fields(int n) {
  return concat({names("q", n), names("dq", n), names("ddq", n), names("dddq", n), names("tau", n), names("dtau", n),
                 names("phi", n), names("dphi", n)});
}

}  // namespace plexus::scenario
