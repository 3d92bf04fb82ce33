// `plexus service list` (cmd_service.cpp): every plexus process on a domain, from discovery
// (each participant's name and its endpoints) and its heartbeats (health/<service>). Pure:
// the command feeds it what DDS reported; tested on its own (tests/service_census_test.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "plexus/msg/messages.hpp"
#include "plexus/runtime/discovery.hpp"

namespace plexus::cli {

class ServiceCensus {
 public:
  /// A heartbeat of a service, taken at `receive_ns` (monotonic) from the writer of `topic`.
  void heartbeat(const std::string& topic, const msg::Heartbeat& hb, int64_t receive_ns);
  /// One row per participant of `endpoints` (remote ones; this tool's own are left out):
  /// executable and name (its participant name, "plant_simulator r1"), host, state, uptime,
  /// loop rate (between its first and last heartbeat seen), compute p99, heartbeat age at
  /// `now_ns`, and its topics out and in with their types (health/ and lockstep/ left out). Sorted by name.
  nlohmann::ordered_json rows(const std::vector<rt::DiscoveredEndpoint>& endpoints, int64_t now_ns) const;

 private:
  struct Seen {
    msg::Heartbeat first, last;
    int64_t last_receive_ns = 0;
    int beats = 0;
  };
  std::map<std::string, Seen> by_topic_;
};

}  // namespace plexus::cli
