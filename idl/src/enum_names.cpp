// Enumerator names in a sample's JSON (type_support.hpp, with_enum_names).
#include <nlohmann/json.hpp>

#include "plexus/msg/type_support.hpp"

namespace plexus::msg {

nlohmann::ordered_json with_enum_names(const TypeSupport& ts, nlohmann::ordered_json j) {
  for (std::size_t e = 0; e < ts.enum_member_count; ++e) {
    const EnumMember& m = ts.enum_members[e];
    const nlohmann::ordered_json::json_pointer at(m.json_pointer);
    if (!j.contains(at) || !j.at(at).is_number_integer()) continue;
    const auto v = j.at(at).get<long long>();
    if (v >= 0 && static_cast<unsigned long long>(v) < m.count) j.at(at) = m.names[v];
  }
  return j;
}

}  // namespace plexus::msg
