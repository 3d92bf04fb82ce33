// Two processes writing one topic (two plant simulators of one robot on a domain) interleave
// their samples, and every reader sees the mix: a rate twice the expected one, a trajectory
// that jumps. Discovery shows it; ProducerWatch says it, once per topic, naming the processes.
// `plexus topic hz/info` watch the topic they read; a service watches every topic it writes
// or reads (plexus/distributed/producer_monitor.hpp).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "plexus/runtime/participant.hpp"

namespace plexus::rt {

/// The processes (participant names) that write `topic`; this participant's own writers count
/// as `self` (empty: they are left out, for a tool that writes nothing).
std::set<std::string> topic_producers(const std::vector<DiscoveredEndpoint>& endpoints, const std::string& topic,
                                      const std::string& self);

class ProducerWatch {
 public:
  /// Watches `topics`; `self` names this process among the producers (see topic_producers).
  explicit ProducerWatch(std::vector<std::string> topics, std::string self = {});

  /// Warns (spdlog, warn level) for each watched topic that discovery now shows written by
  /// more than one process, once per topic: "r1/position has writers in 2 processes
  /// (plant_simulator r1, plant_simulator r1 [pid 4242]): their samples interleave". Returns
  /// the topics warned about by this call. Call it as discovery goes on (once a second).
  std::vector<std::string> check(const Participant& p);

 private:
  std::vector<std::string> topics_;
  std::string self_;
  std::set<std::string> warned_;
};

}  // namespace plexus::rt
