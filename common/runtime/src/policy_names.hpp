// Internal: names of the standard DDS QoS policies. Ids 1..22 are numbered the same way
// by both vendors (the OMG QosPolicyId_t order); each back end names its extensions.
#pragma once

#include <string>

namespace plexus::rt::detail {

inline std::string standard_policy_name(int id) {
  static const char* const names[] = {"INVALID",
                                      "USER_DATA",
                                      "DURABILITY",
                                      "PRESENTATION",
                                      "DEADLINE",
                                      "LATENCY_BUDGET",
                                      "OWNERSHIP",
                                      "OWNERSHIP_STRENGTH",
                                      "LIVELINESS",
                                      "TIME_BASED_FILTER",
                                      "PARTITION",
                                      "RELIABILITY",
                                      "DESTINATION_ORDER",
                                      "HISTORY",
                                      "RESOURCE_LIMITS",
                                      "ENTITY_FACTORY",
                                      "WRITER_DATA_LIFECYCLE",
                                      "READER_DATA_LIFECYCLE",
                                      "TOPIC_DATA",
                                      "GROUP_DATA",
                                      "TRANSPORT_PRIORITY",
                                      "LIFESPAN",
                                      "DURABILITY_SERVICE"};
  if (id >= 0 && id < static_cast<int>(std::size(names))) return names[id];
  return "POLICY_" + std::to_string(id);
}

}  // namespace plexus::rt::detail
