#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

int SignalTrace::field_index(const std::string& field) const {
  for (std::size_t i = 0; i < spec.fields.size(); ++i)
    if (spec.fields[i] == field) return static_cast<int>(i);
  return -1;
}

const SignalTrace* RunLog::find(const std::string& name) const {
  for (const auto& s : signals)
    if (s.spec.name == name) return &s;
  return nullptr;
}

}  // namespace plexus::scenario
