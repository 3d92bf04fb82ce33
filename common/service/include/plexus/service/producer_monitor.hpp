// A service's watch over its own topics (issue 31): two processes writing one topic, two plant
// simulators of r1 on a domain say, interleave their samples, and nothing else would say so.
// A thread of the service, beside its loop, asks discovery once a second whether a topic the
// service writes or reads has writers in another process too, and warns once per topic
// (rt::ProducerWatch), naming the processes. It never touches the loop's thread.
#pragma once

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "plexus/runtime/participant.hpp"
#include "plexus/scenario/scenario.hpp"

namespace plexus::service {

class ProducerMonitor {
 public:
  /// Watches the typed topics of every signal of `sc` (what its components write and read)
  /// on `participant`, named `self` among the producers.
  ProducerMonitor(const rt::Participant& participant, const scenario::Scenario& sc, std::string self);
  ~ProducerMonitor();
  ProducerMonitor(const ProducerMonitor&) = delete;
  ProducerMonitor& operator=(const ProducerMonitor&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace plexus::service
